// effort_controllers/JointVelocityController: a PID (gains under <controller>/pid) turns the
// velocity on <controller>/command (std_msgs/Float64) into an effort on `joint`; it reports on
// <controller>/state (control_msgs/JointControllerState) every 10th update.
#include <std_msgs/Float64.h>

#include "controller_util.h"
#include "sim_control/controller_registry.h"
#include "sim_control/controller_params.h"

namespace sim_control {
namespace {

class JointVelocityController : public Controller {
 public:
  bool init(RobotHW& hw, ros::NodeHandle& /*root_nh*/, ros::NodeHandle& controller_nh, std::string& error) override {
    ros_params::Reader params(controller_nh);
    std::string name;
    if (!readJointName(params, &name)) return noProblems(params, error);
    joint_ = claim(hw, name, InterfaceType::Effort, error);
    if (!joint_ || !pid_.init(ros::NodeHandle(controller_nh, "pid"), error)) return false;
    state_.init(controller_nh);
    sub_ = controller_nh.subscribe("command", 1, &JointVelocityController::commandCallback, this);
    return true;
  }

  void starting(const ros::Time& /*time*/) override {
    command_.set(0.0);
    pid_.reset();
  }

  void update(const ros::Time& time, const ros::Duration& period) override {
    double target;
    command_.get(target);
    const double error = target - joint_->velocity;
    const double effort = controllers::clampEffort(*joint_, pid_.compute(error, period.toSec()));
    joint_->command = effort;
    // ros_controllers leaves process_value_dot (the acceleration) unset here; so do we.
    state_.publish(time, period, target, joint_->velocity, 0.0, error, effort, pid_);
  }

 private:
  void commandCallback(const std_msgs::Float64ConstPtr& msg) { command_.set(msg->data); }

  JointData* joint_ = nullptr;
  Pid pid_;
  controllers::CommandBuffer<double> command_;
  controllers::ControllerStatePublisher state_;
  ros::Subscriber sub_;  // last, so it is shut down before the members its callback uses go away
};

}  // namespace
SIM_CONTROL_REGISTER_CONTROLLER("effort_controllers/JointVelocityController", JointVelocityController)
}  // namespace sim_control
