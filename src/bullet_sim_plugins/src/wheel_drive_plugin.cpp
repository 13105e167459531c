// The wheeled-drive engine that libgazebo_ros_diff_drive.so and libgazebo_ros_skid_steer_drive.so
// share (see wheel_drive_plugin.h).
#include <geometry_msgs/TransformStamped.h>
#include <nav_msgs/Odometry.h>
#include <sensor_msgs/JointState.h>
#include <tf2_msgs/TFMessage.h>

#include <cmath>
#include <sstream>
#include <utility>

#include "bullet_sim_core/description_error.h"
#include "bullet_sim_plugins/ros_conversions.h"
#include "bullet_sim_plugins/wheel_drive_plugin.h"
#include "publish_thread/publish_thread.h"
#include "ros_params/reader.h"

namespace bullet_sim {
namespace {

// Wall-clock throttle for warnings about bad commands (ROS_*_THROTTLE would use sim time).
const ros::WallDuration kWarningPeriod(5.0);

geometry_msgs::TransformStamped toTransformMsg(const Eigen::Isometry3d& pose, const ros::Time& stamp,
                                               const std::string& parent, const std::string& child) {
  geometry_msgs::TransformStamped t;
  t.header.stamp = stamp;
  t.header.frame_id = parent;
  t.child_frame_id = child;
  const geometry_msgs::Pose p = toPoseMsg(pose);
  t.transform.translation.x = p.position.x;
  t.transform.translation.y = p.position.y;
  t.transform.translation.z = p.position.z;
  t.transform.rotation = p.orientation;
  return t;
}

double yawOf(const Eigen::Matrix3d& r) { return std::atan2(r(1, 0), r(0, 0)); }

std::string fmt(double v) {
  std::ostringstream out;
  out << v;
  return out.str();
}

}  // namespace

WheelDrivePlugin::WheelDrivePlugin(PhysicsModel& model, WheelDriveSettings settings)
    : model_(model),
      settings_(std::move(settings)),
      command_(settings_.wheel_separation, settings_.wheel_diameter, settings_.wheel_acceleration,
               settings_.cmd_timeout),
      encoder_(settings_.wheel_separation, settings_.wheel_diameter),
      period_(settings_.update_rate > 0 ? 1.0 / settings_.update_rate : 0.0) {
  auto wheel = [&](const std::string& name) {
    const int j = model.jointIndex(name);
    if (j < 0) {
      throw DescriptionError(settings_.where + ": joint '" + name +
                             "': expected a revolute or continuous joint of model '" + model.name() + "'" +
                             (model.isStatic() ? " (the model is static: nothing in it moves)" : ""));
    }
    const JointDescription& d = model.joints()[j];
    return Wheel{j, name, d.parent, d.child};
  };
  for (const std::string& name : settings_.left_joints) left_.push_back(wheel(name));
  for (const std::string& name : settings_.right_joints) right_.push_back(wheel(name));

  try {
    node_ = ros::NodeHandle(settings_.robot_namespace);
    command_subscriber_ = node_.subscribe(settings_.command_topic, 1, &WheelDrivePlugin::onCommand, this);
    if (settings_.publish_odometry)
      odometry_publisher_ = node_.advertise<nav_msgs::Odometry>(settings_.odometry_topic, 1);
    if (settings_.publish_wheel_joint_state)
      joint_state_publisher_ = node_.advertise<sensor_msgs::JointState>("joint_states", 10);
  } catch (const ros::InvalidNameException& e) {
    throw DescriptionError(settings_.where + ": expected valid ROS names for <robotNamespace> and the topics: " +
                           e.what());
  }
  // tf_prefix as gazebo_plugins reads it (tf::getPrefixParam: searched upward from the namespace).
  ros_params::Reader params(node_);
  params.search("tf_prefix", &tf_prefix_);
  for (const std::string& problem : params.problemList()) ROS_ERROR("%s; no tf_prefix used.", problem.c_str());
  odometry_frame_ = resolveFrame(tf_prefix_, settings_.odometry_frame);
  base_frame_ = resolveFrame(tf_prefix_, settings_.robot_base_frame);
  if ((settings_.publish_odometry && settings_.publish_odom_tf) || settings_.publish_wheel_tf)
    tf_publisher_ = ros::NodeHandle().advertise<tf2_msgs::TFMessage>("/tf", 100);  // as tf2_ros's broadcaster
  if (settings_.odometry_source == OdometrySource::Encoder) readEncoders();  // the reference angles

  std::string wheels;
  for (const auto* side : {&left_, &right_})
    for (const Wheel& w : *side) wheels += (wheels.empty() ? "" : ", ") + w.name;
  std::string odometry = "no odometry (<publishTf> false)";
  if (settings_.publish_odometry) {
    odometry = "odometry on " + odometry_publisher_.getTopic() + " (" + odometry_frame_ + " -> " + base_frame_ + ", " +
               (settings_.odometry_source == OdometrySource::World ? "world pose" : "wheel encoders") +
               (settings_.publish_odom_tf ? ", also on /tf)" : ")");
  }
  ROS_INFO_STREAM("model '" << model.name() << "': " << settings_.plugin_file << ": commands on "
                            << command_subscriber_.getTopic() << " drive " << wheels << " (at most "
                            << settings_.max_torque << " N m each), " << odometry << ", at "
                            << (settings_.update_rate > 0 ? fmt(settings_.update_rate) + " Hz" : "every step")
                            << "; cmdTimeout "
                            << (settings_.cmd_timeout > 0 ? fmt(settings_.cmd_timeout) + " s" : "off"));
}

WheelDrivePlugin::~WheelDrivePlugin() {
  for (const auto* side : {&left_, &right_})
    for (const Wheel& w : *side) model_.clearJointMotor(w.joint);
}

void WheelDrivePlugin::onCommand(const geometry_msgs::Twist::ConstPtr& msg) {
  if (!isFinite(*msg)) {
    const ros::WallTime wall = ros::WallTime::now();
    if (last_bad_command_warning_.isZero() || wall - last_bad_command_warning_ >= kWarningPeriod) {
      last_bad_command_warning_ = wall;
      ROS_WARN_STREAM("model '" << model_.name() << "': " << settings_.plugin_file << ": ignoring a command on "
                                << command_subscriber_.getTopic()
                                << " with a NaN or infinite value (linear " << msg->linear.x << " "
                                << msg->linear.y << " " << msg->linear.z << ", angular " << msg->angular.x << " "
                                << msg->angular.y << " " << msg->angular.z << ")");
    }
    return;
  }
  // Applied, and timed, at the next step: callbacks run between steps.
  pending_linear_ = msg->linear.x;
  pending_angular_ = msg->angular.z;
  has_pending_ = true;
}

bool WheelDrivePlugin::due(const ros::Time& now, ros::Time& next) const {
  if (now < next) return false;
  next = (next.isZero() || now - next > period_) ? now + period_ : next + period_;
  return true;
}

void WheelDrivePlugin::beforeStep(const ros::Time& now, double dt) {
  if (has_pending_) {
    command_.setTwist(pending_linear_, pending_angular_, now.toSec());
    has_pending_ = false;
  }
  if (!due(now, next_command_)) return;
  const double elapsed = has_last_command_ ? (now - last_command_).toSec() : std::max(period_.toSec(), dt);
  last_command_ = now;
  has_last_command_ = true;

  const bool timed_out = command_.timedOut(now.toSec());
  if (timed_out && !was_timed_out_) {
    if (!told_timeout_) {
      ROS_INFO_STREAM("model '" << model_.name() << "': " << settings_.plugin_file << ": no command on "
                                << command_subscriber_.getTopic() << " for " << settings_.cmd_timeout
                                << " s: stopping the wheels (<cmdTimeout> sets this; 0 disables it)");
      told_timeout_ = true;
    } else {
      ROS_DEBUG_STREAM("model '" << model_.name() << "': no command for " << settings_.cmd_timeout
                                 << " s: stopping the wheels");
    }
  }
  was_timed_out_ = timed_out;

  const WheelSpeeds speeds = command_.update(now.toSec(), elapsed);
  for (const Wheel& w : left_) model_.setJointMotor(w.joint, 0.0, speeds.left, 0.0, settings_.max_torque);
  for (const Wheel& w : right_) model_.setJointMotor(w.joint, 0.0, speeds.right, 0.0, settings_.max_torque);
}

void WheelDrivePlugin::readEncoders() {
  double left = 0.0, right = 0.0;
  for (const Wheel& w : left_) left += model_.jointPosition(w.joint) / left_.size();
  for (const Wheel& w : right_) right += model_.jointPosition(w.joint) / right_.size();
  encoder_.update(left, right);
}

void WheelDrivePlugin::afterStep(const ros::Time& now) {
  if (settings_.odometry_source == OdometrySource::Encoder) readEncoders();
  if (!due(now, next_publish_)) return;
  publish(now);
}

void WheelDrivePlugin::publish(const ros::Time& now) {
  tf2_msgs::TFMessage tf;
  if (settings_.publish_odometry) {
    nav_msgs::Odometry odom;
    odom.header.stamp = now;
    odom.header.frame_id = odometry_frame_;
    odom.child_frame_id = base_frame_;
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    if (settings_.odometry_source == OdometrySource::World) {
      // The model frame in the world, as upstream: the odometry frame is the world frame.
      pose = model_.pose();
      const Twist twist = model_.twist();
      const double yaw = yawOf(pose.linear());
      // Planar velocity in the base's heading frame, as upstream.
      odom.twist.twist.linear.x = std::cos(yaw) * twist.linear.x() + std::sin(yaw) * twist.linear.y();
      odom.twist.twist.linear.y = std::cos(yaw) * twist.linear.y() - std::sin(yaw) * twist.linear.x();
      odom.twist.twist.angular.z = twist.angular.z();
    } else {
      pose.translation() = Eigen::Vector3d(encoder_.x(), encoder_.y(), 0.0);
      pose.linear() = Eigen::AngleAxisd(encoder_.heading(), Eigen::Vector3d::UnitZ()).toRotationMatrix();
      const double elapsed = has_published_ ? (now - published_time_).toSec() : 0.0;
      if (elapsed > 0) {
        odom.twist.twist.linear.x = (encoder_.distance() - published_distance_) / elapsed;
        odom.twist.twist.angular.z = (encoder_.heading() - published_heading_) / elapsed;
      }
    }
    published_distance_ = encoder_.distance();
    published_heading_ = encoder_.heading();
    published_time_ = now;
    has_published_ = true;
    odom.pose.pose = toPoseMsg(pose);
    for (int i = 0; i < 6; ++i) {
      odom.pose.covariance[i * 7] = settings_.pose_covariance[i];
      odom.twist.covariance[i * 7] = settings_.twist_covariance[i];
    }
    publish_thread::publish(odometry_publisher_, odom);
    if (settings_.publish_odom_tf) tf.transforms.push_back(toTransformMsg(pose, now, odometry_frame_, base_frame_));
  }
  if (settings_.publish_wheel_tf) {
    for (const auto* side : {&right_, &left_}) {
      for (const Wheel& w : *side) {
        const Eigen::Isometry3d relative = model_.linkPose(w.parent_link).inverse() * model_.linkPose(w.child_link);
        tf.transforms.push_back(toTransformMsg(relative, now, resolveFrame(tf_prefix_, w.parent_link),
                                               resolveFrame(tf_prefix_, w.child_link)));
      }
    }
  }
  if (!tf.transforms.empty() && tf_publisher_) publish_thread::publish(tf_publisher_, std::move(tf));
  if (settings_.publish_wheel_joint_state) {
    sensor_msgs::JointState state;
    state.header.stamp = now;
    for (const auto* side : {&right_, &left_}) {  // upstream's order: right, then left
      for (const Wheel& w : *side) {
        state.name.push_back(w.name);
        state.position.push_back(model_.jointPosition(w.joint));
        state.velocity.push_back(model_.jointVelocity(w.joint));
      }
    }
    publish_thread::publish(joint_state_publisher_, std::move(state));
  }
}

void WheelDrivePlugin::reset() {
  command_.reset();
  has_pending_ = false;
  was_timed_out_ = false;
  encoder_.reset();
  encoder_.resetReference();
  if (settings_.odometry_source == OdometrySource::Encoder) readEncoders();
  has_published_ = false;
  next_command_ = ros::Time();
  next_publish_ = ros::Time();
  has_last_command_ = false;
}

}  // namespace bullet_sim
