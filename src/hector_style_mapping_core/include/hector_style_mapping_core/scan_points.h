#ifndef HECTOR_STYLE_MAPPING_CORE_SCAN_POINTS_H
#define HECTOR_STYLE_MAPPING_CORE_SCAN_POINTS_H

#include <vector>

#include <Eigen/Core>

namespace hector_style_mapping {

// One laser scan as the SLAM core sees it: already range- and height-filtered by the caller and expressed in the
// robot's base frame (2D). Non-finite points are tolerated and ignored everywhere.
struct ScanPoints {
  Eigen::Vector2d origin{0.0, 0.0};      // the laser's position in the base frame; every ray starts here
  std::vector<Eigen::Vector2d> points;   // beam end points in the base frame, metres
  // Beams longer than the caller trusts (gmapping's maxUrange), cut to that length: the map update
  // clears the cells on the way and marks no end; the matchers do not read them.
  std::vector<Eigen::Vector2d> free_rays;
};

}  // namespace hector_style_mapping

#endif  // HECTOR_STYLE_MAPPING_CORE_SCAN_POINTS_H
