#ifndef HECTOR_STYLE_MAPPING_CORE_POSE_2D_H
#define HECTOR_STYLE_MAPPING_CORE_POSE_2D_H

#include <cmath>

#include <Eigen/Core>

namespace hector_style_mapping {

// A planar pose of the robot's base frame in the map frame: metres and radians, theta counter-clockwise from +x.
struct Pose2D {
  double x = 0.0;
  double y = 0.0;
  double theta = 0.0;
};

// The same angle in (-pi, pi].
inline double normalizeAngle(double angle) {
  const double wrapped = std::remainder(angle, 2.0 * M_PI);  // in [-pi, pi]
  return wrapped <= -M_PI ? wrapped + 2.0 * M_PI : wrapped;
}

// The shortest signed rotation that takes angle `from` to angle `to`, in (-pi, pi].
inline double angleDifference(double to, double from) { return normalizeAngle(to - from); }

// Points given in the frame described by `pose`, expressed in the frame `pose` is given in: its cosine and sine
// taken once for a whole scan (the compiler cannot hoist them out of a loop: they may set errno).
class PoseTransform {
 public:
  explicit PoseTransform(const Pose2D& pose)
      : x_(pose.x), y_(pose.y), cos_(std::cos(pose.theta)), sin_(std::sin(pose.theta)) {}
  Eigen::Vector2d operator()(const Eigen::Vector2d& point) const {
    return {x_ + cos_ * point.x() - sin_ * point.y(), y_ + sin_ * point.x() + cos_ * point.y()};
  }

 private:
  double x_, y_, cos_, sin_;
};

// One point given in the frame described by `pose`, expressed in the frame `pose` is given in.
inline Eigen::Vector2d transformPoint(const Pose2D& pose, const Eigen::Vector2d& point) {
  return PoseTransform(pose)(point);
}

// `b` given in the frame of `a`, expressed in the frame `a` is given in (a then b).
inline Pose2D compose(const Pose2D& a, const Pose2D& b) {
  const Eigen::Vector2d p = transformPoint(a, {b.x, b.y});
  return {p.x(), p.y(), normalizeAngle(a.theta + b.theta)};
}

// `b` seen from `a` (both in one frame): the motion from a to b, so that compose(a, between(a, b)) == b.
inline Pose2D between(const Pose2D& a, const Pose2D& b) {
  const double c = std::cos(a.theta);
  const double s = std::sin(a.theta);
  const double dx = b.x - a.x;
  const double dy = b.y - a.y;
  return {c * dx + s * dy, -s * dx + c * dy, normalizeAngle(b.theta - a.theta)};
}

}  // namespace hector_style_mapping

#endif  // HECTOR_STYLE_MAPPING_CORE_POSE_2D_H
