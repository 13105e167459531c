#pragma once
// Pieces the controllers share: a command slot written by ROS callbacks and read by update(),
// a log throttle, ros_controllers' joint-limit handling, and the JointControllerState publisher.
// Controllers publish from update() through publish_thread::publish (the process's publishing
// thread), as ros_controllers do through realtime_tools' RealtimePublisher: update() never waits
// on roscpp.
#include <control_msgs/JointControllerState.h>
#include <ros/node_handle.h>
#include <ros/console.h>
#include <ros/publisher.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <mutex>
#include <sstream>
#include <string>
#include <vector>

#include "publish_thread/publish_thread.h"
#include "sim_control/pid.h"
#include "sim_control/robot_hw.h"

namespace sim_control {
namespace controllers {

// Command callbacks run on a ROS spinner thread while update() runs in the simulation loop;
// this plays the part of ros_controllers' RealtimeBuffer.
template <typename T>
class CommandBuffer {
 public:
  void set(const T& value) {
    std::lock_guard<std::mutex> lock(mutex_);
    value_ = value;
  }
  // Copies into `out` so a vector reuses its storage every update.
  void get(T& out) const {
    std::lock_guard<std::mutex> lock(mutex_);
    out = value_;
  }

 private:
  mutable std::mutex mutex_;
  T value_{};
};

// At most one message per period of wall time. ROS_*_THROTTLE goes by ros::Time::now(), which
// stays at 0 under sim time until /clock starts, and then never logs.
class WallThrottle {
 public:
  explicit WallThrottle(double period) : period_(period) {}
  bool ready() {
    const ros::WallTime now = ros::WallTime::now();
    if (!last_.isZero() && (now - last_).toSec() < period_) return false;
    last_ = now;
    return true;
  }

 private:
  double period_;
  ros::WallTime last_;
};

// A group command must carry one value per joint; ros_controllers drops any other with an error,
// which we also throttle since a misconfigured publisher repeats it at its own rate.
inline bool commandSizeOk(std::size_t size, const std::vector<std::string>& joints, const std::string& topic,
                          WallThrottle& throttle) {
  if (size == joints.size()) return true;
  if (throttle.ready()) {
    std::ostringstream names;
    for (std::size_t k = 0; k < joints.size(); ++k) names << (k ? ", " : "") << joints[k];
    ROS_ERROR_STREAM(topic << ": ignoring a command with " << size << " values; expected " << joints.size()
                           << ", one per joint (" << names.str() << ")");
  }
  return false;
}

// ros_controllers' enforceJointLimits: a position target is kept within [lower, upper] for
// revolute and prismatic joints.
inline double enforcePositionLimits(const JointData& joint, double target) {
  if (!joint.limits.has_position_limits || joint.limits.continuous) return target;
  return std::max(joint.limits.lower, std::min(target, joint.limits.upper));
}

// angles::shortest_angular_distance: to - from wrapped into (-pi, pi]. Written out because
// Debian's angles package is the ROS 2 (ament) build, not a catkin one.
inline double shortestAngularDistance(double from, double to) {
  const double wrapped = std::fmod(to - from + M_PI, 2.0 * M_PI);  // in (-2 pi, 2 pi)
  return wrapped <= 0.0 ? wrapped + M_PI : wrapped - M_PI;
}

// Continuous joints take the short way round; the others move by the plain difference, which
// for a target inside the limits is the way that stays inside them (what ros_controllers'
// shortest_angular_distance_with_limits picks for revolute joints).
inline double positionError(const JointData& joint, double target) {
  if (joint.limits.continuous) return shortestAngularDistance(joint.position, target);
  return target - joint.position;
}

// The URDF effort limit, which Gazebo's ros_control hardware enforces on effort commands.
inline double clampEffort(const JointData& joint, double effort) {
  const double limit = std::abs(joint.limits.effort);
  return std::isfinite(limit) ? std::max(-limit, std::min(effort, limit)) : effort;
}

// control_msgs/JointControllerState on <controller>/state, every 10th update as ros_controllers'
// effort controllers do, while someone subscribes. The subscribers are counted from roscpp's
// connect callbacks: asking roscpp (getNumSubscribers) takes locks and a lookup by name, which at
// every 10th update of every controller costs a noticeable share of a simulator step.
class ControllerStatePublisher {
 public:
  void init(ros::NodeHandle& controller_nh) {
    auto subscribers = subscribers_;
    pub_ = controller_nh.advertise<control_msgs::JointControllerState>(
        "state", 1, [subscribers](const ros::SingleSubscriberPublisher&) { ++*subscribers; },
        [subscribers](const ros::SingleSubscriberPublisher&) { --*subscribers; });
  }
  void publish(const ros::Time& time, const ros::Duration& period, double set_point, double process_value,
               double process_value_dot, double error, double command, const Pid& pid) {
    if (count_++ % 10 != 0 || *subscribers_ <= 0) return;
    control_msgs::JointControllerState msg;
    msg.header.stamp = time;
    msg.set_point = set_point;
    msg.process_value = process_value;
    msg.process_value_dot = process_value_dot;
    msg.error = error;
    msg.time_step = period.toSec();
    msg.command = command;
    msg.p = pid.gains().p;
    msg.i = pid.gains().i;
    msg.d = pid.gains().d;
    msg.i_clamp = pid.gains().i_clamp_max;  // ros_controllers reports i_max here
    msg.antiwindup = pid.gains().antiwindup;
    publish_thread::publish(pub_, std::move(msg));
  }

 private:
  ros::Publisher pub_;
  std::shared_ptr<int> subscribers_ = std::make_shared<int>(0);  // shared with the callbacks
  unsigned long count_ = 0;
};

}  // namespace controllers
}  // namespace sim_control
