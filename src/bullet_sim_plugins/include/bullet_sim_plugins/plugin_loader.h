#pragma once
// The plugins a model asks for: one per <plugin> element of the model (URDF <gazebo><plugin>,
// SDF <model><plugin>) and of its sensors, created through the registry by library name. What
// cannot be simulated is said once, never silently dropped: an unknown plugin library (named with
// the model) and a sensor without a plugin (nothing would be published for it).
#include <memory>
#include <string>
#include <vector>

#include "bullet_sim_plugins/model_plugin.h"

namespace bullet_sim {

struct LoadedPlugin {
  std::string label;  // "model 'm': libgazebo_ros_laser.so (sensor 'lidar')", for messages and timing
  std::unique_ptr<ModelPlugin> plugin;
};

// Throws DescriptionError (naming the plugin or sensor) for a block that cannot be honoured.
std::vector<LoadedPlugin> loadModelPlugins(PhysicsWorld& world, PhysicsModel& model, const std::string& spawn_namespace);

}  // namespace bullet_sim
