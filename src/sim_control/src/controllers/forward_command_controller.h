#pragma once
// ros_controllers' forward_command_controller: the command received on <controller>/command is
// written unchanged to the joint(s) through one interface. The effort_, position_ and
// velocity_controllers Joint(Group)*Controller types are these templates with a fixed interface.
#include <std_msgs/Float64.h>
#include <std_msgs/Float64MultiArray.h>

#include <string>
#include <vector>

#include "controller_util.h"
#include "sim_control/controller.h"
#include "sim_control/controller_params.h"

namespace sim_control {
namespace controllers {

// What a joint is told when the controller starts: keep the current position, or zero effort /
// velocity (ros_controllers' starting() specialisations).
inline double holdCommand(InterfaceType interface, const JointData& joint) {
  return interface == InterfaceType::Position ? joint.position : 0.0;
}

template <InterfaceType Interface>
class ForwardCommandController : public Controller {
 public:
  bool init(RobotHW& hw, ros::NodeHandle& /*root_nh*/, ros::NodeHandle& controller_nh, std::string& error) override {
    ros_params::Reader params(controller_nh);
    std::string name;
    if (!readJointName(params, &name)) return noProblems(params, error);
    joint_ = claim(hw, name, Interface, error);
    if (!joint_) return false;
    sub_ = controller_nh.subscribe("command", 1, &ForwardCommandController::commandCallback, this);
    return true;
  }
  void starting(const ros::Time& /*time*/) override { command_.set(holdCommand(Interface, *joint_)); }
  void update(const ros::Time& /*time*/, const ros::Duration& /*period*/) override { command_.get(joint_->command); }

 private:
  void commandCallback(const std_msgs::Float64ConstPtr& msg) { command_.set(msg->data); }

  JointData* joint_ = nullptr;
  CommandBuffer<double> command_;
  ros::Subscriber sub_;  // last, so it is shut down before the members its callback uses go away
};

template <InterfaceType Interface>
class ForwardJointGroupCommandController : public Controller {
 public:
  bool init(RobotHW& hw, ros::NodeHandle& /*root_nh*/, ros::NodeHandle& controller_nh, std::string& error) override {
    ros_params::Reader params(controller_nh);
    if (!readJointNames(params, &names_)) return noProblems(params, error);
    for (const auto& name : names_) {
      JointData* joint = claim(hw, name, Interface, error);
      if (!joint) return false;
      joints_.push_back(joint);
    }
    command_.set(std::vector<double>(joints_.size(), 0.0));
    topic_ = controller_nh.resolveName("command");
    sub_ = controller_nh.subscribe("command", 1, &ForwardJointGroupCommandController::commandCallback, this);
    return true;
  }
  void starting(const ros::Time& /*time*/) override {
    std::vector<double> hold;
    for (const JointData* joint : joints_) hold.push_back(holdCommand(Interface, *joint));
    command_.set(hold);
  }
  void update(const ros::Time& /*time*/, const ros::Duration& /*period*/) override {
    command_.get(current_);
    for (std::size_t k = 0; k < joints_.size(); ++k) joints_[k]->command = current_[k];
  }

 private:
  void commandCallback(const std_msgs::Float64MultiArrayConstPtr& msg) {
    if (commandSizeOk(msg->data.size(), names_, topic_, throttle_)) command_.set(msg->data);
  }

  std::vector<std::string> names_;
  std::vector<JointData*> joints_;
  std::vector<double> current_;  // update()'s copy of the command
  CommandBuffer<std::vector<double>> command_;
  std::string topic_;
  WallThrottle throttle_{1.0};
  ros::Subscriber sub_;  // last, so it is shut down before the members its callback uses go away
};

}  // namespace controllers
}  // namespace sim_control
