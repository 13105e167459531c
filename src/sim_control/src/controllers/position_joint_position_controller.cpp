// position_controllers/JointPositionController:
// The position on <controller>/command (std_msgs/Float64) goes straight to `joint`;
// it holds the joint's current position when it starts.
#include "forward_command_controller.h"
#include "sim_control/controller_registry.h"

namespace sim_control {
namespace {
using PositionJointPositionController = controllers::ForwardCommandController<InterfaceType::Position>;
}  // namespace
SIM_CONTROL_REGISTER_CONTROLLER("position_controllers/JointPositionController", PositionJointPositionController)
}  // namespace sim_control
