#ifndef HECTOR_STYLE_MAPPING_ROS_NODE_OPTIONS_H
#define HECTOR_STYLE_MAPPING_ROS_NODE_OPTIONS_H

#include <string>
#include <vector>

#include <ros/node_handle.h>

#include "hector_style_mapping/ros/scan_conversion.h"
#include "hector_style_mapping_core/mapper_options.h"

namespace hector_style_mapping {

// Everything the node is configured with; names and defaults are hector_mapping's private parameters.
struct NodeOptions {
  std::string base_frame = "base_link";
  std::string map_frame = "map";
  std::string odom_frame = "odom";  // equal to base_frame: publish map -> base_frame (no odometry frame)
  std::string scan_topic = "scan";
  std::string sys_msg_topic = "syscommand";
  std::string pose_update_topic = "poseupdate";
  std::string tf_map_scanmatch_transform_frame_name = "scanmatcher_frame";
  bool use_tf_scan_transformation = true;   // laser pose in the base frame from tf (else: at the base origin)
  bool use_tf_pose_start_estimate = false;  // each scan's first guess from tf map_frame -> base_frame
  // Ours, off as in upstream: with an odometry frame (odom_frame != base_frame), each scan's first
  // guess is the last matched pose moved by the odometry's motion since the last scan.
  bool use_odometry_prediction = false;
  bool pub_map_odom_transform = true;
  bool pub_map_scanmatch_transform = true;
  bool pub_odometry = false;                // nav_msgs/Odometry on scanmatch_odom
  bool advertise_map_service = true;        // dynamic_map
  bool output_timing = false;               // log each scan's processing time
  int scan_subscriber_queue_size = 5;
  double map_pub_period = 2.0;              // s (ROS time, sim time in simulation) between map publications
  double transform_pub_period = 0.05;       // s (wall) between re-publications of the map tf
  ScanFilter filter;
  MapperOptions mapper;
};

// The private parameters of `private_nh` into `options` (defaults where unset). Returns "" or every
// problem, one per line, each naming the parameter, what was expected and what was given.
std::string loadNodeOptions(const ros::NodeHandle& private_nh, NodeOptions* options);

// Private parameters that the node does not know (typos such as ~map_resoluton), as full names.
std::vector<std::string> unknownParameters(const ros::NodeHandle& private_nh);

}  // namespace hector_style_mapping

#endif  // HECTOR_STYLE_MAPPING_ROS_NODE_OPTIONS_H
