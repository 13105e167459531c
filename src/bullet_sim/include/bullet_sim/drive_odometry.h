#pragma once
// The ROS-free part of the wheeled-drive plugins (libgazebo_ros_diff_drive.so and
// libgazebo_ros_skid_steer_drive.so, see drive_plugins.h): their <plugin> parameters read from a
// model's <gazebo> blocks, wheel speeds from a body twist, the acceleration ramp and command
// timeout, and odometry integrated from the wheel encoders. Lengths in m, angles in rad, times in s.
#include <optional>
#include <string>

#include "bullet_sim/model_description.h"

namespace bullet_sim {

// ---------------------------------------------------------------------------------------------
// Configuration: gazebo_plugins' (Noetic) parameter names and defaults
// ---------------------------------------------------------------------------------------------

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

// The model's libgazebo_ros_diff_drive.so block (URDF <gazebo><plugin>, or an SDF model's
// <plugin>), or nothing. Throws DescriptionError naming the source, the element path and what was
// expected: a value that is not a number (or out of range), not a boolean, an unknown
// odometrySource, a wheel that is not a revolute/continuous joint of the model, two such blocks.
std::optional<DiffDriveConfig> parseDiffDrive(const ModelDescription& model);
std::optional<SkidSteerDriveConfig> parseSkidSteerDrive(const ModelDescription& model);

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

// ---------------------------------------------------------------------------------------------
// Kinematics, ramp, timeout, odometry
// ---------------------------------------------------------------------------------------------

struct WheelSpeeds {
  double left = 0.0;   // rad/s
  double right = 0.0;  // rad/s
};

// Wheel angular velocities for a forward speed `linear` (m/s) and a turn rate `angular` (rad/s,
// counter-clockwise seen from above, REP 103): (linear -/+ angular * separation / 2) / (diameter / 2),
// minus for the left wheel.
WheelSpeeds wheelSpeeds(double linear, double angular, double wheel_separation, double wheel_diameter);

// `current` moved toward `target` by at most `max_change` (>= 0; infinity jumps to the target).
double rampToward(double current, double target, double max_change);

// What the wheels are told at each update: the last twist command through the acceleration ramp,
// and a stop once the command is older than the timeout.
class DriveCommand {
 public:
  // wheel_acceleration: m/s^2 at the wheel rim (0: unlimited); cmd_timeout: s (0: never).
  DriveCommand(double wheel_separation, double wheel_diameter, double wheel_acceleration = 0.0,
               double cmd_timeout = 0.0);

  // A new command (linear.x, angular.z) that arrived at `time`.
  void setTwist(double linear, double angular, double time);
  // True when there was a command, a timeout is set and the command is older than it at `time`.
  bool timedOut(double time) const;
  // The wheel velocities to command at `time`, `dt` after the previous update: the target
  // wheelSpeeds() of the command (zero without one, or timed out), each wheel's change limited to
  // wheel_acceleration / radius * dt.
  WheelSpeeds update(double time, double dt);
  const WheelSpeeds& current() const { return current_; }
  void reset();  // no command, wheels commanded at rest

 private:
  double wheel_separation_, wheel_diameter_, wheel_acceleration_, cmd_timeout_;
  bool has_command_ = false;
  double linear_ = 0.0, angular_ = 0.0, command_time_ = 0.0;
  WheelSpeeds current_;
};

// Pose on the plane (x, y, heading) of the base from the wheels' rotations, each step taken as a
// circular arc (wheels turning at constant rates in between), so that a run of constant commands
// is integrated exactly whatever the step size. Wheel angles grow as the wheel drives forward.
class EncoderOdometry {
 public:
  EncoderOdometry(double wheel_separation, double wheel_diameter);

  void reset(double x = 0.0, double y = 0.0, double heading = 0.0);  // pose and distance; keeps the reference
  // Adds the motion for wheel rotations `left`, `right` (rad) since the last call.
  void integrate(double left_rotation, double right_rotation);
  // Absolute wheel angles (rad): the first call after construction or resetReference() only takes
  // them as the reference; later calls integrate the change.
  void update(double left_angle, double right_angle);
  void resetReference() { has_reference_ = false; }

  double x() const { return x_; }
  double y() const { return y_; }
  double heading() const { return heading_; }    // rad, not wrapped
  double distance() const { return distance_; }  // signed path length of the base since reset (m)

 private:
  double wheel_separation_, wheel_radius_;
  double x_ = 0.0, y_ = 0.0, heading_ = 0.0, distance_ = 0.0;
  bool has_reference_ = false;
  double left_reference_ = 0.0, right_reference_ = 0.0;
};

}  // namespace bullet_sim
