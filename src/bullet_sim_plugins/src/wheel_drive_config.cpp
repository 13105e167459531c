#include "bullet_sim_plugins/wheel_drive_config.h"

#include <algorithm>
#include <cmath>

#include "bullet_sim_core/description_error.h"

namespace bullet_sim {

namespace {

const char* jointTypeName(JointType t) {
  switch (t) {
    case JointType::Fixed: return "fixed";
    case JointType::Revolute: return "revolute";
    case JointType::Continuous: return "continuous";
    case JointType::Prismatic: return "prismatic";
  }
  return "unknown";
}

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

// A wheel: the name of a revolute or continuous joint of the model (`fallback` when missing, as upstream).
std::string wheelJoint(const SdfElement& plugin, const char* tag, const std::string& fallback,
                       const ModelDescription& model) {
  const SdfElement e = plugin.child(tag);
  const std::string name = e ? e.text() : fallback;
  const JointDescription* found = nullptr;
  for (const JointDescription& j : model.joints)
    if (j.name == name) found = &j;
  if (found && (found->type == JointType::Revolute || found->type == JointType::Continuous)) return name;
  std::string got = "'" + name + "'";
  if (!e)
    got += std::string(" (the default, as <") + tag + "> is missing)";
  else if (found)
    got += std::string(" (a ") + jointTypeName(found->type) + " joint)";
  e.fail("expected a revolute or continuous joint of model '" + model.name + "', got " + got);
}

OdometrySource odometrySource(const SdfElement& plugin, OdometrySource fallback) {
  const SdfElement e = plugin.child("odometrySource");
  if (!e) return fallback;
  const std::string l = lower(e.text());
  // Upstream's enum is ENCODER = 0, WORLD = 1; numbers are taken by those values.
  if (l == "encoder" || l == "0") return OdometrySource::Encoder;
  if (l == "world" || l == "1") return OdometrySource::World;
  e.fail("expected world or encoder, got '" + e.text() + "'");
}

const NumberCheck kLength{[](double v) { return v > 0; }, "> 0 (m)"};
const NumberCheck kTorque{[](double v) { return v >= 0; }, ">= 0 (N m)"};
const NumberCheck kRate{[](double v) { return v >= 0; }, ">= 0 (Hz; 0 for every step)"};
const NumberCheck kTimeout{[](double v) { return v >= 0; }, ">= 0 (s; 0 for never)"};

std::string where(const PluginDescription& plugin) { return plugin.element.source() + ": " + plugin.element.path(); }

}  // namespace

DiffDriveConfig parseDiffDrive(const PluginDescription& plugin, const ModelDescription& model) {
  const SdfElement& p = plugin.element;
  DiffDriveConfig c;
  c.plugin_name = plugin.name;
  c.where = where(plugin);
  c.robot_namespace_given = static_cast<bool>(p.child("robotNamespace"));
  c.robot_namespace = p.string("robotNamespace", "");
  c.left_joint = wheelJoint(p, "leftJoint", c.left_joint, model);
  c.right_joint = wheelJoint(p, "rightJoint", c.right_joint, model);
  c.wheel_separation = p.number("wheelSeparation", c.wheel_separation, kLength);
  c.wheel_diameter = p.number("wheelDiameter", c.wheel_diameter, kLength);
  // <torque> is the name older tutorials use; <wheelTorque> wins when both are given.
  c.wheel_torque = p.number("torque", c.wheel_torque, kTorque);
  c.wheel_torque = p.number("wheelTorque", c.wheel_torque, kTorque);
  c.wheel_acceleration =
      p.number("wheelAcceleration", c.wheel_acceleration, {[](double v) { return v >= 0; }, ">= 0 (m/s^2; 0 for unlimited)"});
  c.command_topic = p.string("commandTopic", c.command_topic);
  c.odometry_topic = p.string("odometryTopic", c.odometry_topic);
  c.odometry_frame = p.string("odometryFrame", c.odometry_frame);
  c.robot_base_frame = p.string("robotBaseFrame", c.robot_base_frame);
  c.odometry_source = odometrySource(p, c.odometry_source);
  c.publish_tf = p.boolean("publishTf", c.publish_tf);
  c.publish_odom_tf = p.boolean("publishOdomTF", c.publish_odom_tf);
  c.publish_wheel_tf = p.boolean("publishWheelTF", c.publish_wheel_tf);
  c.publish_wheel_joint_state = p.boolean("publishWheelJointState", c.publish_wheel_joint_state);
  // Not validated: Noetic's plugin does not read it (removed in gazebo_plugins 2.8.3).
  const std::string legacy = lower(p.string("legacyMode", ""));
  c.legacy_mode = legacy == "true" || legacy == "1";
  c.update_rate = p.number("updateRate", c.update_rate, kRate);
  c.cmd_timeout = p.number("cmdTimeout", c.cmd_timeout, kTimeout);
  return c;
}

SkidSteerDriveConfig parseSkidSteerDrive(const PluginDescription& plugin, const ModelDescription& model) {
  const SdfElement& p = plugin.element;
  SkidSteerDriveConfig c;
  c.plugin_name = plugin.name;
  c.where = where(plugin);
  c.robot_namespace_given = static_cast<bool>(p.child("robotNamespace"));
  c.robot_namespace = p.string("robotNamespace", "");
  c.left_front_joint = wheelJoint(p, "leftFrontJoint", c.left_front_joint, model);
  c.right_front_joint = wheelJoint(p, "rightFrontJoint", c.right_front_joint, model);
  c.left_rear_joint = wheelJoint(p, "leftRearJoint", c.left_rear_joint, model);
  c.right_rear_joint = wheelJoint(p, "rightRearJoint", c.right_rear_joint, model);
  c.wheel_separation = p.number("wheelSeparation", c.wheel_separation, kLength);
  c.wheel_diameter = p.number("wheelDiameter", c.wheel_diameter, kLength);
  c.torque = p.number("torque", c.torque, kTorque);
  c.command_topic = p.string("commandTopic", c.command_topic);
  c.odometry_topic = p.string("odometryTopic", c.odometry_topic);
  c.odometry_frame = p.string("odometryFrame", c.odometry_frame);
  c.robot_base_frame = p.string("robotBaseFrame", c.robot_base_frame);
  c.broadcast_tf = p.boolean("broadcastTF", c.broadcast_tf);
  c.update_rate = p.number("updateRate", c.update_rate, kRate);
  c.covariance_x = p.number("covariance_x", c.covariance_x, nonNegative());
  c.covariance_y = p.number("covariance_y", c.covariance_y, nonNegative());
  c.covariance_yaw = p.number("covariance_yaw", c.covariance_yaw, nonNegative());
  c.cmd_timeout = p.number("cmdTimeout", c.cmd_timeout, kTimeout);
  return c;
}

std::string diffDriveNamespace(const DiffDriveConfig& config, const std::string& spawn_namespace,
                               const std::string& model_name) {
  if (config.robot_namespace_given) return config.robot_namespace.empty() ? model_name : config.robot_namespace;
  return spawn_namespace.empty() ? model_name : spawn_namespace;
}

std::string skidSteerNamespace(const SkidSteerDriveConfig& config, const std::string& spawn_namespace) {
  return config.robot_namespace_given ? config.robot_namespace : spawn_namespace;
}

std::string resolveFrame(const std::string& tf_prefix, const std::string& frame) {
  if (!frame.empty() && frame[0] == '/') return frame.substr(1);
  const auto b = tf_prefix.find_first_not_of('/');
  if (b == std::string::npos) return frame;
  const std::string prefix = tf_prefix.substr(b, tf_prefix.find_last_not_of('/') - b + 1);
  return prefix + "/" + frame;
}

}  // namespace bullet_sim
