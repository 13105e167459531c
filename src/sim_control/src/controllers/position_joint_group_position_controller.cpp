// position_controllers/JointGroupPositionController:
// The positions on <controller>/command (std_msgs/Float64MultiArray, one per entry
// of `joints`) go straight to the joints; they hold their current positions when it starts.
#include "forward_command_controller.h"
#include "sim_control/controller_registry.h"

namespace sim_control {
namespace {
using PositionJointGroupPositionController = controllers::ForwardJointGroupCommandController<InterfaceType::Position>;
}  // namespace
SIM_CONTROL_REGISTER_CONTROLLER("position_controllers/JointGroupPositionController", PositionJointGroupPositionController)
}  // namespace sim_control
