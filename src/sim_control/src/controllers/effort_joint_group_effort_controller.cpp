// effort_controllers/JointGroupEffortController:
// The efforts on <controller>/command (std_msgs/Float64MultiArray, one per entry of
// `joints`) go straight to the joints; zero effort when it starts.
#include "forward_command_controller.h"
#include "sim_control/controller_registry.h"

namespace sim_control {
namespace {
using JointGroupEffortController = controllers::ForwardJointGroupCommandController<InterfaceType::Effort>;
}  // namespace
SIM_CONTROL_REGISTER_CONTROLLER("effort_controllers/JointGroupEffortController", JointGroupEffortController)
}  // namespace sim_control
