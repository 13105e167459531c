#pragma once
// A robot's footprint: a polygon in the robot's base frame, as costmap_2d's `footprint` parameter
// gives it, or a circle from `robot_radius`; padding and the radii the planners use.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace navigation_core {

struct Point2 {
  double x = 0.0;
  double y = 0.0;
};
using Footprint = std::vector<Point2>;

struct Pose2 {  // a robot's pose in a costmap's frame
  double x = 0.0, y = 0.0, theta = 0.0;
};

// Walks the footprint's outline in the world at `pose`, points at most `step` m apart (vertices
// included): the points the planners check against a costmap and the obstacle layer frees.
// visit(x, y) returns false to stop the walk, which then returns false. Inline: it runs for every
// pose of every sampled trajectory.
template <typename Visit>
bool forEachOutlinePoint(const Footprint& footprint, const Pose2& pose, double step, Visit&& visit) {
  const double c = std::cos(pose.theta), s = std::sin(pose.theta);
  for (std::size_t i = 0; i < footprint.size(); ++i) {
    const Point2& a = footprint[i];
    const Point2& b = footprint[(i + 1) % footprint.size()];
    const double ax = pose.x + c * a.x - s * a.y, ay = pose.y + s * a.x + c * a.y;
    const double bx = pose.x + c * b.x - s * b.y, by = pose.y + s * b.x + c * b.y;
    // |dx| + |dy| bounds the edge's length.
    const int n = std::max(1, static_cast<int>(std::ceil((std::abs(bx - ax) + std::abs(by - ay)) / step)));
    for (int k = 0; k <= n; ++k) {
      const double t = static_cast<double>(k) / n;
      if (!visit(ax + t * (bx - ax), ay + t * (by - ay))) return false;
    }
  }
  return true;
}

// costmap_2d's circle for `robot_radius`: 16 points on it.
Footprint footprintFromRadius(double radius);

// `footprint_padding`: each vertex moved `padding` further from the base along x and along y
// (a vertex on an axis only along the other), as costmap_2d pads.
Footprint padFootprint(Footprint footprint, double padding);

// The inscribed radius (the largest circle about the base inside the polygon: the nearest edge or
// vertex) and the circumscribed radius (the farthest vertex).
struct FootprintRadii {
  double inscribed = 0.0;
  double circumscribed = 0.0;
};
FootprintRadii footprintRadii(const Footprint& footprint);

// The `footprint` parameter's string form, "[[x1, y1], [x2, y2], ...]", with at least three points.
// Throws std::invalid_argument saying what was expected and where the text went wrong.
Footprint parseFootprint(const std::string& text);

}  // namespace navigation_core
