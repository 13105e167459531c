#pragma once
// pioneer_pid_controller's configuration from the parameter server's tree (what
// ros::param::get returns for the namespace pioneer_controller_params.yaml was loaded into).
// Needs no master: the node fetches the tree, this reads it with ros_params::Reader.
#include <xmlrpcpp/XmlRpcValue.h>

#include <stdexcept>
#include <string>

#include "pioneer_ros/body_velocity_controller.h"

namespace pioneer_ros {

// A parameter of the wrong type or out of range; what() names its full path and what was
// expected: "/pioneer_pid_controller/controller_gains/body/linear/p: expected a number, got the
// string 'fast'".
class BadParameter : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

// The configuration in `tree`, laid out as pioneer_controller_params.yaml; `ns` is where the
// tree was read from (for the messages). Absent parameters keep ControllerConfig's defaults;
// anything present must be a number (int or double, not NaN) or, above the leaves, a
// dictionary. Unknown keys are ignored. Throws BadParameter (every problem, one a line).
ControllerConfig configFromParams(const XmlRpc::XmlRpcValue& tree, const std::string& ns);

}  // namespace pioneer_ros
