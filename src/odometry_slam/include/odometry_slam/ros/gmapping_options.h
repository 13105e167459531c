#ifndef ODOMETRY_SLAM_ROS_GMAPPING_OPTIONS_H
#define ODOMETRY_SLAM_ROS_GMAPPING_OPTIONS_H

#include <optional>
#include <string>
#include <vector>

#include <ros/node_handle.h>

#include "odometry_slam/odometry_slam.h"

namespace odometry_slam {

// slam_gmapping's private parameters, with its names and defaults.
struct GmappingOptions {
  std::string base_frame = "base_link";
  std::string map_frame = "map";
  std::string odom_frame = "odom";
  int throttle_scans = 1;                  // use every n-th scan
  double map_update_interval = 5.0;        // s (ROS time) between map publications
  double transform_publish_period = 0.05;  // s (ROS time) between map -> odom publications; 0: none
  double tf_delay = 0.05;                  // s the map -> odom stamp lies ahead of now (default: the period)
  // Unset: from the first scan, maxRange = range_max - 0.01 and maxUrange = maxRange, as gmapping.
  std::optional<double> max_range;         // ~maxRange: longer beams are dropped
  std::optional<double> max_usable_range;  // ~maxUrange: longer beams are cut to it and only clear space
  OdometrySlamOptions slam;
  // Parameters of gmapping's particle filter that were set: read, and unused here (the node says so once).
  std::vector<std::string> particle_filter_parameters_set;
};

// The private parameters of `private_nh` into `options`. Returns "" or every problem, one per line, each
// naming the parameter, what was expected and what was given.
std::string loadGmappingOptions(const ros::NodeHandle& private_nh, GmappingOptions* options);

// Private parameters that are not slam_gmapping's (typos such as ~linearUpdte), as full names.
std::vector<std::string> unknownGmappingParameters(const ros::NodeHandle& private_nh);

}  // namespace odometry_slam

#endif  // ODOMETRY_SLAM_ROS_GMAPPING_OPTIONS_H
