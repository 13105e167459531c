#include "bullet_sim_plugins/ros_names.h"

namespace bullet_sim {

std::string sensorPluginNamespace(const PluginContext& context, bool given, const std::string& robot_namespace) {
  if (given) return robot_namespace.empty() ? context.model.name() : robot_namespace;
  return context.spawn_namespace;
}

ros::NodeHandle nodeHandleOrFail(const PluginContext& context, const std::string& ns) {
  try {
    return ros::NodeHandle(ns);
  } catch (const ros::InvalidNameException& e) {
    context.plugin.element.fail("expected a valid ROS namespace, got '" + ns + "': " + e.what());
  }
}

ros::NodeHandle pluginNodeHandle(const PluginContext& context, bool given, const std::string& robot_namespace) {
  return nodeHandleOrFail(context, sensorPluginNamespace(context, given, robot_namespace));
}

std::string tfFrame(const std::string& frame) { return !frame.empty() && frame[0] == '/' ? frame.substr(1) : frame; }

}  // namespace bullet_sim
