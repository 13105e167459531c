#include "hector_style_mapping/ros/scan_conversion.h"

#include <cmath>
#include <sstream>

namespace hector_style_mapping {

ScanConversionReport scanToPoints(const sensor_msgs::LaserScan& scan, const Eigen::Isometry3d& laser_in_base,
                                  const ScanFilter& filter, ScanPoints* out) {
  ScanConversionReport report;
  out->points.clear();
  report.beams = static_cast<int>(scan.ranges.size());
  const double increment = scan.angle_increment;
  if (!std::isfinite(scan.angle_min) || !std::isfinite(scan.angle_max) || !std::isfinite(increment) ||
      increment == 0.0) {
    std::ostringstream what;
    what << "angle_min " << scan.angle_min << ", angle_max " << scan.angle_max << ", angle_increment " << increment
         << ": expected finite angles and a non-zero increment";
    report.error = what.str();
    return report;
  }
  report.expected_beams = static_cast<int>(std::lround((scan.angle_max - scan.angle_min) / increment)) + 1;

  const Eigen::Vector3d laser_origin = laser_in_base.translation();
  out->origin = laser_origin.head<2>();
  // A range must be inside both the sensor's own limits and hector's laser_*_dist.
  const double min_range = std::max<double>(scan.range_min, filter.laser_min_dist);
  const double max_range = std::min<double>(scan.range_max, filter.laser_max_dist);
  out->points.reserve(scan.ranges.size());
  for (std::size_t i = 0; i < scan.ranges.size(); ++i) {
    const double range = scan.ranges[i];
    if (std::isnan(range)) {
      ++report.nan;
      continue;
    }
    if (std::isinf(range)) {
      ++report.infinite;
      continue;
    }
    // range_max itself is what many drivers report for "no return": not a hit.
    if (range < min_range || range >= max_range) {
      ++report.out_of_range;
      continue;
    }
    const double angle = scan.angle_min + static_cast<double>(i) * increment;
    const Eigen::Vector3d in_base = laser_in_base * Eigen::Vector3d(range * std::cos(angle), range * std::sin(angle), 0.0);
    const double height = in_base.z() - laser_origin.z();
    if (height < filter.laser_z_min_value || height > filter.laser_z_max_value) {
      ++report.outside_height;
      continue;
    }
    out->points.emplace_back(in_base.x(), in_base.y());
  }
  report.used = static_cast<int>(out->points.size());
  return report;
}

}  // namespace hector_style_mapping
