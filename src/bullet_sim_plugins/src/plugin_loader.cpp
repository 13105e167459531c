#include "bullet_sim_plugins/plugin_loader.h"

#include <ros/console.h>

#include <set>

#include "bullet_sim_core/description_error.h"
#include "bullet_sim_plugins/plugin_registry.h"

namespace bullet_sim {
namespace {

std::string knownPlugins() {
  std::string list;
  for (const std::string& name : registeredPlugins()) list += (list.empty() ? "" : ", ") + name;
  return list;
}

}  // namespace

std::vector<LoadedPlugin> loadModelPlugins(PhysicsWorld& world, PhysicsModel& model, const std::string& spawn_namespace) {
  const ModelDescription& description = model.description();
  std::vector<LoadedPlugin> plugins;
  std::set<std::string> told;  // unknown libraries already reported for this model

  auto load = [&](const PluginDescription& plugin, const SensorDescription* sensor) {
    const PluginFactory* factory = findPlugin(plugin.filename);
    if (!factory) {
      const std::string library = pluginLibraryName(plugin.filename);
      if (told.insert(library).second)
        ROS_WARN_STREAM("model '" << model.name() << "': unknown plugin '" << library << "' ("
                                  << description.source << ": " << plugin.element.path()
                                  << "); bullet_sim does not simulate it. Known plugins: " << knownPlugins());
      return;
    }
    const PluginContext context{world, model, plugin, sensor, spawn_namespace};
    plugins.push_back({context.label() + (sensor ? " (sensor '" + sensor->name + "')" : ""), (*factory)(context)});
  };

  for (const SensorDescription& sensor : description.sensors) {
    if (!model.hasLink(sensor.link))
      sensor.element.fail("expected the name of a link of model '" + model.name() + "', got '" + sensor.link + "'");
    if (sensor.plugins.empty())
      ROS_WARN_STREAM("model '" << model.name() << "': " << sensor.type << " sensor '" << sensor.name
                                << "' has no plugin, so nothing is published for it");
    for (const PluginDescription& plugin : sensor.plugins) load(plugin, &sensor);
  }
  for (const PluginDescription& plugin : description.plugins) load(plugin, nullptr);
  return plugins;
}

}  // namespace bullet_sim
