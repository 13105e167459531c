// libgazebo_ros_diff_drive.so: two wheels, on the wheeled-drive engine (wheel_drive_plugin.h).
#include <ros/console.h>

#include "bullet_sim_plugins/plugin_registry.h"
#include "bullet_sim_plugins/wheel_drive_plugin.h"

namespace bullet_sim {
namespace {

const char* kDiffDriveFile = "libgazebo_ros_diff_drive.so";

WheelDriveSettings diffDriveSettings(const DiffDriveConfig& c, const std::string& spawn_namespace,
                                     const std::string& model_name) {
  WheelDriveSettings s;
  s.plugin_file = kDiffDriveFile;
  s.where = c.where;
  s.robot_namespace = diffDriveNamespace(c, spawn_namespace, model_name);
  s.left_joints = {c.left_joint};
  s.right_joints = {c.right_joint};
  s.wheel_separation = c.wheel_separation;
  s.wheel_diameter = c.wheel_diameter;
  s.max_torque = c.wheel_torque;
  s.wheel_acceleration = c.wheel_acceleration;
  s.update_rate = c.update_rate;
  s.cmd_timeout = c.cmd_timeout;
  s.command_topic = c.command_topic;
  s.odometry_topic = c.odometry_topic;
  s.odometry_frame = c.odometry_frame;
  s.robot_base_frame = c.robot_base_frame;
  s.odometry_source = c.odometry_source;
  s.publish_odometry = c.publish_tf;
  s.publish_odom_tf = c.publish_odom_tf;
  s.publish_wheel_tf = c.publish_wheel_tf;
  s.publish_wheel_joint_state = c.publish_wheel_joint_state;
  // gazebo_ros_diff_drive's fixed covariances: the pose's, none for the twist.
  s.pose_covariance = {0.00001, 0.00001, 1e12, 1e12, 1e12, 0.001};
  s.twist_covariance = {0, 0, 0, 0, 0, 0};
  return s;
}

class DiffDrivePlugin : public WheelDrivePlugin {
 public:
  explicit DiffDrivePlugin(const PluginContext& context) : DiffDrivePlugin(context, parseDiffDrive(context.plugin, context.model.description())) {}

 private:
  DiffDrivePlugin(const PluginContext& context, const DiffDriveConfig& config)
      : WheelDrivePlugin(context.model, diffDriveSettings(config, context.spawn_namespace, context.model.name())) {
    if (config.legacy_mode) {
      ROS_WARN_STREAM("model '" << context.model.name() << "': " << kDiffDriveFile
                                << ": <legacyMode> true is ignored, as by ROS Noetic's plugin (gazebo_plugins 2.8.3 "
                                   "removed it): the left wheel turns at (v - w * wheelSeparation / 2) / radius (REP "
                                   "103). If the robot turns the wrong way, swap <leftJoint> and <rightJoint>.");
    }
  }
};

}  // namespace
}  // namespace bullet_sim

BULLET_SIM_REGISTER_PLUGIN("libgazebo_ros_diff_drive.so", bullet_sim::DiffDrivePlugin)
