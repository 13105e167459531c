// libgazebo_ros_skid_steer_drive.so: four wheels, each side's two driven alike, on the
// wheeled-drive engine (wheel_drive_plugin.h). Odometry is the model's world pose, as upstream.
#include "bullet_sim_plugins/plugin_registry.h"
#include "bullet_sim_plugins/wheel_drive_plugin.h"

namespace bullet_sim {
namespace {

WheelDriveSettings skidSteerSettings(const SkidSteerDriveConfig& c, const std::string& spawn_namespace) {
  WheelDriveSettings s;
  s.plugin_file = "libgazebo_ros_skid_steer_drive.so";
  s.where = c.where;
  s.robot_namespace = skidSteerNamespace(c, spawn_namespace);
  s.left_joints = {c.left_front_joint, c.left_rear_joint};
  s.right_joints = {c.right_front_joint, c.right_rear_joint};
  s.wheel_separation = c.wheel_separation;
  s.wheel_diameter = c.wheel_diameter;
  s.max_torque = c.torque;
  s.wheel_acceleration = 0.0;  // upstream has no ramp
  s.update_rate = c.update_rate;
  s.cmd_timeout = c.cmd_timeout;
  s.command_topic = c.command_topic;
  s.odometry_topic = c.odometry_topic;
  s.odometry_frame = c.odometry_frame;
  s.robot_base_frame = c.robot_base_frame;
  s.odometry_source = OdometrySource::World;
  s.publish_odometry = true;
  s.publish_odom_tf = c.broadcast_tf;
  s.publish_wheel_tf = false;
  s.publish_wheel_joint_state = false;
  // Upstream sets the same diagonal on the pose and on the twist.
  s.pose_covariance = {c.covariance_x, c.covariance_y, 1e12, 1e12, 1e12, c.covariance_yaw};
  s.twist_covariance = s.pose_covariance;
  return s;
}

class SkidSteerDrivePlugin : public WheelDrivePlugin {
 public:
  explicit SkidSteerDrivePlugin(const PluginContext& context)
      : WheelDrivePlugin(context.model,
                         skidSteerSettings(parseSkidSteerDrive(context.plugin, context.model.description()),
                                           context.spawn_namespace)) {}
};

}  // namespace
}  // namespace bullet_sim

BULLET_SIM_REGISTER_PLUGIN("libgazebo_ros_skid_steer_drive.so", bullet_sim::SkidSteerDrivePlugin)
