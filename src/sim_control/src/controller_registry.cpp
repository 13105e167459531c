#include "sim_control/controller_registry.h"

#include <map>

namespace sim_control {
namespace {
std::map<std::string, ControllerFactory>& registry() {
  static std::map<std::string, ControllerFactory> factories;  // built before main by static registrars
  return factories;
}
}  // namespace

bool registerControllerType(const std::string& type, ControllerFactory factory) {
  return registry().emplace(type, std::move(factory)).second;
}

std::unique_ptr<Controller> createController(const std::string& type) {
  auto it = registry().find(type);
  return it == registry().end() ? nullptr : it->second();
}

std::vector<std::string> controllerTypes() {
  std::vector<std::string> types;
  for (const auto& [type, factory] : registry()) types.push_back(type);
  return types;
}

}  // namespace sim_control
