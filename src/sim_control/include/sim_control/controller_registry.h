#pragma once
// Controller types by their ros_controllers names ("effort_controllers/JointPositionController").
// Each controller's .cpp registers itself with SIM_CONTROL_REGISTER_CONTROLLER.
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "sim_control/controller.h"

namespace sim_control {

using ControllerFactory = std::function<std::unique_ptr<Controller>()>;

bool registerControllerType(const std::string& type, ControllerFactory factory);
// nullptr if the type is unknown.
std::unique_ptr<Controller> createController(const std::string& type);
std::vector<std::string> controllerTypes();  // sorted

}  // namespace sim_control

#define SIM_CONTROL_REGISTER_CONTROLLER(TYPE_STRING, CLASS)                                           \
  namespace {                                                                                         \
  const bool registered_##CLASS = ::sim_control::registerControllerType(                              \
      TYPE_STRING, [] { return std::unique_ptr<::sim_control::Controller>(std::make_unique<CLASS>()); }); \
  }
