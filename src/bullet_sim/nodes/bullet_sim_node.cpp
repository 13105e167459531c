// bullet_sim_node: the simulator, started like gzserver:
//   rosrun bullet_sim bullet_sim_node [-u] [--verbose] [-e ENGINE] [WORLD_FILE]
//   rosrun bullet_sim bullet_sim_node --list-plugins
// -u starts paused. Without a world file the empty world (ground plane + sun) is loaded.
// --list-plugins prints the plugin libraries models can name, and exits.
// A world file that cannot be read exits with status 1 and a message naming the problem.
#include <ros/package.h>
#include <ros/ros.h>

#include <iostream>

#include "bullet_sim/simulator.h"
#include "bullet_sim_core/description_error.h"
#include "bullet_sim_core/sdf_parser.h"
#include "bullet_sim_plugins/plugin_registry.h"

namespace {

struct Arguments {
  bool paused = false;
  bool verbose = false;
  bool list_plugins = false;
  std::string world_file;
};

bool parseArguments(const std::vector<std::string>& args, Arguments& out, std::string& error) {
  for (size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (a == "-u" || a == "--pause") {
      out.paused = true;
    } else if (a == "--verbose") {
      out.verbose = true;
    } else if (a == "--list-plugins") {
      out.list_plugins = true;
    } else if (a == "-e" || a == "--physics") {
      ++i;  // gzserver's physics engine choice; there is only Bullet here
    } else if (!a.empty() && a[0] == '-') {
      // Other gzserver flags (e.g. -s plugin) have no meaning here.
      ROS_WARN_STREAM("bullet_sim_node: ignoring option '" << a << "'");
    } else if (out.world_file.empty()) {
      out.world_file = a;
    } else {
      error = "bullet_sim_node: expected one world file, got '" + out.world_file + "' and '" + a + "'";
      return false;
    }
  }
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  ros::init(argc, argv, "gazebo");
  std::vector<std::string> args;
  ros::removeROSArgs(argc, argv, args);
  args.erase(args.begin());
  Arguments arguments;
  std::string error;
  if (!parseArguments(args, arguments, error)) {
    std::cerr << error << std::endl;
    return 2;
  }
  if (arguments.list_plugins) {
    for (const std::string& name : bullet_sim::registeredPlugins()) std::cout << name << "\n";
    return 0;
  }
  ros::NodeHandle gazebo("/gazebo");
  bullet_sim::SimulatorOptions options;
  options.paused = arguments.paused;
  gazebo.param("pub_clock_frequency", options.pub_clock_frequency, 0.0);
  // A node started alone still gives sim time to everyone who asks for it.
  if (!ros::param::has("/use_sim_time")) ros::param::set("/use_sim_time", true);

  const bullet_sim::ResourceResolver resolver = bullet_sim::ResourceResolver::fromEnvironment();
  bullet_sim::WorldDescription world;
  std::string world_file = arguments.world_file;
  if (world_file.empty()) world_file = ros::package::getPath("bullet_sim") + "/worlds/empty.world";
  try {
    world = bullet_sim::parseWorldFile(world_file, resolver);
    bullet_sim::Simulator simulator(world, resolver, options);
    ROS_INFO_STREAM("bullet_sim: world '" << world.name << "' from " << world_file << " with "
                                          << world.models.size() << " models, step "
                                          << world.physics.max_step_size << " s"
                                          << (options.paused ? ", paused" : ""));
    simulator.run();
  } catch (const bullet_sim::DescriptionError& e) {
    ROS_FATAL_STREAM("bullet_sim: cannot load world: " << e.what());
    std::cerr << "bullet_sim: cannot load world: " << e.what() << std::endl;
    return 1;
  }
  return 0;
}
