#pragma once
// What the simulator runs for a model besides its physics: sensors that publish, drives and
// controllers that command joints. Like a Gazebo ModelPlugin, one instance per model.
#include <ros/time.h>

namespace bullet_sim {

class ModelPlugin {
 public:
  virtual ~ModelPlugin() = default;
  // Before each physics step: read commands, apply efforts.
  virtual void beforeStep(const ros::Time& /*now*/, double /*dt*/) {}
  // After each physics step: sense and publish. `now` is the time after the step.
  virtual void afterStep(const ros::Time& /*now*/) {}
  // reset_simulation / reset_world: forget state that refers to the old time.
  virtual void reset() {}
};

}  // namespace bullet_sim
