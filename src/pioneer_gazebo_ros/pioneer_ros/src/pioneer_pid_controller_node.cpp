// pioneer_pid_controller, the report's: velocity commands on cmd_vel (from move_base or a
// teleop) in, commands for the drive plugin on pioneer/cmd_vel out, with a PID on the linear and
// angular velocity errors against the odometry on pioneer/odom (the drive plugin's). Names are
// relative, so remap them (pioneer_bringup.launch does). The algorithm and its timeouts:
// pioneer_ros/body_velocity_controller.h.
//
// Parameters: the tree of pioneer_controller_params.yaml (controller_gains/body/{linear,angular}/
// {p,i,d,i_clamp}, feedforward, limits, derivative_filter_time, rate, cmd_timeout, odom_timeout),
// read from the node's private namespace, or, when that has no controller_gains, from
// /pioneer_ros, where the report's bring-up (`rosparam load pioneer_controller_params.yaml
// pioneer_ros`) puts them. A bad parameter stops the node with exit status 1.
#include <geometry_msgs/Twist.h>
#include <nav_msgs/Odometry.h>
#include <ros/ros.h>
#include <xmlrpcpp/XmlRpcValue.h>

#include <optional>
#include <stdexcept>
#include <string>

#include "pioneer_ros/body_velocity_controller.h"
#include "pioneer_ros/controller_params.h"
#include "pioneer_ros/velocity_messages.h"

namespace pioneer_ros {
namespace {

const char* const kReportNamespace = "/pioneer_ros";

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

class PidControllerNode {
 public:
  PidControllerNode(ros::NodeHandle& nh, const ControllerConfig& config)
      : controller_(config), odom_topic_(nh.resolveName("pioneer/odom")) {
    publisher_ = nh.advertise<geometry_msgs::Twist>("pioneer/cmd_vel", 10);
    // Odometry comes at the physics' rate (2200 messages a second at 22x real time): no Nagle delay.
    const ros::TransportHints hints = ros::TransportHints().tcpNoDelay();
    command_subscriber_ = nh.subscribe("cmd_vel", 10, &PidControllerNode::onCommand, this, hints);
    odometry_subscriber_ = nh.subscribe("pioneer/odom", 10, &PidControllerNode::onOdometry, this, hints);
    timer_ = nh.createTimer(ros::Duration(1.0 / config.rate), &PidControllerNode::onTimer, this);
    ROS_INFO("%s: %s -> %s at %g Hz, feedback from %s; linear %s; angular %s", ros::this_node::getName().c_str(),
             command_subscriber_.getTopic().c_str(), publisher_.getTopic().c_str(), config.rate,
             odom_topic_.c_str(), describe(pidGains(config.linear, config.derivative_filter_time)).c_str(),
             describe(pidGains(config.angular, config.derivative_filter_time)).c_str());
  }

 private:
  void onCommand(const geometry_msgs::Twist::ConstPtr& msg) {
    try {
      controller_.setCommand(PlanarVelocity{msg->linear.x, msg->angular.z}, ros::Time::now().toSec());
    } catch (const std::invalid_argument& e) {
      ROS_WARN_THROTTLE(5.0, "%s: command ignored: %s", ros::this_node::getName().c_str(), e.what());
    }
  }

  void onOdometry(const nav_msgs::Odometry::ConstPtr& msg) {
    controller_.setMeasurement(planarVelocity(*msg), ros::Time::now().toSec());
  }

  void onTimer(const ros::TimerEvent&) {
    const std::optional<PlanarVelocity> output = controller_.update(ros::Time::now().toSec());
    if (controller_.mode() == ControllerMode::kOpenLoop) {
      ROS_WARN_THROTTLE(10.0, "%s: no odometry on %s: commands pass uncorrected", ros::this_node::getName().c_str(),
                        odom_topic_.c_str());
    }
    if (output) publisher_.publish(twistMessage(*output));
  }

  BodyVelocityController controller_;
  const std::string odom_topic_;
  ros::Publisher publisher_;
  ros::Subscriber command_subscriber_, odometry_subscriber_;
  ros::Timer timer_;
};

}  // namespace
}  // namespace pioneer_ros

int main(int argc, char** argv) {
  ros::init(argc, argv, "pioneer_pid_controller");
  ros::NodeHandle nh;
  pioneer_ros::ControllerConfig config;
  try {
    const pioneer_ros::ParamTree params = pioneer_ros::readParams();
    config = pioneer_ros::configFromParams(params.tree, params.ns);
  } catch (const pioneer_ros::BadParameter& e) {
    ROS_FATAL("%s: bad parameter: %s", ros::this_node::getName().c_str(), e.what());
    return 1;
  }
  pioneer_ros::PidControllerNode node(nh, config);
  ros::spin();
  return 0;
}
