// bench_studio_messages: what one /gazebo/pose_info and one /gazebo/scene_info message cost the
// simulator to build and serialize, in a given world (scripts/bench_studio_topics.py runs it on the
// Katana's). Deterministic where the real-time factor of a shared VM is not.
//
//   bench_studio_messages WORLD_FILE [URDF_FILE ...]
//
// Loads the world, adds each URDF as a model of its own (model_0, model_1, ...: a file may come
// more than once), and prints:
//   links: N
//   pose_info: X us to build and serialize one message (B bytes)
//   scene_info: Y us to build and serialize one message (M markers, B bytes)
//   wall clock read: Z ns
#include <ros/serialization.h>

#include <chrono>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>

#include "bullet_sim/pose_info.h"
#include "bullet_sim/scene_info.h"
#include "bullet_sim_core/sdf_parser.h"
#include "bullet_sim_core/urdf_parser.h"

namespace {

double now() { return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count(); }

// Seconds per call of f, over enough calls for a second or so of work (at least `min_calls`).
template <class F>
double secondsPerCall(F f, int min_calls) {
  int calls = min_calls;
  for (;;) {
    const double start = now();
    for (int i = 0; i < calls; ++i) f();
    const double elapsed = now() - start;
    if (elapsed > 0.5) return elapsed / calls;
    calls *= 4;
  }
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::cerr << "usage: bench_studio_messages WORLD_FILE [URDF_FILE ...]" << std::endl;
    return 2;
  }
  const bullet_sim::ResourceResolver resolver = bullet_sim::ResourceResolver::fromEnvironment();
  const bullet_sim::WorldDescription world_description = bullet_sim::parseWorldFile(argv[1], resolver);
  bullet_sim::PhysicsWorld world(world_description.physics);
  for (const bullet_sim::PlacedModel& placed : world_description.models) world.addModel(placed.model, placed.pose);
  for (int i = 2; i < argc; ++i) {
    std::ifstream file(argv[i]);
    std::stringstream text;
    text << file.rdbuf();
    bullet_sim::ModelDescription model = bullet_sim::parseUrdf(text.str(), argv[i], resolver);
    model.name = "model_" + std::to_string(i - 2);
    world.addModel(model, Eigen::Isometry3d(Eigen::Translation3d(i, 0, 0)));
  }
  world.step();

  size_t links = 0;
  for (const std::string& name : world.modelNames()) links += world.findModel(name)->linkNames().size();
  uint32_t pose_bytes = 0, scene_bytes = 0, markers = 0;
  const double pose = secondsPerCall(
      [&] { pose_bytes = ros::serialization::serializeMessage(bullet_sim::linkStates(world)).num_bytes; }, 100);
  const bullet_sim::ModelPlugins no_plugins;
  const double scene = secondsPerCall(
      [&] {
        const visualization_msgs::MarkerArray m = bullet_sim::sceneInfo(world, no_plugins);
        markers = m.markers.size();
        scene_bytes = ros::serialization::serializeMessage(m).num_bytes;
      },
      10);
  volatile double sink = 0;
  const double clock = secondsPerCall([&] { sink = sink + ros::WallTime::now().toSec(); }, 100000);
  std::printf("links: %zu\n", links);
  std::printf("pose_info: %.1f us to build and serialize one message (%u bytes)\n", pose * 1e6, pose_bytes);
  std::printf("scene_info: %.1f us to build and serialize one message (%u markers, %u bytes)\n", scene * 1e6, markers,
              scene_bytes);
  std::printf("wall clock read: %.0f ns\n", clock * 1e9);
  return 0;
}
