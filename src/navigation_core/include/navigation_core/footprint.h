#pragma once
// A robot's footprint: a polygon in the robot's base frame, as costmap_2d's `footprint` parameter
// gives it, or a circle from `robot_radius`; padding and the radii the planners use.
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

// The footprint's outline in the world at `pose`, at most `step` m between points (vertices
// included): the points the planners check against a costmap.
std::vector<Point2> outlinePoints(const Footprint& footprint, const Pose2& pose, double step);

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
