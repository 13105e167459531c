#ifndef HECTOR_STYLE_MAPPING_POSE_2D_H
#define HECTOR_STYLE_MAPPING_POSE_2D_H

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

// A point given in the frame described by `pose`, expressed in the frame `pose` is given in.
inline Eigen::Vector2d transformPoint(const Pose2D& pose, const Eigen::Vector2d& point) {
  const double c = std::cos(pose.theta);
  const double s = std::sin(pose.theta);
  return {pose.x + c * point.x() - s * point.y(), pose.y + s * point.x() + c * point.y()};
}

}  // namespace hector_style_mapping

#endif  // HECTOR_STYLE_MAPPING_POSE_2D_H
