// diff_drive_controller/DiffDriveController: ros_controllers' differential-drive controller.
// Takes geometry_msgs/Twist on <controller>/cmd_vel (linear.x, angular.z), limits it, and
// commands the wheel joints' angular velocity through the VelocityJointInterface; integrates
// odometry from the wheel positions and publishes nav_msgs/Odometry on <controller>/odom and the
// odom -> base transform on /tf. Parameters and behaviour follow ros_controllers (noetic).
#include <geometry_msgs/TwistStamped.h>
#include <nav_msgs/Odometry.h>
#include <ros/console.h>
#include <ros/node_handle.h>
#include <tf2_msgs/TFMessage.h>
#include <urdf/model.h>
#include <xmlrpcpp/XmlRpcValue.h>

#include <cmath>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "publish_thread/publish_thread.h"
#include "ros_params/reader.h"
#include "sim_control/controller.h"
#include "sim_control/controller_registry.h"
#include "sim_control/diff_drive_kinematics.h"

namespace sim_control {
namespace {

// At most one message a second per site, on wall time: sim time may be paused or run much
// faster than real time.
bool throttle(double& last) {
  const double now = ros::WallTime::now().toSec();
  if (last >= 0.0 && now - last < 1.0) return false;
  last = now;
  return true;
}

std::string str(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

// Optional parameters: absent keeps the default; a wrong type is a problem of `params`, which init
// returns as its error. Each says whether all is well so far.
bool number(ros_params::Reader& params, const std::string& name, double& value, const std::string& expected = "a number") {
  params.read(name, &value, expected);
  return params.ok();
}
bool boolean(ros_params::Reader& params, const std::string& name, bool& value) {
  params.read(name, &value, "a boolean (true or false)");
  return params.ok();
}
bool integer(ros_params::Reader& params, const std::string& name, int& value, const std::string& expected) {
  params.read(name, &value, expected);
  return params.ok();
}
bool nonEmptyString(ros_params::Reader& params, const std::string& name, std::string& value,
                    const std::string& expected) {
  std::string read;
  if (!params.read(name, &read, expected)) return params.ok();
  if (read.empty()) return params.fail(name, "expected " + expected + ", got an empty string");
  value = read;
  return true;
}
bool isNumber(const XmlRpc::XmlRpcValue& v) {
  return v.getType() == XmlRpc::XmlRpcValue::TypeDouble || v.getType() == XmlRpc::XmlRpcValue::TypeInt;
}
double toDouble(XmlRpc::XmlRpcValue& v) {
  return v.getType() == XmlRpc::XmlRpcValue::TypeInt ? static_cast<double>(static_cast<int>(v)) : static_cast<double>(v);
}

// The position of a joint's origin in the URDF's root link frame (movable joints in between at
// zero), so that wheels hung from different links still give their true separation.
urdf::Vector3 jointOriginInRoot(const urdf::Model& model, const urdf::Joint& joint) {
  urdf::Vector3 p = joint.parent_to_joint_origin_transform.position;
  urdf::LinkConstSharedPtr link = model.getLink(joint.parent_link_name);
  while (link && link->parent_joint) {
    const urdf::Pose& pose = link->parent_joint->parent_to_joint_origin_transform;
    p = pose.rotation * p + pose.position;
    link = model.getLink(link->parent_joint->parent_link_name);
  }
  return p;
}

// Radius of the first cylinder or sphere among a link's collision geometries.
bool collisionRadius(const urdf::Link& link, double& radius) {
  std::vector<urdf::CollisionSharedPtr> collisions = link.collision_array;
  if (collisions.empty() && link.collision) collisions.push_back(link.collision);
  for (const auto& c : collisions) {
    if (!c || !c->geometry) continue;
    if (c->geometry->type == urdf::Geometry::CYLINDER) {
      radius = static_cast<const urdf::Cylinder*>(c->geometry.get())->radius;
      return true;
    }
    if (c->geometry->type == urdf::Geometry::SPHERE) {
      radius = static_cast<const urdf::Sphere*>(c->geometry.get())->radius;
      return true;
    }
  }
  return false;
}

class DiffDriveController : public Controller {
 public:
  bool init(RobotHW& hw, ros::NodeHandle& root_nh, ros::NodeHandle& controller_nh, std::string& error) override;
  void starting(const ros::Time& time) override;
  void update(const ros::Time& time, const ros::Duration& period) override;
  void stopping(const ros::Time& time) override;

 private:
  struct Command {
    double lin = 0.0;
    double ang = 0.0;
    ros::Time stamp;
  };

  bool configure(RobotHW& hw, ros::NodeHandle& root_nh, ros::NodeHandle& controller_nh, ros_params::Reader& params,
                 std::string& error);
  bool readWheelNames(ros_params::Reader& params, const std::string& side, std::vector<std::string>& names);
  bool readLimiter(ros_params::Reader& params, const std::string& prefix, diff_drive::SpeedLimiter& limiter);
  bool readCovariance(ros_params::Reader& params, const std::string& name, double (&diagonal)[6]);
  bool setOdomParamsFromUrdf(ros::NodeHandle& root_nh, ros_params::Reader& params, const std::string& left_wheel,
                             const std::string& right_wheel, bool lookup_separation, bool lookup_radius);
  void cmdVelCallback(const geometry_msgs::Twist& command);
  void brake();
  void publishOdometry(const ros::Time& time);

  std::string name_;
  std::vector<JointData*> left_wheels_, right_wheels_;

  // Parameters.
  double wheel_separation_ = 0.0, wheel_radius_ = 0.0;
  double wheel_separation_multiplier_ = 1.0;
  double left_wheel_radius_multiplier_ = 1.0, right_wheel_radius_multiplier_ = 1.0;
  double ws_ = 0.0, lwr_ = 0.0, rwr_ = 0.0;  // with the multipliers applied
  double cmd_vel_timeout_ = 0.5;
  bool allow_multiple_cmd_vel_publishers_ = true;
  std::string base_frame_id_ = "base_link";
  std::string odom_frame_id_ = "odom";
  bool enable_odom_tf_ = true;
  bool open_loop_ = false;
  bool publish_cmd_ = false;
  ros::Duration publish_period_;
  diff_drive::SpeedLimiter limiter_lin_, limiter_ang_;

  // State.
  bool running_ = false;
  ros::Time last_time_;                // the latest control time seen: stamps incoming commands
  ros::Time last_state_publish_time_;
  Command command_;                     // latest accepted cmd_vel
  Command last0_cmd_, last1_cmd_;       // the two previous limited commands
  diff_drive::Odometry odometry_;

  ros::Subscriber sub_command_;
  ros::Publisher odom_pub_, tf_odom_pub_, cmd_vel_pub_;
  nav_msgs::Odometry odom_msg_;
  tf2_msgs::TFMessage tf_msg_;
  double log_not_running_last_ = -1.0, log_publishers_last_ = -1.0, log_nonfinite_last_ = -1.0;  // for throttle()
};

bool DiffDriveController::readWheelNames(ros_params::Reader& params, const std::string& side, std::vector<std::string>& names) {
  // ros_controllers' name is "<side>_wheel"; "<side>_wheel_joint" is accepted as well.
  const std::string primary = side + "_wheel";
  const std::string alias = side + "_wheel_joint";
  const std::string expected = "expected a joint name or a list of joint names";

  auto read = [&](const std::string& name, std::vector<std::string>& out) {
    XmlRpc::XmlRpcValue v;
    params.read(name, &v);
    if (v.getType() == XmlRpc::XmlRpcValue::TypeString) {
      if (static_cast<std::string>(v).empty()) return params.fail(name, "empty joint name; " + expected);
      out.push_back(static_cast<std::string>(v));
      return true;
    }
    if (v.getType() != XmlRpc::XmlRpcValue::TypeArray) return params.fail(name, expected);
    if (v.size() == 0) return params.fail(name, "empty list; " + expected);
    for (int i = 0; i < v.size(); ++i) {
      if (v[i].getType() != XmlRpc::XmlRpcValue::TypeString || static_cast<std::string>(v[i]).empty())
        return params.fail(name, "element " + std::to_string(i) + " is not a joint name; " + expected);
      out.push_back(static_cast<std::string>(v[i]));
    }
    return true;
  };

  const bool has_primary = params.has(primary), has_alias = params.has(alias);
  if (!has_primary && !has_alias)
    return params.fail(primary, "required parameter missing (neither " + primary + " nor " + alias + " is set); " +
                                    expected);
  if (has_primary && !read(primary, names)) return false;
  if (has_alias) {
    std::vector<std::string> alias_names;
    if (!read(alias, alias_names)) return false;
    if (has_primary && alias_names != names)
      return params.fail(alias, "differs from " + params.path(primary) + "; expected only one of the two");
    names = alias_names;
  }
  return true;
}

bool DiffDriveController::readLimiter(ros_params::Reader& params, const std::string& prefix, diff_drive::SpeedLimiter& l) {
  // As ros_controllers: each min_* defaults to -max_*.
  if (!boolean(params, prefix + "has_velocity_limits", l.has_velocity_limits) ||
      !boolean(params, prefix + "has_acceleration_limits", l.has_acceleration_limits) ||
      !boolean(params, prefix + "has_jerk_limits", l.has_jerk_limits) ||
      !number(params, prefix + "max_velocity", l.max_velocity))
    return false;
  l.min_velocity = -l.max_velocity;
  if (!number(params, prefix + "min_velocity", l.min_velocity) ||
      !number(params, prefix + "max_acceleration", l.max_acceleration))
    return false;
  l.min_acceleration = -l.max_acceleration;
  if (!number(params, prefix + "min_acceleration", l.min_acceleration) || !number(params, prefix + "max_jerk", l.max_jerk))
    return false;
  l.min_jerk = -l.max_jerk;
  if (!number(params, prefix + "min_jerk", l.min_jerk)) return false;

  struct Range {
    bool enabled;
    const char* what;
    double min, max;
  };
  for (const Range& r : {Range{l.has_velocity_limits, "velocity", l.min_velocity, l.max_velocity},
                         Range{l.has_acceleration_limits, "acceleration", l.min_acceleration, l.max_acceleration},
                         Range{l.has_jerk_limits, "jerk", l.min_jerk, l.max_jerk}}) {
    if (!r.enabled) continue;
    if (r.min > r.max)
      return params.fail(prefix + "min_" + r.what, "is " + str(r.min) + ", above max_" + r.what + " (" + str(r.max) +
                                                      "); expected min_" + r.what + " <= max_" + r.what);
    if (r.min == 0.0 && r.max == 0.0)
      ROS_WARN_STREAM_NAMED(name_, params.path(prefix + "has_" + r.what + "_limits")
                                       << " is true but max_" << r.what << " and min_" << r.what
                                       << " are 0: the controller will not move along this axis");
  }
  return true;
}

bool DiffDriveController::readCovariance(ros_params::Reader& params, const std::string& name, double (&diagonal)[6]) {
  // Optional (ros_controllers asserts it is there; without it a release build used zeros).
  for (double& d : diagonal) d = 0.0;
  XmlRpc::XmlRpcValue v;
  if (!params.read(name, &v)) return true;
  const std::string expected = "expected a list of 6 numbers (the covariance diagonal for x, y, z, rotation about X, Y, Z)";
  if (v.getType() != XmlRpc::XmlRpcValue::TypeArray || v.size() != 6) return params.fail(name, expected);
  for (int i = 0; i < 6; ++i) {
    if (!isNumber(v[i])) return params.fail(name, "element " + std::to_string(i) + " is not a number; " + expected);
    diagonal[i] = toDouble(v[i]);
  }
  return true;
}

bool DiffDriveController::setOdomParamsFromUrdf(ros::NodeHandle& root_nh, ros_params::Reader& params, const std::string& left_wheel,
                                                const std::string& right_wheel, bool lookup_separation,
                                                bool lookup_radius) {
  if (!lookup_separation && !lookup_radius) return true;  // nothing to derive: don't parse the URDF
  const std::string param = lookup_separation ? "wheel_separation" : "wheel_radius";
  const std::string description = root_nh.resolveName("robot_description");
  auto fail = [&](const std::string& param_name, const std::string& why) {
    return params.fail(param_name, "not set, and could not be derived from the URDF: " + why +
                                       "; expected a positive number (m), or " + description +
                                       " with the wheel joints and their wheel links' cylinder (or sphere) collisions");
  };

  std::string urdf_xml;
  if (!root_nh.getParam("robot_description", urdf_xml)) return fail(param, description + " is not set (or not a string)");
  urdf::Model model;
  if (!model.initString(urdf_xml)) return fail(param, description + " is not a valid URDF");

  const urdf::JointConstSharedPtr left = model.getJoint(left_wheel);
  const urdf::JointConstSharedPtr right = model.getJoint(right_wheel);
  if (!left) return fail(param, "joint '" + left_wheel + "' is not in " + description);

  if (lookup_separation) {
    if (!right) return fail("wheel_separation", "joint '" + right_wheel + "' is not in " + description);
    const urdf::Vector3 l = jointOriginInRoot(model, *left);
    const urdf::Vector3 r = jointOriginInRoot(model, *right);
    wheel_separation_ = std::sqrt((l.x - r.x) * (l.x - r.x) + (l.y - r.y) * (l.y - r.y) + (l.z - r.z) * (l.z - r.z));
    if (!(wheel_separation_ > 0.0))
      return fail("wheel_separation", "joints '" + left_wheel + "' and '" + right_wheel + "' have the same origin");
    ROS_INFO_STREAM_NAMED(name_, "wheel_separation " << wheel_separation_ << " m from the URDF joints '" << left_wheel
                                                     << "' and '" << right_wheel << "'");
  }
  if (lookup_radius) {
    const urdf::LinkConstSharedPtr link = model.getLink(left->child_link_name);
    if (!link) return fail("wheel_radius", "link '" + left->child_link_name + "' is not in " + description);
    if (!collisionRadius(*link, wheel_radius_))
      return fail("wheel_radius", "link '" + link->name + "' (child of joint '" + left_wheel +
                                      "') has no cylinder or sphere collision geometry");
    if (!(wheel_radius_ > 0.0)) return fail("wheel_radius", "link '" + link->name + "' has a collision radius of 0");
    ROS_INFO_STREAM_NAMED(name_, "wheel_radius " << wheel_radius_ << " m from the collision of URDF link '"
                                                 << link->name << "'");
  }
  return true;
}

bool DiffDriveController::init(RobotHW& hw, ros::NodeHandle& root_nh, ros::NodeHandle& controller_nh,
                               std::string& error) {
  ros_params::Reader params(controller_nh);
  if (configure(hw, root_nh, controller_nh, params, error)) return true;
  if (!params.ok()) error = params.problems();  // else claim() has said what went wrong
  return false;
}

bool DiffDriveController::configure(RobotHW& hw, ros::NodeHandle& root_nh, ros::NodeHandle& controller_nh,
                                    ros_params::Reader& params, std::string& error) {
  const std::string ns = controller_nh.getNamespace();
  name_ = ns.substr(ns.find_last_of('/') + 1);

  // Wheel joints.
  std::vector<std::string> left_names, right_names;
  if (!readWheelNames(params, "left", left_names) || !readWheelNames(params, "right", right_names)) return false;
  if (left_names.size() != right_names.size())
    return params.fail(params.has("right_wheel") ? "right_wheel" : "right_wheel_joint",
                       "has " + std::to_string(right_names.size()) + " joint(s) but the left side has " +
                           std::to_string(left_names.size()) + "; expected as many right wheels as left wheels");
  for (std::size_t i = 0; i < left_names.size(); ++i) {
    JointData* l = claim(hw, left_names[i], InterfaceType::Velocity, error);
    if (!l) return false;
    JointData* r = claim(hw, right_names[i], InterfaceType::Velocity, error);
    if (!r) return false;
    left_wheels_.push_back(l);
    right_wheels_.push_back(r);
  }

  // Odometry and command parameters.
  double publish_rate = 50.0;
  if (!number(params, "publish_rate", publish_rate, "a positive number (Hz)")) return false;
  if (!(publish_rate > 0.0) || std::isinf(publish_rate) || 1.0 / publish_rate > 1e9)
    return params.fail("publish_rate", "is " + str(publish_rate) + "; expected a positive number (Hz)");
  publish_period_ = ros::Duration(1.0 / publish_rate);

  if (!boolean(params, "open_loop", open_loop_)) return false;

  for (const char* name : {"wheel_separation_multiplier", "wheel_radius_multiplier", "left_wheel_radius_multiplier",
                           "right_wheel_radius_multiplier"}) {
    double m = 1.0;
    if (!number(params, name, m, "a non-zero number")) return false;
    if (m == 0.0 || std::isinf(m)) return params.fail(name, "is " + str(m) + "; expected a non-zero number");
  }
  number(params, "wheel_separation_multiplier", wheel_separation_multiplier_);
  if (params.has("wheel_radius_multiplier")) {  // overrides the per-side ones, as ros_controllers
    double m = 1.0;
    number(params, "wheel_radius_multiplier", m);
    left_wheel_radius_multiplier_ = right_wheel_radius_multiplier_ = m;
  } else {
    number(params, "left_wheel_radius_multiplier", left_wheel_radius_multiplier_);
    number(params, "right_wheel_radius_multiplier", right_wheel_radius_multiplier_);
  }

  int window = 10;
  if (!integer(params, "velocity_rolling_window_size", window, "a positive integer")) return false;
  if (window < 1)
    return params.fail("velocity_rolling_window_size", "is " + std::to_string(window) + "; expected a positive integer");
  odometry_.setVelocityRollingWindowSize(static_cast<std::size_t>(window));

  if (!number(params, "cmd_vel_timeout", cmd_vel_timeout_, "a non-negative number (s)")) return false;
  if (cmd_vel_timeout_ < 0.0)
    return params.fail("cmd_vel_timeout", "is " + str(cmd_vel_timeout_) + "; expected a non-negative number (s)");

  if (!boolean(params, "allow_multiple_cmd_vel_publishers", allow_multiple_cmd_vel_publishers_) ||
      !nonEmptyString(params, "base_frame_id", base_frame_id_, "a frame name") ||
      !nonEmptyString(params, "odom_frame_id", odom_frame_id_, "a frame name") ||
      !boolean(params, "enable_odom_tf", enable_odom_tf_) || !boolean(params, "publish_cmd", publish_cmd_))
    return false;

  if (!readLimiter(params, "linear/x/", limiter_lin_) || !readLimiter(params, "angular/z/", limiter_ang_)) return false;

  double pose_cov[6], twist_cov[6];
  if (!readCovariance(params, "pose_covariance_diagonal", pose_cov) ||
      !readCovariance(params, "twist_covariance_diagonal", twist_cov))
    return false;

  // Wheel geometry: parameters, else the URDF.
  const bool lookup_separation = !params.has("wheel_separation");
  const bool lookup_radius = !params.has("wheel_radius");
  if (!lookup_separation) {
    if (!number(params, "wheel_separation", wheel_separation_, "a positive number (m)")) return false;
    if (!(wheel_separation_ > 0.0) || std::isinf(wheel_separation_))
      return params.fail("wheel_separation", "is " + str(wheel_separation_) + "; expected a positive number (m)");
  }
  if (!lookup_radius) {
    if (!number(params, "wheel_radius", wheel_radius_, "a positive number (m)")) return false;
    if (!(wheel_radius_ > 0.0) || std::isinf(wheel_radius_))
      return params.fail("wheel_radius", "is " + str(wheel_radius_) + "; expected a positive number (m)");
  }
  if (!setOdomParamsFromUrdf(root_nh, params, left_names[0], right_names[0], lookup_separation, lookup_radius))
    return false;

  ws_ = wheel_separation_multiplier_ * wheel_separation_;
  lwr_ = left_wheel_radius_multiplier_ * wheel_radius_;
  rwr_ = right_wheel_radius_multiplier_ * wheel_radius_;
  odometry_.setWheelParams(ws_, lwr_, rwr_);

  // Publishers and the command subscriber.
  odom_msg_.header.frame_id = odom_frame_id_;
  odom_msg_.child_frame_id = base_frame_id_;
  for (int i = 0; i < 6; ++i) {
    odom_msg_.pose.covariance[static_cast<std::size_t>(i * 7)] = pose_cov[i];
    odom_msg_.twist.covariance[static_cast<std::size_t>(i * 7)] = twist_cov[i];
  }
  odom_pub_ = controller_nh.advertise<nav_msgs::Odometry>("odom", 100);
  if (enable_odom_tf_) {
    tf_msg_.transforms.resize(1);
    tf_msg_.transforms[0].header.frame_id = odom_frame_id_;
    tf_msg_.transforms[0].child_frame_id = base_frame_id_;
    tf_odom_pub_ = root_nh.advertise<tf2_msgs::TFMessage>("/tf", 100);
  }
  if (publish_cmd_) cmd_vel_pub_ = controller_nh.advertise<geometry_msgs::TwistStamped>("cmd_vel_out", 100);
  sub_command_ = controller_nh.subscribe("cmd_vel", 1, &DiffDriveController::cmdVelCallback, this);

  std::ostringstream joints;
  for (std::size_t i = 0; i < left_names.size(); ++i)
    joints << (i ? ", " : "") << left_names[i] << " / " << right_names[i];
  ROS_INFO_STREAM_NAMED(name_, name_ << ": wheels (left / right) " << joints.str() << "; wheel separation " << ws_
                                     << " m, left wheel radius " << lwr_ << " m, right wheel radius " << rwr_
                                     << " m; odometry " << (open_loop_ ? "open loop" : "from wheel positions")
                                     << " published at " << publish_rate << " Hz in " << odom_frame_id_ << " -> "
                                     << base_frame_id_ << (enable_odom_tf_ ? " (and on /tf)" : "")
                                     << "; cmd_vel timeout " << cmd_vel_timeout_ << " s");
  return true;
}

void DiffDriveController::starting(const ros::Time& time) {
  brake();
  running_ = true;
  last_time_ = time;
  last_state_publish_time_ = time;
  // A fresh start: no stale command (the wheels were braked when stopped) and the limiter
  // history starts from rest. The pose is kept, as ros_controllers does.
  command_ = Command();
  command_.stamp = time;
  last0_cmd_ = last1_cmd_ = Command();
  odometry_.init(time.toSec());
}

void DiffDriveController::stopping(const ros::Time& /*time*/) {
  brake();
  running_ = false;
}

void DiffDriveController::brake() {
  for (JointData* j : left_wheels_) j->command = 0.0;
  for (JointData* j : right_wheels_) j->command = 0.0;
}

void DiffDriveController::update(const ros::Time& time, const ros::Duration& period) {
  if (time < last_time_) {  // simulation time went backwards (world reset): restart the timing
    last_state_publish_time_ = time;
    command_.stamp = time;
    command_.lin = command_.ang = 0.0;
  }
  last_time_ = time;

  // Odometry.
  if (open_loop_) {
    odometry_.updateOpenLoop(last0_cmd_.lin, last0_cmd_.ang, time.toSec());
  } else {
    double left_pos = 0.0, right_pos = 0.0;
    for (std::size_t i = 0; i < left_wheels_.size(); ++i) {
      const double lp = left_wheels_[i]->position, rp = right_wheels_[i]->position;
      if (std::isnan(lp) || std::isnan(rp)) return;  // no valid state: leave everything as is
      left_pos += lp;
      right_pos += rp;
    }
    left_pos /= static_cast<double>(left_wheels_.size());
    right_pos /= static_cast<double>(right_wheels_.size());
    odometry_.update(left_pos, right_pos, time.toSec());
  }
  if (last_state_publish_time_ + publish_period_ < time) {
    last_state_publish_time_ += publish_period_;
    publishOdometry(time);
  }

  // Command: brake if stale, limit, then split onto the wheels.
  Command cmd = command_;
  const double age = (time - cmd.stamp).toSec();
  if (age > cmd_vel_timeout_ || age < 0.0) {
    cmd.lin = 0.0;
    cmd.ang = 0.0;
  }
  const double dt = period.toSec();
  limiter_lin_.limit(cmd.lin, last0_cmd_.lin, last1_cmd_.lin, dt);
  limiter_ang_.limit(cmd.ang, last0_cmd_.ang, last1_cmd_.ang, dt);
  last1_cmd_ = last0_cmd_;
  last0_cmd_ = cmd;

  if (publish_cmd_) {
    geometry_msgs::TwistStamped out;
    out.header.stamp = time;
    out.header.frame_id = base_frame_id_;
    out.twist.linear.x = cmd.lin;
    out.twist.angular.z = cmd.ang;
    publish_thread::publish(cmd_vel_pub_, out);
  }

  const diff_drive::WheelVelocities w = diff_drive::inverseKinematics(cmd.lin, cmd.ang, ws_, lwr_, rwr_);
  for (JointData* j : left_wheels_) j->command = w.left;
  for (JointData* j : right_wheels_) j->command = w.right;
}

void DiffDriveController::publishOdometry(const ros::Time& time) {
  const double half = odometry_.heading() * 0.5;
  geometry_msgs::Quaternion q;
  q.x = 0.0;
  q.y = 0.0;
  q.z = std::sin(half);
  q.w = std::cos(half);

  odom_msg_.header.stamp = time;
  odom_msg_.pose.pose.position.x = odometry_.x();
  odom_msg_.pose.pose.position.y = odometry_.y();
  odom_msg_.pose.pose.orientation = q;
  odom_msg_.twist.twist.linear.x = odometry_.linear();
  odom_msg_.twist.twist.angular.z = odometry_.angular();
  publish_thread::publish(odom_pub_, odom_msg_);

  if (enable_odom_tf_) {
    geometry_msgs::TransformStamped& t = tf_msg_.transforms[0];
    t.header.stamp = time;
    t.transform.translation.x = odometry_.x();
    t.transform.translation.y = odometry_.y();
    t.transform.translation.z = 0.0;
    t.transform.rotation = q;
    publish_thread::publish(tf_odom_pub_, tf_msg_);
  }
}

void DiffDriveController::cmdVelCallback(const geometry_msgs::Twist& command) {
  if (!running_) {
    if (throttle(log_not_running_last_))
      ROS_ERROR_STREAM_NAMED(name_, name_ << ": can't accept new commands; the controller is not running.");
    return;
  }
  if (!allow_multiple_cmd_vel_publishers_ && sub_command_.getNumPublishers() > 1) {
    if (throttle(log_publishers_last_))
      ROS_ERROR_STREAM_NAMED(name_, name_ << ": detected " << sub_command_.getNumPublishers() << " publishers on "
                                          << sub_command_.getTopic() << "; only 1 is allowed. Braking.");
    brake();
    command_ = Command();  // and keep braking until a single publisher sends again
    command_.stamp = last_time_;
    return;
  }
  if (!std::isfinite(command.linear.x) || !std::isfinite(command.angular.z)) {
    if (throttle(log_nonfinite_last_)) {
      ROS_WARN_STREAM_NAMED(name_, name_ << ": received a non-finite velocity command (linear.x " << command.linear.x
                                         << ", angular.z " << command.angular.z << ") on "
                                         << sub_command_.getTopic() << ". Ignoring.");
    }
    return;
  }
  command_.lin = command.linear.x;
  command_.ang = command.angular.z;
  // Callbacks run between simulation steps: the command arrived at the latest control time.
  command_.stamp = last_time_;
}

}  // namespace

SIM_CONTROL_REGISTER_CONTROLLER("diff_drive_controller/DiffDriveController", DiffDriveController)

}  // namespace sim_control
