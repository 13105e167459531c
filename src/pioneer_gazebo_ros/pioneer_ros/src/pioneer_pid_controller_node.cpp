// pioneer_pid_controller, the report's: velocity commands on cmd_vel (from move_base or a
// teleop) in, commands for the drive plugin on pioneer/cmd_vel out, with a PID on the linear and
// angular velocity errors against the odometry on pioneer/odom (the drive plugin's). Names are
// relative, so remap them (pioneer_bringup.launch does). The algorithm and its timeouts:
// pioneer_ros/body_velocity_controller.h.
//
// Each command goes out when it comes, as the report's controller (which works in the command's
// callback) sends it, and the update runs again every 1 / rate s of sim time between commands (the
// loop's corrections, and the stop after cmd_timeout). Sent only on the 20 Hz tick, a command would
// wait up to 50 ms, which put enough lag into move_base's loop to halve the Pioneer's exploration
// speed and make explore give up goals (docs/PERFORMANCE.md).
//
// Parameters: the tree of pioneer_controller_params.yaml (controller_gains/body/{linear,angular}/
// {p,i,d,i_clamp}, feedforward, limits, derivative_filter_time, rate, cmd_timeout, odom_timeout),
// read from the node's private namespace, or, when that has no controller_gains, from
// /pioneer_ros, where the report's bring-up (`rosparam load pioneer_controller_params.yaml
// pioneer_ros`) puts them. A bad parameter stops the node with exit status 1.
//
// What it costs. The benchmarks run the simulation at 22x real time, so /clock and /pioneer/odom
// (100 Hz of sim time each) bring 2200 messages a second apiece. roscpp hands every message from
// its network thread to another thread (ros::spin()'s, or its own internal one for /clock), and
// on sim time a ros::Timer's thread polls the clock every millisecond. Those wake-ups, not the
// controller, were most of the node's CPU: without them it takes half as much (README.md). So:
// - the subscriptions' callbacks run in roscpp's network thread as messages arrive
//   (InlineCallbackQueue), under one mutex;
// - on sim time the node reads /clock itself, in the same thread: it sets ros::Time as roscpp's
//   own clock subscription would (that one is remapped to /unused_clock, as the bring-up does for
//   static_transform_publisher) and runs the update every 1 / rate s of sim time (PeriodicTick:
//   ros::Timer's schedule). On wall time, or with /clock remapped on the command line, a
//   ros::Timer runs it.
#include <geometry_msgs/Twist.h>
#include <nav_msgs/Odometry.h>
#include <ros/callback_queue_interface.h>
#include <ros/ros.h>
#include <rosgraph_msgs/Clock.h>
#include <xmlrpcpp/XmlRpcValue.h>

#include <algorithm>
#include <chrono>
#include <mutex>
#include <optional>
#include <string>

#include "pioneer_ros/body_velocity_controller.h"
#include "pioneer_ros/controller_params.h"
#include "pioneer_ros/periodic_tick.h"
#include "pioneer_ros/velocity_messages.h"

namespace pioneer_ros {
namespace {

const char* const kReportNamespace = "/pioneer_ros";
// The node's own clock subscription, ~clock, is remapped to /clock, since /clock itself is
// remapped away from roscpp's subscription.
const char* const kOwnClock = "clock";

// ros::init with the command line's remappings, plus, unless the command line remaps the clock,
// /clock -> /unused_clock and ~clock -> /clock. True when it added them.
bool initWithOwnClock(int argc, char** argv) {
  ros::M_string remappings;  // as ros::init(argc, argv, ...) reads the command line
  for (int k = 1; k < argc; ++k) {
    const std::string arg = argv[k];
    const std::string::size_type pos = arg.find(":=");
    if (pos != std::string::npos) remappings[arg.substr(0, pos)] = arg.substr(pos + 2);
  }
  const bool own_clock = remappings.count("/clock") == 0 && remappings.count("clock") == 0;
  if (own_clock) {
    remappings["/clock"] = "/unused_clock";
    remappings[std::string("~") + kOwnClock] = "/clock";
  }
  ros::init(remappings, "pioneer_pid_controller");
  return own_clock;
}

// The parameter tree and the namespace it came from.
struct ParamTree {
  XmlRpc::XmlRpcValue tree;
  std::string ns;
};

ParamTree readParams() {
  ParamTree params{XmlRpc::XmlRpcValue(), ros::NodeHandle("~").getNamespace()};
  ros::param::get(params.ns, params.tree);
  const bool has_gains =
      params.tree.getType() == XmlRpc::XmlRpcValue::TypeStruct && params.tree.hasMember("controller_gains");
  if (!has_gains && ros::param::has(std::string(kReportNamespace) + "/controller_gains")) {
    params = ParamTree{XmlRpc::XmlRpcValue(), kReportNamespace};
    ros::param::get(params.ns, params.tree);
  }
  return params;
}

// Runs each callback at once, in the thread that queues it: for a subscription, roscpp's network
// thread, as the message arrives.
class InlineCallbackQueue : public ros::CallbackQueueInterface {
 public:
  void addCallback(const ros::CallbackInterfacePtr& callback, uint64_t /*owner_id*/) override { callback->call(); }
  void removeByID(uint64_t /*owner_id*/) override {}
};

std::chrono::nanoseconds sinceEpoch(const ros::Time& t) { return std::chrono::nanoseconds(t.toNSec()); }

// 1 / rate in whole nanoseconds, as ros::Duration rounds it (at least 1).
std::chrono::nanoseconds period(double rate) {
  return std::max(std::chrono::nanoseconds(1), std::chrono::nanoseconds(ros::Duration(1.0 / rate).toNSec()));
}

class PidControllerNode {
 public:
  PidControllerNode(const ros::NodeHandle& nh, const ControllerConfig& config, bool own_clock)
      : nh_(nh),
        controller_(config),
        odom_topic_(nh_.resolveName("pioneer/odom")),
        tick_(period(config.rate), sinceEpoch(ros::Time::now())) {
    ROS_INFO("%s: %s -> %s at %g Hz, feedback from %s; linear %s; angular %s", ros::this_node::getName().c_str(),
             nh_.resolveName("cmd_vel").c_str(), nh_.resolveName("pioneer/cmd_vel").c_str(), config.rate,
             odom_topic_.c_str(), describe(pidGains(config.linear, config.derivative_filter_time)).c_str(),
             describe(pidGains(config.angular, config.derivative_filter_time)).c_str());
    publisher_ = nh_.advertise<geometry_msgs::Twist>("pioneer/cmd_vel", 10);
    // Callbacks may run from here on, in the network thread.
    if (own_clock && ros::Time::isSimTime()) {
      clock_subscriber_ =
          subscribeInline<rosgraph_msgs::Clock>(ros::NodeHandle("~"), kOwnClock, &PidControllerNode::onClock);
    } else {
      timer_ = nh_.createTimer(ros::Duration(1.0 / config.rate), &PidControllerNode::onTimer, this);
    }
    command_subscriber_ = subscribeInline<geometry_msgs::Twist>(nh_, "cmd_vel", &PidControllerNode::onCommand);
    odometry_subscriber_ = subscribeInline<nav_msgs::Odometry>(nh_, "pioneer/odom", &PidControllerNode::onOdometry);
  }

