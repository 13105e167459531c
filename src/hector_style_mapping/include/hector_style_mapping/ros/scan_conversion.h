#ifndef HECTOR_STYLE_MAPPING_ROS_SCAN_CONVERSION_H
#define HECTOR_STYLE_MAPPING_ROS_SCAN_CONVERSION_H

#include <string>

#include <Eigen/Geometry>
#include <sensor_msgs/LaserScan.h>

#include "hector_style_mapping_core/scan_points.h"

namespace hector_style_mapping {

// hector_mapping's beam filters (its parameter names).
struct ScanFilter {
  double laser_min_dist = 0.4;      // m; shorter ranges are dropped (the robot itself)
  double laser_max_dist = 30.0;     // m; longer ones are dropped
  double laser_z_min_value = -1.0;  // m; end points lower than this relative to the laser's height are dropped
  double laser_z_max_value = 1.0;   // m; ... higher than this
};

// What happened to a scan's beams; the node turns the counts into (throttled) warnings.
struct ScanConversionReport {
  int beams = 0;                  // ranges in the message
  int expected_beams = 0;         // from angle_min, angle_max, angle_increment
  int used = 0;                   // end points handed to the SLAM core
  int nan = 0;                    // NaN: an invalid measurement (REP 117)
  int infinite = 0;               // +inf: no return; -inf: too close (REP 117)
  int out_of_range = 0;           // outside range_min..range_max or laser_min_dist..laser_max_dist
  int outside_height = 0;         // outside laser_z_min_value..laser_z_max_value
  std::string error;              // set when the scan cannot be used at all (then nothing else is)
};

// The end points of `scan` in the base frame, given where the laser is in that frame. Beam i is at
// angle_min + i * angle_increment whatever the number of ranges (a scan with fewer or more ranges than
// its angles say is used as far as it goes; the report says so). Never throws.
ScanConversionReport scanToPoints(const sensor_msgs::LaserScan& scan, const Eigen::Isometry3d& laser_in_base,
                                  const ScanFilter& filter, ScanPoints* out);

}  // namespace hector_style_mapping

#endif  // HECTOR_STYLE_MAPPING_ROS_SCAN_CONVERSION_H
