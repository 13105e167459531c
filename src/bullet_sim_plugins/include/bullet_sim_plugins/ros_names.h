#pragma once
// How plugins turn their <robotNamespace>, topic and frame parameters into ROS names, with a
// DescriptionError naming the plugin (never a crash) for a name ROS refuses.
#include <ros/ros.h>

#include <string>

#include "bullet_sim_core/description_error.h"
#include "bullet_sim_plugins/model_plugin.h"

namespace bullet_sim {

// gazebo_ros's sensor plugins (laser, camera): a non-empty <robotNamespace>; a given but empty one
// means the model's name; without one, the spawn request's namespace.
std::string sensorPluginNamespace(const PluginContext& context, bool given, const std::string& robot_namespace);

// NodeHandle(sensorPluginNamespace(...)).
ros::NodeHandle pluginNodeHandle(const PluginContext& context, bool given, const std::string& robot_namespace);
// NodeHandle(ns), or DescriptionError naming the plugin.
ros::NodeHandle nodeHandleOrFail(const PluginContext& context, const std::string& ns);

template <class Message>
ros::Publisher advertiseOrFail(const PluginContext& context, ros::NodeHandle& node, const std::string& topic,
                               int queue) {
  try {
    return node.advertise<Message>(topic, queue);
  } catch (const ros::InvalidNameException& e) {
    context.plugin.element.fail("expected a valid ROS topic name, got '" + topic + "': " + e.what());
  }
}

// A tf2 frame id: without a leading slash ("/base_link" -> "base_link").
std::string tfFrame(const std::string& frame);

}  // namespace bullet_sim
