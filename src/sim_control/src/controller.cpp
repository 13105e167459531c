#include "sim_control/controller.h"

namespace sim_control {

JointData* Controller::claim(RobotHW& hw, const std::string& joint, InterfaceType interface, std::string& error) {
  JointData* data = hw.joint(joint);
  if (!data || data->interface != interface) {
    error = "Could not find joint '" + joint + "' in '" + interfaceName(interface) + "'";
    if (data) error += " (its transmission exposes " + interfaceName(data->interface) + ")";
    return nullptr;
  }
  for (auto& c : claimed_) {
    if (c.interface == interface) {
      c.joints.push_back(joint);
      return data;
    }
  }
  claimed_.push_back({interface, {joint}});
  return data;
}

}  // namespace sim_control
