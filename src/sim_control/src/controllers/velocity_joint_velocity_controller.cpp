// velocity_controllers/JointVelocityController:
// The velocity on <controller>/command (std_msgs/Float64) goes straight to `joint`;
// zero velocity when it starts.
#include "forward_command_controller.h"
#include "sim_control/controller_registry.h"

namespace sim_control {
namespace {
using JointVelocityController = controllers::ForwardCommandController<InterfaceType::Velocity>;
}  // namespace
SIM_CONTROL_REGISTER_CONTROLLER("velocity_controllers/JointVelocityController", JointVelocityController)
}  // namespace sim_control