 private:
  template <typename Message>
  ros::Subscriber subscribeInline(ros::NodeHandle nh, const std::string& topic,
                                  void (PidControllerNode::*callback)(const typename Message::ConstPtr&)) {
    ros::SubscribeOptions options = ros::SubscribeOptions::create<Message>(
        topic, 10, [this, callback](const typename Message::ConstPtr& msg) { (this->*callback)(msg); },
        ros::VoidPtr(), &inline_queue_);
    // Odometry comes at the physics' rate, and the loop waits for it: no Nagle delay.
    options.transport_hints = ros::TransportHints().tcpNoDelay();
    return nh.subscribe(options);
  }

  void onClock(const rosgraph_msgs::Clock::ConstPtr& msg) {
    ros::Time::setNow(msg->clock);  // what roscpp's own /clock callback does
    const std::lock_guard<std::mutex> lock(mutex_);
    if (tick_.due(sinceEpoch(msg->clock))) update();
  }

  void onTimer(const ros::TimerEvent& /*event*/) {
    const std::lock_guard<std::mutex> lock(mutex_);
    update();
  }

  void onCommand(const geometry_msgs::Twist::ConstPtr& msg) {
    const std::lock_guard<std::mutex> lock(mutex_);
    try {
      controller_.setCommand(PlanarVelocity{msg->linear.x, msg->angular.z}, ros::Time::now().toSec());
    } catch (const std::invalid_argument& e) {
      ROS_WARN_THROTTLE(5.0, "%s: command ignored: %s", ros::this_node::getName().c_str(), e.what());
      return;
    }
    update();  // a command goes out when it comes, as the report's controller sends it
  }

  void onOdometry(const nav_msgs::Odometry::ConstPtr& msg) {
    const std::lock_guard<std::mutex> lock(mutex_);
    controller_.setMeasurement(planarVelocity(*msg), ros::Time::now().toSec());
  }

  void update() {  // with mutex_ held
    const std::optional<PlanarVelocity> output = controller_.update(ros::Time::now().toSec());
    if (controller_.mode() == ControllerMode::kOpenLoop) {
      ROS_WARN_THROTTLE(10.0, "%s: no odometry on %s: commands pass uncorrected", ros::this_node::getName().c_str(),
                        odom_topic_.c_str());
    }
    if (output) publisher_.publish(twistMessage(*output));
  }

  ros::NodeHandle nh_;
  std::mutex mutex_;  // callbacks run in the network thread, a ros::Timer's in ros::spin()'s
  InlineCallbackQueue inline_queue_;
  BodyVelocityController controller_;
  const std::string odom_topic_;
  PeriodicTick tick_;  // the update's schedule when the node reads /clock itself
  ros::Publisher publisher_;
  ros::Timer timer_;
  ros::Subscriber clock_subscriber_, command_subscriber_, odometry_subscriber_;
};

}  // namespace
}  // namespace pioneer_ros

int main(int argc, char** argv) {
  const bool own_clock = pioneer_ros::initWithOwnClock(argc, argv);
  ros::NodeHandle nh;  // the node runs while a NodeHandle exists: the first one starts it, the last one stops it
  pioneer_ros::ControllerConfig config;
  try {
    const pioneer_ros::ParamTree params = pioneer_ros::readParams();
    config = pioneer_ros::configFromParams(params.tree, params.ns);
  } catch (const pioneer_ros::BadParameter& e) {
    ROS_FATAL("%s: bad parameter: %s", ros::this_node::getName().c_str(), e.what());
    return 1;
  }
  pioneer_ros::PidControllerNode node(nh, config, own_clock);
  ros::spin();
  return 0;
}
