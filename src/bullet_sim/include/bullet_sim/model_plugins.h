#pragma once
// Which plugins a model gets: one place that reads a model's <gazebo> blocks and creates the
// sensors and plugins they name (libgazebo_ros_laser.so, ...). Unknown plugin files are
// reported once and skipped, as Gazebo does when a plugin library is missing.
#include <memory>
#include <string>
#include <vector>

#include "bullet_sim/model_plugin.h"
#include "bullet_sim/physics_world.h"

namespace bullet_sim {

// Throws DescriptionError (naming the sensor or plugin) for a block that cannot be honoured.
std::vector<std::unique_ptr<ModelPlugin>> makeModelPlugins(PhysicsWorld& world, PhysicsModel& model,
                                                           const std::string& robot_namespace);

}  // namespace bullet_sim
