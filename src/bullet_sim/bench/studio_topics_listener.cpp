// studio_topics_listener: the studio benchmark's subscriber (scripts/bench_studio_topics.py).
//
//   studio_topics_listener OUT_FILE
//
// Subscribes to /gazebo/pose_info and /gazebo/scene_info, as a client like sim_studio does, and
// counts what arrives; creates OUT_FILE.ready once it has both a scene and a pose, and writes
// "pose_info N SECONDS" and "scene_info N" to OUT_FILE when stopped (SIGINT or SIGTERM). In C++ so that the
// benchmark measures what the simulator pays for its subscribers, not a Python process competing
// with it for the two cores.
#include <gazebo_msgs/LinkStates.h>
#include <ros/callback_queue.h>
#include <ros/ros.h>
#include <visualization_msgs/MarkerArray.h>

#include <csignal>
#include <fstream>
#include <string>

namespace {
volatile std::sig_atomic_t stop = 0;
}  // namespace

int main(int argc, char** argv) {
  // Its own SIGINT handler: the counts are written at once, before roscpp's shutdown talks to the
  // master, which on a loaded machine can take longer than the benchmark waits.
  ros::init(argc, argv, "studio_topics_listener", ros::init_options::AnonymousName | ros::init_options::NoSigintHandler);
  std::signal(SIGINT, [](int) { stop = 1; });
  std::signal(SIGTERM, [](int) { stop = 1; });
  if (argc < 2) {
    std::cerr << "usage: studio_topics_listener OUT_FILE" << std::endl;
    return 2;
  }
  const std::string out = argv[1];
  ros::NodeHandle node;
  long poses = 0, scenes = 0;
  ros::WallTime first_pose, last_pose;
  bool ready = false;
  auto check_ready = [&] {
    if (ready || poses == 0 || scenes == 0) return;
    ready = true;
    std::ofstream(out + ".ready") << "ready\n";
  };
  auto on_pose = [&](const gazebo_msgs::LinkStates::ConstPtr&) {
    last_pose = ros::WallTime::now();
    if (poses++ == 0) first_pose = last_pose;
    check_ready();
  };
  auto on_scene = [&](const visualization_msgs::MarkerArray::ConstPtr&) {
    ++scenes;
    check_ready();
  };
  const ros::TransportHints hints = ros::TransportHints().tcpNoDelay();
  ros::Subscriber pose_sub = node.subscribe<gazebo_msgs::LinkStates>("/gazebo/pose_info", 1, on_pose, {}, hints);
  ros::Subscriber scene_sub = node.subscribe<visualization_msgs::MarkerArray>("/gazebo/scene_info", 1, on_scene, {}, hints);
  while (!stop) ros::getGlobalCallbackQueue()->callAvailable(ros::WallDuration(0.01));
  std::ofstream f(out);
  f << "pose_info " << poses << " " << (poses > 1 ? (last_pose - first_pose).toSec() : 0.0) << "\n";
  f << "scene_info " << scenes << "\n";
  f.close();
  ros::shutdown();
  return f ? 0 : 1;
}
