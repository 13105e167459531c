#pragma once
// What the simulator runs for a model besides its physics: sensors that publish, drives and
// controllers that command joints. Like a Gazebo ModelPlugin or SensorPlugin: one instance per
// <plugin> element, created by the library name in its filename (plugin_registry.h).
//
// Threading model -- read this before writing a plugin:
//  - The simulator node has ONE thread for physics, plugins and ROS callbacks. Its loop is
//      ROS callbacks -> beforeStep() of every plugin -> one physics step -> afterStep() of every
//      plugin -> /clock,
//    so a plugin never runs at the same time as the physics or another plugin, and needs no locks
//    for the model, the world or its own members.
//  - ROS subscriber and service callbacks of a plugin's own NodeHandle run on that same thread,
//    between steps (the node spins the global callback queue). Keep them short: store the message,
//    act on it in beforeStep(). That way a command always takes effect at a step boundary and the
//    same commands at the same sim times give the same run.
//  - Publish from beforeStep/afterStep with publish_thread::publish(publisher, message): the
//    message is handed to the process's publishing thread, so the loop does not wait on roscpp
//    (a plain publisher.publish() costs the loop 6-10 us; see publish_thread.h), and every
//    message of the process goes out in the order it was handed over.
//  - Don't spawn threads that touch the world: Bullet is not thread-safe. Heavy work that only
//    reads a copy of what it needs may run elsewhere, if its results come back through a queue
//    that beforeStep/afterStep drains.
//  - All times are sim time (`now`); never read the wall clock for behaviour, only for log throttling.
#include <ros/time.h>

#include <optional>
#include <string>

#include "bullet_sim_core/model_description.h"
#include "bullet_sim_core/physics_world.h"

namespace bullet_sim {

// What a plugin is created with.
struct PluginContext {
  PhysicsWorld& world;
  PhysicsModel& model;
  const PluginDescription& plugin;          // its <plugin> element: filename, name, parameters
  const SensorDescription* sensor;          // the <sensor> a sensor plugin sits in; nullptr for model plugins
  std::string spawn_namespace;              // the spawn request's robot_namespace ("" for world files)
  // "model 'm': libgazebo_ros_laser.so" -- how messages about this plugin start.
  std::string label() const { return "model '" + model.name() + "': " + pluginLibraryName(plugin.filename); }
};

// A sensor's output as a client draws it from its topic (the studio's laser rays, a camera's view):
// /gazebo/scene_info lists one marker per sensor plugin that says what it publishes.
struct SensorTopic {
  std::string kind;   // "laser" or "camera"
  std::string topic;  // the resolved name of its LaserScan or Image topic
  std::string link;   // the link the sensor sits on
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();  // the sensor in the link frame
  double range = 0.0;  // m: a laser's range max, a camera's far clip
};

class ModelPlugin {
 public:
  virtual ~ModelPlugin() = default;
  // Before each physics step: read commands, apply efforts. `dt` is the step about to be taken.
  virtual void beforeStep(const ros::Time& /*now*/, double /*dt*/) {}
  // After each physics step: sense and publish. `now` is the time after the step.
  virtual void afterStep(const ros::Time& /*now*/) {}
  // reset_simulation / reset_world: forget state that refers to the old time.
  virtual void reset() {}
  // A sensor plugin's output, for clients that draw it; other plugins have none.
  virtual std::optional<SensorTopic> sensorTopic() const { return std::nullopt; }
};

}  // namespace bullet_sim
