#pragma once
// A controller, in ros_control's shape: init from parameters, then starting / update / stopping
// driven by the controller manager in the simulator's loop, in sim time.
#include <ros/node_handle.h>
#include <ros/time.h>

#include <string>
#include <vector>

#include "sim_control/robot_hw.h"

namespace sim_control {

struct ClaimedResources {
  InterfaceType interface;
  std::vector<std::string> joints;
};

class Controller {
 public:
  virtual ~Controller() = default;

  // Reads the controller's parameters (controller_nh is <robot ns>/<controller name>) and
  // looks up its joints. On failure returns false and says why in `error`, naming the
  // parameter and what was expected, e.g. "joint1_position_controller/pid/p: expected a number".
  virtual bool init(RobotHW& hw, ros::NodeHandle& root_nh, ros::NodeHandle& controller_nh, std::string& error) = 0;
  virtual void starting(const ros::Time& /*time*/) {}
  virtual void update(const ros::Time& time, const ros::Duration& period) = 0;
  virtual void stopping(const ros::Time& /*time*/) {}

  // The joints whose command slots this controller writes, by interface (read-only
  // controllers such as JointStateController claim nothing).
  const std::vector<ClaimedResources>& claimedResources() const { return claimed_; }

 protected:
  // Looks up `joint` for writing through `interface`; on failure fills `error` the way
  // ros_control says it: "Could not find joint 'j' in 'hardware_interface::EffortJointInterface'".
  JointData* claim(RobotHW& hw, const std::string& joint, InterfaceType interface, std::string& error);

 private:
  std::vector<ClaimedResources> claimed_;
};

}  // namespace sim_control
