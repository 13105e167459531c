#pragma once
// The hardware side that controllers see, like ros_control's hardware_interface: named joints,
// their state, and one command slot per joint for the interface its transmission exposes.
// The simulator fills the state before each control update and applies the commands after;
// controllers never see the simulator.
#include <cmath>
#include <limits>
#include <map>
#include <string>
#include <vector>

namespace sim_control {

enum class InterfaceType { Effort, Position, Velocity };

// "hardware_interface::EffortJointInterface" etc.: the names ros_control reports.
std::string interfaceName(InterfaceType type);
// Accepts both "EffortJointInterface" and "hardware_interface/EffortJointInterface" (and "::").
bool parseInterfaceName(const std::string& text, InterfaceType& type);

struct JointLimits {
  bool has_position_limits = false;  // revolute and prismatic joints
  bool continuous = false;           // continuous joints: angles wrap
  double lower = -std::numeric_limits<double>::infinity();
  double upper = std::numeric_limits<double>::infinity();
  double effort = std::numeric_limits<double>::infinity();    // N or N m
  double velocity = std::numeric_limits<double>::infinity();  // rad/s or m/s
};

struct JointData {
  std::string name;
  InterfaceType interface = InterfaceType::Effort;  // what the joint's transmission exposes
  JointLimits limits;
  double position = 0.0;  // state, joint space (after the transmission's reduction)
  double velocity = 0.0;
  double effort = 0.0;
  // Command in the interface's unit. The hardware starts it at "hold": zero effort, the
  // joint's position at start-up, or zero velocity.
  double command = 0.0;
  // Whether a running controller claims the joint (kept by the controller manager; the
  // hardware leaves the others undriven). A flag, so the simulator need not look names up every step.
  bool driven = false;
};

class RobotHW {
 public:
  JointData& addJoint(const std::string& name, InterfaceType interface, const JointLimits& limits);
  // nullptr if there is no such joint.
  JointData* joint(const std::string& name);
  const JointData* joint(const std::string& name) const;
  std::vector<std::string> jointNames() const;  // in the order they were added
  std::vector<JointData>& joints() { return joints_; }

 private:
  std::vector<JointData> joints_;  // reserved up front by the simulator so pointers stay valid
};

}  // namespace sim_control
