#include "sim_control/robot_hw.h"

namespace sim_control {

std::string interfaceName(InterfaceType type) {
  switch (type) {
    case InterfaceType::Effort: return "hardware_interface::EffortJointInterface";
    case InterfaceType::Position: return "hardware_interface::PositionJointInterface";
    case InterfaceType::Velocity: return "hardware_interface::VelocityJointInterface";
  }
  return "";
}

bool parseInterfaceName(const std::string& text, InterfaceType& type) {
  std::string name = text;
  for (const std::string prefix : {"hardware_interface/", "hardware_interface::"})
    if (name.rfind(prefix, 0) == 0) name = name.substr(prefix.size());
  if (name == "EffortJointInterface") type = InterfaceType::Effort;
  else if (name == "PositionJointInterface") type = InterfaceType::Position;
  else if (name == "VelocityJointInterface") type = InterfaceType::Velocity;
  else return false;
  return true;
}

JointData& RobotHW::addJoint(const std::string& name, InterfaceType interface, const JointLimits& limits) {
  JointData data;
  data.name = name;
  data.interface = interface;
  data.limits = limits;
  joints_.push_back(data);
  return joints_.back();
}

JointData* RobotHW::joint(const std::string& name) {
  for (auto& j : joints_)
    if (j.name == name) return &j;
  return nullptr;
}

const JointData* RobotHW::joint(const std::string& name) const {
  for (const auto& j : joints_)
    if (j.name == name) return &j;
  return nullptr;
}

std::vector<std::string> RobotHW::jointNames() const {
  std::vector<std::string> names;
  for (const auto& j : joints_) names.push_back(j.name);
  return names;
}

}  // namespace sim_control
