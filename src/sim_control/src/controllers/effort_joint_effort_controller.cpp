// effort_controllers/JointEffortController:
// The effort (N m or N) on <controller>/command (std_msgs/Float64) goes straight to
// `joint`; zero effort when it starts.
#include "forward_command_controller.h"
#include "sim_control/controller_registry.h"

namespace sim_control {
namespace {
using JointEffortController = controllers::ForwardCommandController<InterfaceType::Effort>;
}  // namespace
SIM_CONTROL_REGISTER_CONTROLLER("effort_controllers/JointEffortController", JointEffortController)
}  // namespace sim_control
