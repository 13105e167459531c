// effort_controllers/JointGroupPositionController: one PID per entry of `joints` (gains under
// <controller>/<joint>/pid) turns the positions on <controller>/command
// (std_msgs/Float64MultiArray, one per joint) into efforts. No state topic, as in ros_controllers.
#include <std_msgs/Float64MultiArray.h>

#include "controller_util.h"
#include "sim_control/controller_registry.h"
#include "sim_control/controller_params.h"

namespace sim_control {
namespace {

using controllers::clampEffort;
using controllers::enforcePositionLimits;
using controllers::positionError;

class JointGroupPositionController : public Controller {
 public:
  bool init(RobotHW& hw, ros::NodeHandle& /*root_nh*/, ros::NodeHandle& controller_nh, std::string& error) override {
    ros_params::Reader params(controller_nh);
    if (!readJointNames(params, &names_)) return noProblems(params, error);
    pids_.resize(names_.size());
    for (std::size_t k = 0; k < names_.size(); ++k) {
      JointData* joint = claim(hw, names_[k], InterfaceType::Effort, error);
      if (!joint || !pids_[k].init(ros::NodeHandle(controller_nh, names_[k] + "/pid"), error)) return false;
      joints_.push_back(joint);
    }
    command_.set(std::vector<double>(joints_.size(), 0.0));
    topic_ = controller_nh.resolveName("command");
    sub_ = controller_nh.subscribe("command", 1, &JointGroupPositionController::commandCallback, this);
    return true;
  }

  void starting(const ros::Time& /*time*/) override {
    std::vector<double> hold;
    for (std::size_t k = 0; k < joints_.size(); ++k) {
      hold.push_back(enforcePositionLimits(*joints_[k], joints_[k]->position));
      pids_[k].reset();
    }
    command_.set(hold);
  }

  void update(const ros::Time& /*time*/, const ros::Duration& period) override {
    command_.get(targets_);
    for (std::size_t k = 0; k < joints_.size(); ++k) {
      JointData& joint = *joints_[k];
      const double error = positionError(joint, enforcePositionLimits(joint, targets_[k]));
      joint.command = clampEffort(joint, pids_[k].compute(error, period.toSec()));
    }
  }

 private:
  void commandCallback(const std_msgs::Float64MultiArrayConstPtr& msg) {
    if (controllers::commandSizeOk(msg->data.size(), names_, topic_, throttle_)) command_.set(msg->data);
  }

  std::vector<std::string> names_;
  std::vector<JointData*> joints_;
  std::vector<Pid> pids_;
  std::vector<double> targets_;  // update()'s copy of the command
  controllers::CommandBuffer<std::vector<double>> command_;
  std::string topic_;
  controllers::WallThrottle throttle_{1.0};
  ros::Subscriber sub_;  // last, so it is shut down before the members its callback uses go away
};

}  // namespace
SIM_CONTROL_REGISTER_CONTROLLER("effort_controllers/JointGroupPositionController", JointGroupPositionController)
}  // namespace sim_control
