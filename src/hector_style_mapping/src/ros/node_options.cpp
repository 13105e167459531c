#include "hector_style_mapping/ros/node_options.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>

#include <ros/console.h>

#include "ros_params/reader.h"

namespace hector_style_mapping {
namespace {

// hector_mapping parameters that are accepted and ignored: debugging aids of upstream's.
const char* const kIgnoredParameters[] = {"pub_drawings", "pub_debug_output"};

// Reads every parameter into `o` (or, with o null, only records the names).
void readAll(ros_params::Reader& r, NodeOptions* o) {
  r.read("base_frame", &o->base_frame);
  r.read("map_frame", &o->map_frame);
  r.read("odom_frame", &o->odom_frame);
  r.read("scan_topic", &o->scan_topic);
  r.read("sys_msg_topic", &o->sys_msg_topic);
  r.read("pose_update_topic", &o->pose_update_topic);
  r.read("tf_map_scanmatch_transform_frame_name", &o->tf_map_scanmatch_transform_frame_name);
  r.read("use_tf_scan_transformation", &o->use_tf_scan_transformation);
  r.read("use_tf_pose_start_estimate", &o->use_tf_pose_start_estimate);
  r.read("use_odometry_prediction", &o->use_odometry_prediction);
  r.read("pub_map_odom_transform", &o->pub_map_odom_transform);
  r.read("pub_map_scanmatch_transform", &o->pub_map_scanmatch_transform);
  r.read("pub_odometry", &o->pub_odometry);
  r.read("advertise_map_service", &o->advertise_map_service);
  r.read("output_timing", &o->output_timing);
  r.read("scan_subscriber_queue_size", &o->scan_subscriber_queue_size);
  r.read("map_pub_period", &o->map_pub_period);
  r.read("transform_pub_period", &o->transform_pub_period);
  r.read("laser_min_dist", &o->filter.laser_min_dist);
  r.read("laser_max_dist", &o->filter.laser_max_dist);
  r.read("laser_z_min_value", &o->filter.laser_z_min_value);
  r.read("laser_z_max_value", &o->filter.laser_z_max_value);
  r.read("map_resolution", &o->mapper.map_resolution);
  r.read("map_size", &o->mapper.map_size);
  r.read("map_start_x", &o->mapper.map_start_x);
  r.read("map_start_y", &o->mapper.map_start_y);
  r.read("map_multi_res_levels", &o->mapper.map_multi_res_levels);
  r.read("update_factor_free", &o->mapper.update_factor_free);
  r.read("update_factor_occupied", &o->mapper.update_factor_occupied);
  r.read("map_update_distance_thresh", &o->mapper.map_update_distance_thresh);
  r.read("map_update_angle_thresh", &o->mapper.map_update_angle_thresh);
  r.read("search_window_linear", &o->mapper.search_window_linear);
  r.read("search_window_angular", &o->mapper.search_window_angular);
  r.read("search_motion_weight", &o->mapper.search_motion_weight);
  r.read("loop_closure", &o->mapper.loop_closure);
}

}  // namespace

std::string loadNodeOptions(const ros::NodeHandle& private_nh, NodeOptions* options) {
  ros_params::Reader reader(private_nh);
  readAll(reader, options);
  const std::string mapper_problems = validate(options->mapper);
  if (!mapper_problems.empty()) reader.problem(mapper_problems);
  const ScanFilter& f = options->filter;
  if (!(f.laser_min_dist >= 0.0 && f.laser_min_dist < f.laser_max_dist))
    reader.problem("laser_min_dist / laser_max_dist: expected 0 <= laser_min_dist < laser_max_dist (got " +
                   std::to_string(f.laser_min_dist) + ", " + std::to_string(f.laser_max_dist) + ")");
  if (!(f.laser_z_min_value < f.laser_z_max_value))
    reader.problem("laser_z_min_value / laser_z_max_value: expected min < max (got " +
                   std::to_string(f.laser_z_min_value) + ", " + std::to_string(f.laser_z_max_value) + ")");
  if (options->scan_subscriber_queue_size < 1)
    reader.problem("scan_subscriber_queue_size: expected >= 1 (got " +
                   std::to_string(options->scan_subscriber_queue_size) + ")");
  if (!(options->map_pub_period > 0.0))
    reader.problem("map_pub_period: expected > 0 s (got " + std::to_string(options->map_pub_period) + ")");
  if (!(options->transform_pub_period >= 0.0))
    reader.problem("transform_pub_period: expected >= 0 s, 0 to publish only with each scan (got " +
                   std::to_string(options->transform_pub_period) + ")");
  if (options->base_frame.empty() || options->map_frame.empty() || options->odom_frame.empty())
    reader.problem("base_frame, map_frame, odom_frame: expected frame names, got an empty one");
  if (options->map_frame == options->base_frame)
    reader.problem("map_frame and base_frame are both '" + options->map_frame + "': expected two frames");
  return reader.problems();
}

std::vector<std::string> unknownParameters(const ros::NodeHandle& private_nh) {
  ros_params::Reader reader(private_nh);
  NodeOptions scratch;
  readAll(reader, &scratch);
  return reader.unknown(std::set<std::string>(std::begin(kIgnoredParameters), std::end(kIgnoredParameters)));
}

}  // namespace hector_style_mapping
