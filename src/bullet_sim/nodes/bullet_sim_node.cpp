// bullet_sim_node: the simulator, started like gzserver:
//   rosrun bullet_sim bullet_sim_node [-u] [--verbose] [--timing] [GZSERVER_OPTIONS] [WORLD_FILE]
//   rosrun bullet_sim bullet_sim_node --list-plugins
// -u starts paused. Without a world file the empty world (ground plane + sun) is loaded. A
// relative WORLD_FILE is looked for, as gzserver does, in the current folder, then in each folder
// of GAZEBO_RESOURCE_PATH, then in this package (so Gazebo's `worlds/empty.world` works).
// --timing prints, at exit, where the loop's time went (see loop_timing.h).
// --list-plugins prints the plugin libraries models can name, and exits.
// gzserver's other options (-e bullet, -s libfoo.so, --seed 3, ...) are accepted with a warning.
// A world file that cannot be read exits with status 1 and a message naming the problem; a
// crash prints the stack it happened on (crash_report.h).
#include <ros/package.h>
#include <ros/ros.h>
#include <sys/prctl.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <sstream>
#include <vector>

#include "bullet_sim/crash_report.h"
#include "bullet_sim/simulator.h"
#include "bullet_sim_core/description_error.h"
#include "bullet_sim_core/sdf_parser.h"
#include "bullet_sim_plugins/plugin_registry.h"
#include "publish_thread/no_delay.h"
#include "ros_params/reader.h"

namespace {

// gzserver's options that take a value.
const std::vector<std::string> kOptionsWithValue = {
    "-e", "--physics", "-s", "--server-plugin", "-p", "--play", "-o", "--profile", "--seed", "--iters",
    "--record_encoding", "--record_path", "--record_period", "--record_filter", "-g", "--gui-plugin"};

struct Arguments {
  bool paused = false;
  bool verbose = false;
  bool list_plugins = false;
  bool timing = false;
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
    } else if (a == "--timing") {
      out.timing = true;
    } else if (std::find(kOptionsWithValue.begin(), kOptionsWithValue.end(), a) != kOptionsWithValue.end()) {
      // gzserver's options that take a value (physics engine, plugins, recording, ...): no meaning here.
      ROS_WARN_STREAM("bullet_sim_node: ignoring option '" << a << (i + 1 < args.size() ? " " + args[i + 1] : "")
                                                           << "'");
      ++i;
    } else if (!a.empty() && a[0] == '-') {
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

// The world file as gzserver finds it: a path that exists as given (absolute, or relative to the
// current folder), else the first folder of GAZEBO_RESOURCE_PATH, then of this package, holding it.
// Unfound, the name is returned as given and loading it says so.
std::string findWorldFile(const std::string& name) {
  namespace fs = std::filesystem;
  if (name.empty() || fs::path(name).is_absolute() || fs::exists(name)) return name;
  std::vector<std::string> folders;
  if (const char* resource_path = std::getenv("GAZEBO_RESOURCE_PATH")) {
    std::stringstream list(resource_path);
    for (std::string folder; std::getline(list, folder, ':');)
      if (!folder.empty()) folders.push_back(folder);
  }
  folders.push_back(ros::package::getPath("bullet_sim"));
  for (const std::string& folder : folders)
    if (fs::exists(fs::path(folder) / name)) return (fs::path(folder) / name).string();
  return name;
}

// Gazebo makes ~/.gazebo/models, its local model folder, the first time it runs; tutorials then
// copy models into it (`cp -r Capstone_Map ~/.gazebo/models`).
void makeLocalModelFolder() {
  const char* home = std::getenv("HOME");
  if (!home || !*home) return;
  std::error_code ignored;  // a read-only home only means there is no local model folder
  std::filesystem::create_directories(std::filesystem::path(home) / ".gazebo" / "models", ignored);
}

}  // namespace

int main(int argc, char** argv) {
  // Named as Gazebo's server is, so that `killall gzserver` (in the tutorials) stops the simulator
  // however it was started. Threads started later inherit the name.
  prctl(PR_SET_NAME, "gzserver", 0, 0, 0);
  bullet_sim::reportCrashesOnStderr("bullet_sim_node");
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
  publish_thread::sendWithoutDelay();  // every subscriber gets each message at once, even faster than real time
  bullet_sim::SimulatorOptions options;
  options.paused = arguments.paused;
  options.timing = arguments.timing;
  ros_params::Reader gazebo_params(gazebo);
  gazebo_params.read("pub_clock_frequency", &options.pub_clock_frequency, "a rate in Hz (0: every step)");
  for (const std::string& problem : gazebo_params.problemList()) ROS_ERROR("%s; using the default.", problem.c_str());
  // A node started alone still gives sim time to everyone who asks for it.
  if (!ros::param::has("/use_sim_time")) ros::param::set("/use_sim_time", true);

  makeLocalModelFolder();
  const bullet_sim::ResourceResolver resolver = bullet_sim::ResourceResolver::fromEnvironment();
  bullet_sim::WorldDescription world;
  std::string world_file = findWorldFile(arguments.world_file);
  if (world_file.empty()) world_file = ros::package::getPath("bullet_sim") + "/worlds/empty.world";
  try {
    world = bullet_sim::parseWorldFile(world_file, resolver);
    for (const std::string& warning : world.warnings) ROS_WARN_STREAM("bullet_sim: " << warning);
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
