#pragma once
// Plugins by the library name Gazebo would load ("libgazebo_ros_laser.so"), as ros_control's
// controllers are found by type name. Each plugin's .cpp registers itself with one line:
//
//   BULLET_SIM_REGISTER_PLUGIN("libgazebo_ros_laser.so", LaserPlugin)
//
// where LaserPlugin derives from ModelPlugin and is constructed from a `const PluginContext&`.
// A constructor that cannot honour its <plugin> block throws DescriptionError naming it.
//
// Registration happens when the library holding the plugin is loaded. A plugin library the node
// does not call into by name must be linked with --no-as-needed (see bullet_sim's CMakeLists.txt).
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "bullet_sim_plugins/model_plugin.h"

namespace bullet_sim {

using PluginFactory = std::function<std::unique_ptr<ModelPlugin>(const PluginContext&)>;

// False (and nothing changes) if `library` is registered already.
bool registerPlugin(const std::string& library, PluginFactory factory);
// The factory for a <plugin filename>: a folder in front of the library name is allowed, as in
// Gazebo. nullptr if no plugin is registered under that name.
const PluginFactory* findPlugin(const std::string& filename);
std::vector<std::string> registeredPlugins();  // sorted library names

}  // namespace bullet_sim

#define BULLET_SIM_PLUGIN_CONCAT_(a, b) a##b
#define BULLET_SIM_PLUGIN_VARIABLE_(line) BULLET_SIM_PLUGIN_CONCAT_(registered_plugin_, line)
#define BULLET_SIM_REGISTER_PLUGIN(LIBRARY, CLASS)                                                        \
  namespace {                                                                                             \
  const bool BULLET_SIM_PLUGIN_VARIABLE_(__LINE__) = ::bullet_sim::registerPlugin(                        \
      LIBRARY, [](const ::bullet_sim::PluginContext& context) -> std::unique_ptr<::bullet_sim::ModelPlugin> { \
        return std::make_unique<CLASS>(context);                                                          \
      });                                                                                                 \
  }
