#include "bullet_sim/simulator.h"

#include <ros/callback_queue.h>
#include <rosgraph_msgs/Clock.h>

#include <cstdio>

#include "bullet_sim/gazebo_ros_api.h"
#include "bullet_sim/joint_command_topic.h"
#include "bullet_sim/pose_info.h"
#include "bullet_sim/scene_info.h"
#include "bullet_sim/scene_markers.h"
#include "bullet_sim_core/description_error.h"
#include "bullet_sim_plugins/plugin_loader.h"
#include "publish_thread/publish_thread.h"

namespace bullet_sim {
namespace {
// The wall-clock floor between /clock messages, whatever pub_clock_frequency asks: every node that
// uses sim time wakes for each one, so at 20x gazebo_ros' 100 Hz of sim time (2000 a second) would
// cost each of them more than it gains. About 1 kHz is what real time at 1 ms steps gives them; just
// under 1 ms, so that at real time every step still gets its message.
const ros::WallDuration kMinClockWallPeriod(0.0009);
// While paused, /clock repeats the frozen time so that late starters learn it.
const ros::WallDuration kPausedClockPeriod(0.1);
// When running ahead of the target speed, the loop sleeps only once it is this far ahead: at 10x and
// beyond, a sleep per step (tens of microseconds each) would cost more in thread switches than the
// step itself. At real time each step still ends in a sleep.
const double kMinPaceSleep = 0.0005;
}  // namespace

Simulator::Simulator(const WorldDescription& world, const ResourceResolver& resolver, const SimulatorOptions& options)
    : world_name_(world.name),
      resolver_(resolver),
      physics_(world.physics),
      paused_(options.paused),
      options_(options),
      timing_(options.timing),
      node_("/") {
  clock_publisher_ = node_.advertise<rosgraph_msgs::Clock>("/clock", 10);
  for (const PlacedModel& placed : world.models) spawn(placed.model, placed.pose, "");
  api_ = std::make_unique<GazeboRosApi>(*this);
  scene_markers_ = std::make_unique<SceneMarkers>(physics_);
  pose_info_ = std::make_unique<PoseInfo>(physics_);
  scene_info_ = std::make_unique<SceneInfo>();
  joint_commands_ = std::make_unique<JointCommandTopic>(physics_);
  publishClock(true);
}

Simulator::~Simulator() {
  if (timing_.enabled()) {
    const std::string report = timing_.report(physics_.time());
    ROS_INFO_STREAM(report);
    std::fputs(report.c_str(), stdout);
  }
}

void Simulator::spawn(const ModelDescription& model, const Eigen::Isometry3d& pose, const std::string& robot_namespace) {
  PhysicsModel& added = physics_.addModel(model, pose);
  for (const std::string& w : model.warnings) ROS_WARN_STREAM(w);
  for (const std::string& w : physics_.warnings()) ROS_WARN_STREAM(w);
  try {
    plugins_[model.name] = loadModelPlugins(physics_, added, robot_namespace);
  } catch (...) {
    plugins_.erase(model.name);
    physics_.removeModel(model.name);
    throw;
  }
  scene_changed_ = true;
}

bool Simulator::remove(const std::string& name) {
  plugins_.erase(name);  // plugins refer to the model: they go first
  if (joint_commands_) joint_commands_->forgetModel(name);
  if (!physics_.removeModel(name)) return false;
  scene_changed_ = true;
  return true;
}

void Simulator::setPaused(bool paused) {
  paused_ = paused;
  pace_wall_start_ = ros::WallTime();  // restart real-time tracking on resume
}

void Simulator::resetWorld() {
  physics_.resetModels();
  joint_commands_->clear();  // as Gazebo's Model::Reset resets its JointController
  for (auto& [name, plugins] : plugins_)
    for (LoadedPlugin& p : plugins) p.plugin->reset();
  pace_wall_start_ = ros::WallTime();
}

void Simulator::resetSimulation() {
  physics_.setTime(0.0);
  resetWorld();
  last_clock_ = ros::Time();
  publishClock(true);
}

// With --timing, every part's wall time is recorded; otherwise the laps cost a branch each.
void Simulator::stepOnce() {
  timing_.mark();
  const ros::Time before = now();
  if (before_step) before_step(before);
  const double dt = physics_.settings().max_step_size;
  joint_commands_->beforeStep(dt);
  timing_.lap("/gazebo apply_joint_effort, apply_body_wrench, joint_cmd");
  for (auto& [name, plugins] : plugins_) {
    for (LoadedPlugin& p : plugins) {
      p.plugin->beforeStep(before, dt);
      timing_.lap(p.label, ", before the step");
    }
  }
  physics_.step();
  timing_.lap("physics step");
  const ros::Time after = now();
  for (auto& [name, plugins] : plugins_) {
    for (LoadedPlugin& p : plugins) {
      p.plugin->afterStep(after);
      timing_.lap(p.label, ", after the step");
    }
  }
  api_->afterStep(after);
  scene_markers_->publish();
  pose_info_->publish();
  timing_.lap("/gazebo model_states, link_states, scene_markers, pose_info");
  publishClock(false);
  timing_.lap("/clock");
  timing_.countStep();
}

void Simulator::runSteps(int n) {
  for (int i = 0; i < n; ++i) stepOnce();
  publishClock(true);  // the last step's time, even inside the wall-clock throttle
}

void Simulator::publishClock(bool force) {
  const ros::Time t = now();
  const ros::WallTime wall = ros::WallTime::now();
  if (!force) {
    // gazebo_ros: /clock at pub_clock_frequency Hz of sim time whatever the speed (0: every step).
    if (options_.pub_clock_frequency > 0 && (t - last_clock_).toSec() < 1.0 / options_.pub_clock_frequency) return;
    if (wall - last_clock_wall_ < kMinClockWallPeriod) return;
  }
  rosgraph_msgs::Clock msg;
  msg.clock = t;
  publish_thread::publish(clock_publisher_, msg);
  last_clock_ = t;
  last_clock_wall_ = wall;
}

void Simulator::publishSceneIfChanged() {
  if (!scene_changed_) return;
  scene_info_->publish(physics_, plugins_);
  scene_changed_ = false;
}

void Simulator::run() {
  ros::CallbackQueue& queue = *ros::getGlobalCallbackQueue();
  while (ros::ok()) {
    if (paused_) {
      queue.callAvailable(ros::WallDuration(0.01));
      publishSceneIfChanged();
      pose_info_->publish();  // a model moved while paused shows within the loop's 10 ms (at most 60 Hz)
      if (ros::WallTime::now() - last_clock_wall_ > kPausedClockPeriod) {
        publishClock(true);
        api_->publishStates(true);
        scene_markers_->publish();
      }
      continue;
    }
    timing_.mark();
    queue.callAvailable();
    publishSceneIfChanged();
    timing_.lap("ROS callbacks (services, subscriptions)");
    if (paused_) continue;
    stepOnce();

    // Target speed: real_time_update_rate steps a second, as Gazebo paces (its real_time_factor
    // is only the figure the two should give); 0 means as fast as possible. So
    // set_physics_properties' max_update_rate 5000 with 1 ms steps runs at 5 x, as in Gazebo.
    const PhysicsSettings& s = physics_.settings();
    const double target = s.real_time_update_rate > 0 ? s.real_time_update_rate * s.max_step_size : 0.0;
    if (target <= 0) continue;
    const ros::WallTime wall = ros::WallTime::now();
    if (pace_wall_start_.isZero()) {
      pace_wall_start_ = wall;
      pace_sim_start_ = physics_.time();
      continue;
    }
    const double ahead = (physics_.time() - pace_sim_start_) / target - (wall - pace_wall_start_).toSec();
    if (ahead > kMinPaceSleep) {
      queue.callAvailable(ros::WallDuration(ahead));  // sleeps, but answers requests meanwhile
      const double still_ahead =
          (physics_.time() - pace_sim_start_) / target - (ros::WallTime::now() - pace_wall_start_).toSec();
      if (still_ahead > 0) ros::WallDuration(still_ahead).sleep();
    } else if (ahead < -0.5) {
      pace_wall_start_ = ros::WallTime();  // far behind: do not try to catch up in a burst
    }
  }
}

}  // namespace bullet_sim
