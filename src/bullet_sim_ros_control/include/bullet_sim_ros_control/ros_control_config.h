#pragma once
// What libgazebo_ros_control.so reads from a model: its <plugin> parameters and the joints the
// URDF's transmissions drive, with the interface each is commanded through.
#include <string>
#include <vector>

#include "bullet_sim_core/model_description.h"
#include "sim_control/robot_hw.h"

namespace bullet_sim {

struct RosControlConfig {
  std::string robot_namespace;  // <robotNamespace>, default the model name
  double control_period = 0.0;  // <controlPeriod> in s; 0: every physics step
  std::string robot_param = "robot_description";  // <robotParam>, kept for the record
};

// Throws DescriptionError naming the element for a bad value (see sdf_element.h).
RosControlConfig parseRosControlConfig(const PluginDescription& plugin, const std::string& model_name);

struct TransmissionJoint {
  std::string joint;
  sim_control::InterfaceType interface = sim_control::InterfaceType::Effort;
};

// The joints every SimpleTransmission of the URDF drives, and through which interface. Throws
// DescriptionError for another transmission type or an unknown interface.
std::vector<TransmissionJoint> transmissionJoints(const ModelDescription& model);

}  // namespace bullet_sim
