// velocity_controllers/JointGroupVelocityController:
// The velocities on <controller>/command (std_msgs/Float64MultiArray, one per entry
// of `joints`) go straight to the joints; zero velocity when it starts.
#include "forward_command_controller.h"
#include "sim_control/controller_registry.h"

namespace sim_control {
namespace {
using JointGroupVelocityController = controllers::ForwardJointGroupCommandController<InterfaceType::Velocity>;
}  // namespace
SIM_CONTROL_REGISTER_CONTROLLER("velocity_controllers/JointGroupVelocityController", JointGroupVelocityController)
}  // namespace sim_control
