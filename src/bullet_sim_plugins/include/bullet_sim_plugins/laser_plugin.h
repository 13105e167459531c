#pragma once
// libgazebo_ros_laser.so (and libgazebo_ros_gpu_laser.so): the sensor's scans as
// sensor_msgs/LaserScan on <topicName>, in <frameName>, at the sensor's <update_rate>, stamped with
// sim time; rays are cast only while something subscribes, as in Gazebo.
#include <string>

#include "bullet_sim_core/model_description.h"

namespace bullet_sim {

// The <plugin>'s parameters, with gazebo_ros_laser's defaults.
struct LaserPluginConfig {
  std::string topic_name = "/world";  // gazebo_ros_laser's default when <topicName> is missing
  std::string frame_name = "/world";  // likewise <frameName>; a leading slash is dropped (tf2)
  // <robotNamespace>: absent -> the spawn request's namespace; present but empty -> the model name.
  std::string robot_namespace;
  bool robot_namespace_given = false;
  double gaussian_noise = 0.0;  // legacy <gaussianNoise>: read but not applied, as by gazebo_ros_laser
};

// Throws DescriptionError naming the element for a bad value (see sdf_element.h).
LaserPluginConfig parseLaserPlugin(const PluginDescription& plugin);

}  // namespace bullet_sim
