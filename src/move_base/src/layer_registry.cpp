#include "move_base/layer_registry.h"

#include <map>

namespace move_base {
namespace {
std::map<std::string, LayerFactory>& registry() {
  static std::map<std::string, LayerFactory> factories;  // filled before main by static registrars
  return factories;
}
}  // namespace

bool registerLayer(const std::string& type, LayerFactory factory) {
  return registry().emplace(type, std::move(factory)).second;
}

std::unique_ptr<CostmapLayer> makeLayer(const std::string& type) {
  const auto it = registry().find(type);
  return it == registry().end() ? nullptr : it->second();
}

std::vector<std::string> layerTypes() {
  std::vector<std::string> types;
  for (const auto& [type, factory] : registry()) types.push_back(type);
  return types;
}

}  // namespace move_base
