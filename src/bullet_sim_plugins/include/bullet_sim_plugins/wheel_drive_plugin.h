#pragma once
// gazebo_plugins' wheeled drives for bullet_sim: libgazebo_ros_diff_drive.so and
// libgazebo_ros_skid_steer_drive.so, with Noetic's parameter names and defaults
// (DiffDriveConfig / SkidSteerDriveConfig in wheel_drive_config.h). This is their shared engine,
// WheelDrivePlugin; diff_drive_plugin.cpp and skid_steer_drive_plugin.cpp register the two names.
//
// What they do, as upstream:
// - Subscribe geometry_msgs/Twist on <commandTopic> (cmd_vel) in the robot namespace
//   (diffDriveNamespace / skidSteerNamespace). linear.x and angular.z are used.
// - Every 1/<updateRate> s of sim time, turn the command into wheel angular velocities
//   (v -/+ w * wheelSeparation / 2) / (wheelDiameter / 2) (minus for the left wheels) and drive the
//   wheel joints with velocity motors in the solver, bounded by the wheel torque (Gazebo's joint
//   "vel" + "fmax"): the wheels can slip, and a robot pushing a wall stops.
//   <wheelAcceleration> (diff drive) limits how fast each wheel's commanded rim speed changes.
// - Publish nav_msgs/Odometry on <odometryTopic> (odom) at the same rate, stamped in sim time:
//   header.frame_id <odometryFrame>, child_frame_id <robotBaseFrame> (both through tf_prefix if that
//   parameter is set, and without a leading slash), the pose, the twist in the base frame and
//   upstream's covariances. <odometrySource> world (the default, and the skid steer's only source)
//   is the model's world pose: the odometry frame is the world frame. encoder integrates the wheel
//   joints' rotations from where the robot started (heading 0).
// - When enabled, odometryFrame -> robotBaseFrame on /tf (diff drive <publishOdomTF>, default true;
//   skid steer <broadcastTF>, default false), the wheels' links relative to their joints' parent
//   links on /tf (<publishWheelTF>), and the wheel joints' positions and velocities as
//   sensor_msgs/JointState on joint_states (<publishWheelJointState>).
// - reset_world / reset_simulation: command and encoder odometry back to zero.
//
// Our additions and differences:
// - <cmdTimeout> (s of sim time, default 0.5; 0 disables, which is upstream's behaviour): when no
//   command arrived for that long, the wheels are commanded to stop (through the acceleration ramp).
//   A command received between two physics steps takes effect, and is timed, from the next step.
// - A Twist with a NaN or infinite field is ignored (a throttled warning says so).
// - <legacyMode> is ignored, as by Noetic's plugin (gazebo_plugins 2.8.3 removed it; Kinetic's
//   legacyMode true swapped the wheels' turning directions). A warning says so when it is true.
// - The diff drive's older <torque> is honoured when <wheelTorque> is absent (Noetic ignores it).
// - The acceleration ramp limits the commanded rim speed itself; upstream steps from the measured
//   speed, winding up when a wheel is blocked.
// - Encoder odometry integrates the wheel joints' angle changes every physics step as circular
//   arcs; its twist is the mean over the last odometry period.
// - A wheel that is not a revolute or continuous joint of the model is a DescriptionError at spawn.
#include <geometry_msgs/Twist.h>
#include <ros/ros.h>

#include <array>
#include <memory>
#include <string>
#include <vector>

#include "bullet_sim_core/physics_model.h"
#include "bullet_sim_plugins/model_plugin.h"
#include "bullet_sim_plugins/wheel_drive_config.h"
#include "bullet_sim_plugins/wheel_kinematics.h"

namespace bullet_sim {

// What a wheeled drive does, whichever plugin block asked for it.
struct WheelDriveSettings {
  std::string plugin_file;      // for messages
  std::string where;            // the plugin block, for messages
  std::string robot_namespace;  // already resolved
  std::vector<std::string> left_joints, right_joints;
  double wheel_separation = 0.34;
  double wheel_diameter = 0.15;
  double max_torque = 5.0;
  double wheel_acceleration = 0.0;
  double update_rate = 100.0;
  double cmd_timeout = 0.5;
  std::string command_topic = "cmd_vel";
  std::string odometry_topic = "odom";
  std::string odometry_frame = "odom";
  std::string robot_base_frame = "base_footprint";
  OdometrySource odometry_source = OdometrySource::World;
  bool publish_odometry = true;  // the topic; false also stops the odometry TF
  bool publish_odom_tf = true;
  bool publish_wheel_tf = false;
  bool publish_wheel_joint_state = false;
  std::array<double, 6> pose_covariance{};   // diagonal: x y z roll pitch yaw
  std::array<double, 6> twist_covariance{};  // diagonal
};

class WheelDrivePlugin : public ModelPlugin {
 public:
  // Throws DescriptionError when a wheel is not a moving joint of `model` (e.g. a static model).
  WheelDrivePlugin(PhysicsModel& model, WheelDriveSettings settings);
  ~WheelDrivePlugin() override;  // releases the wheels' motors
  void beforeStep(const ros::Time& now, double dt) override;
  void afterStep(const ros::Time& now) override;
  void reset() override;

 private:
  struct Wheel {
    int joint;
    std::string name, parent_link, child_link;
  };
  void onCommand(const geometry_msgs::Twist::ConstPtr& msg);
  void readEncoders();
  void publish(const ros::Time& now);
  // Whether an update is due at `now`; advances `next` (catching up without bursts after a pause).
  bool due(const ros::Time& now, ros::Time& next) const;

  PhysicsModel& model_;
  const WheelDriveSettings settings_;
  std::vector<Wheel> left_, right_;
  ros::NodeHandle node_;
  ros::Subscriber command_subscriber_;
  ros::Publisher odometry_publisher_, joint_state_publisher_;
  ros::Publisher tf_publisher_;  // /tf, from the publishing thread as every message here
  std::string odometry_frame_, base_frame_, tf_prefix_;

  DriveCommand command_;
  bool has_pending_ = false;  // a command received since the last step
  double pending_linear_ = 0.0, pending_angular_ = 0.0;
  bool was_timed_out_ = false, told_timeout_ = false;
  ros::WallTime last_bad_command_warning_;

  EncoderOdometry encoder_;
  double published_distance_ = 0.0, published_heading_ = 0.0;
  ros::Time published_time_;
  bool has_published_ = false;

  ros::Duration period_;
  ros::Time next_command_, next_publish_, last_command_;
  bool has_last_command_ = false;
};

}  // namespace bullet_sim
