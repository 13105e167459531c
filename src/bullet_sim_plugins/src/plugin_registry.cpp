#include "bullet_sim_plugins/plugin_registry.h"

#include <map>

namespace bullet_sim {
namespace {
std::map<std::string, PluginFactory>& registry() {
  static std::map<std::string, PluginFactory> factories;  // filled before main by static registrars
  return factories;
}
}  // namespace

bool registerPlugin(const std::string& library, PluginFactory factory) {
  return registry().emplace(library, std::move(factory)).second;
}

const PluginFactory* findPlugin(const std::string& filename) {
  const auto it = registry().find(pluginLibraryName(filename));
  return it == registry().end() ? nullptr : &it->second;
}

std::vector<std::string> registeredPlugins() {
  std::vector<std::string> names;
  for (const auto& [name, factory] : registry()) names.push_back(name);
  return names;
}

}  // namespace bullet_sim
