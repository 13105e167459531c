#pragma once
// The simulator node's heart: one thread runs the fixed-step loop
//   ROS callbacks -> plugins apply commands -> physics step -> plugins sense/publish -> /clock,
// paced to real_time_factor. Doing callbacks between steps keeps runs deterministic: a
// command always takes effect at a step boundary.
#include <ros/ros.h>

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "bullet_sim/loop_timing.h"
#include "bullet_sim_core/physics_world.h"
#include "bullet_sim_core/resource_resolver.h"
#include "bullet_sim_plugins/plugin_loader.h"

namespace bullet_sim {

class GazeboRosApi;
class JointCommandTopic;
class PoseInfo;
class SceneInfo;
class SceneMarkers;

struct SimulatorOptions {
  bool paused = false;
  double pub_clock_frequency = 0.0;  // Hz of sim time; 0: every step (Gazebo's default)
  bool timing = false;               // time the loop's parts and print where the time went at exit
};

class Simulator {
 public:
  Simulator(const WorldDescription& world, const ResourceResolver& resolver, const SimulatorOptions& options);
  ~Simulator();

  void run();         // until ROS shuts down
  void runSteps(int n);  // n steps now, ignoring pause and pacing, then /clock (/gazebo/step_world)

  // Spawning goes through here so that sensors and plugins come with the model. Throws
  // DescriptionError naming the problem; nothing is added then. Both republish /gazebo/scene_info;
  // remove() drops the model's /gazebo/joint_cmd commands.
  void spawn(const ModelDescription& model, const Eigen::Isometry3d& pose, const std::string& robot_namespace);
  bool remove(const std::string& name);

  PhysicsWorld& physics() { return physics_; }
  const ResourceResolver& resolver() const { return resolver_; }
  ros::Time now() const { return ros::Time(physics_.time()); }
  bool paused() const { return paused_; }
  void setPaused(bool paused);
  void resetWorld();       // models to their initial state, time kept
  void resetSimulation();  // and time back to zero
  const std::string& worldName() const { return world_name_; }

  // Called before each step; the API applies timed joint efforts and body wrenches here.
  std::function<void(const ros::Time&)> before_step;

 private:
  void stepOnce();
  void publishClock(bool force);
  void publishSceneIfChanged();

  std::string world_name_;
  ResourceResolver resolver_;
  PhysicsWorld physics_;
  bool paused_;
  SimulatorOptions options_;
  std::map<std::string, std::vector<LoadedPlugin>> plugins_;  // by model name
  LoopTiming timing_;
  ros::NodeHandle node_;
  ros::Publisher clock_publisher_;
  ros::Time last_clock_;
  ros::WallTime last_clock_wall_;
  std::unique_ptr<GazeboRosApi> api_;
  std::unique_ptr<SceneMarkers> scene_markers_;
  // What a client like sim_studio reads and sends (docs/SIMULATOR.md, "For a client: ...").
  std::unique_ptr<PoseInfo> pose_info_;
  std::unique_ptr<SceneInfo> scene_info_;
  std::unique_ptr<JointCommandTopic> joint_commands_;
  bool scene_changed_ = true;  // models came or went since scene_info was last published
  // Pacing: wall time and sim time at the last (re)start of real-time tracking.
  ros::WallTime pace_wall_start_;
  double pace_sim_start_ = 0.0;
};

}  // namespace bullet_sim
