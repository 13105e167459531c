#pragma once
// The parameters of the wheeled-drive plugins (libgazebo_ros_diff_drive.so and
// libgazebo_ros_skid_steer_drive.so, see wheel_drive_plugin.h), read from their <plugin> element,
// and the namespaces and frames they resolve to. Lengths in m, angles in rad, times in s.
#include <string>

#include "bullet_sim_core/model_description.h"

namespace bullet_sim {

// gazebo_plugins' (Noetic) parameter names and defaults.
enum class OdometrySource { Encoder, World };

// <plugin filename="libgazebo_ros_diff_drive.so">.
struct DiffDriveConfig {
  std::string plugin_name;  // name='...'
  std::string where;        // "<source>: <gazebo>/<plugin ...>", for messages
  bool robot_namespace_given = false;
  std::string robot_namespace;  // <robotNamespace>; see diffDriveNamespace()
  std::string left_joint = "left_joint";    // <leftJoint>
  std::string right_joint = "right_joint";  // <rightJoint>
  double wheel_separation = 0.34;    // <wheelSeparation>, m between the wheels' contact points
  double wheel_diameter = 0.15;      // <wheelDiameter>, m
  double wheel_torque = 5.0;         // <wheelTorque> (or the older <torque>), N m per wheel
  double wheel_acceleration = 0.0;   // <wheelAcceleration>, m/s^2 at the rim; 0: unlimited
  std::string command_topic = "cmd_vel";           // <commandTopic>
  std::string odometry_topic = "odom";             // <odometryTopic>
  std::string odometry_frame = "odom";             // <odometryFrame>
  std::string robot_base_frame = "base_footprint"; // <robotBaseFrame>
  OdometrySource odometry_source = OdometrySource::World;  // <odometrySource> world|encoder
  bool publish_tf = true;                  // <publishTf>: false publishes no odometry at all (topic nor TF)
  bool publish_odom_tf = true;             // <publishOdomTF>: odometryFrame -> robotBaseFrame on /tf
  bool publish_wheel_tf = false;           // <publishWheelTF>: joint parent link -> wheel link on /tf
  bool publish_wheel_joint_state = false;  // <publishWheelJointState>: sensor_msgs/JointState on joint_states
  bool legacy_mode = false;  // <legacyMode>, kept for the record: Noetic's plugin ignores it, and so do we
  double update_rate = 100.0;  // <updateRate>, Hz; 0: every physics step
  double cmd_timeout = 0.5;    // <cmdTimeout> (ours), s of sim time; 0: never (upstream's behaviour)
};

// <plugin filename="libgazebo_ros_skid_steer_drive.so">.
struct SkidSteerDriveConfig {
  std::string plugin_name;
  std::string where;
  bool robot_namespace_given = false;
  std::string robot_namespace;  // see skidSteerNamespace()
  std::string left_front_joint = "left_front_joint";
  std::string right_front_joint = "right_front_joint";
  std::string left_rear_joint = "left_rear_joint";
  std::string right_rear_joint = "right_rear_joint";
  double wheel_separation = 0.4;
  double wheel_diameter = 0.15;
  double torque = 5.0;  // <torque>, N m per wheel
  std::string command_topic = "cmd_vel";
  std::string odometry_topic = "odom";
  std::string odometry_frame = "odom";
  std::string robot_base_frame = "base_footprint";
  bool broadcast_tf = false;  // <broadcastTF>
  double update_rate = 100.0;
  double covariance_x = 0.0001;    // <covariance_x>: pose and twist covariance of x
  double covariance_y = 0.0001;    // <covariance_y>
  double covariance_yaw = 0.01;    // <covariance_yaw>
  double cmd_timeout = 0.5;        // <cmdTimeout> (ours), as for the diff drive
};

// A libgazebo_ros_diff_drive.so / libgazebo_ros_skid_steer_drive.so <plugin> of `model`. Throws
// DescriptionError naming the source, the element path and what was expected: a value that is not
// a number (or out of range), not a boolean, an unknown odometrySource, a wheel that is not a
// revolute or continuous joint of the model.
DiffDriveConfig parseDiffDrive(const PluginDescription& plugin, const ModelDescription& model);
SkidSteerDriveConfig parseSkidSteerDrive(const PluginDescription& plugin, const ModelDescription& model);

// The ROS namespace the plugins live in. Diff drive (gazebo_plugins' GazeboRos helper): a
// non-empty <robotNamespace>; an empty one means the model name; without one, the spawn request's
// namespace (gazebo_ros inserts it into every plugin that has none) or else the model name.
std::string diffDriveNamespace(const DiffDriveConfig& config, const std::string& spawn_namespace,
                               const std::string& model_name);
// Skid steer: its <robotNamespace> even if empty, else the spawn request's namespace (else global).
std::string skidSteerNamespace(const SkidSteerDriveConfig& config, const std::string& spawn_namespace);

// tf::resolve as the plugins use it, for tf2 (no leading slash): "/odom" -> "odom";
// ("robot1", "odom") -> "robot1/odom"; ("", "odom") -> "odom".
std::string resolveFrame(const std::string& tf_prefix, const std::string& frame);

}  // namespace bullet_sim
