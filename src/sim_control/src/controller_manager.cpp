#include "sim_control/controller_manager.h"

#include <algorithm>
#include <map>

#include "ros_params/reader.h"
#include "sim_control/controller_registry.h"

namespace sim_control {
namespace {
constexpr int kBestEffort = controller_manager_msgs::SwitchController::Request::BEST_EFFORT;

bool contains(const std::vector<std::string>& list, const std::string& name) {
  return std::find(list.begin(), list.end(), name) != list.end();
}

std::string joinLines(const std::vector<std::string>& items) {
  std::string out;
  for (const auto& i : items) out += "\n    " + i;
  return out;
}
}  // namespace

std::string stateName(ControllerManager::State state) {
  switch (state) {
    case ControllerManager::State::Initialized: return "initialized";
    case ControllerManager::State::Running: return "running";
    case ControllerManager::State::Stopped: return "stopped";
  }
  return "";
}

ControllerManager::ControllerManager(RobotHW& hw, const ros::NodeHandle& robot_nh) : hw_(hw), robot_nh_(robot_nh) {
  ros::NodeHandle cm(robot_nh_, "controller_manager");
  services_ = {
      cm.advertiseService("load_controller", &ControllerManager::onLoad, this),
      cm.advertiseService("unload_controller", &ControllerManager::onUnload, this),
      cm.advertiseService("switch_controller", &ControllerManager::onSwitch, this),
      cm.advertiseService("list_controllers", &ControllerManager::onList, this),
      cm.advertiseService("list_controller_types", &ControllerManager::onListTypes, this),
      cm.advertiseService("reload_controller_libraries", &ControllerManager::onReload, this),
  };
}

ControllerManager::~ControllerManager() {
  for (auto& e : controllers_)
    if (e.state == State::Running) e.controller->stopping(last_time_);
}

ControllerManager::Entry* ControllerManager::find(const std::string& name) {
  for (auto& e : controllers_)
    if (e.name == name) return &e;
  return nullptr;
}

bool ControllerManager::fail(const std::string& message, std::string& error) {
  error = message;
  ROS_ERROR_STREAM(message);
  return false;
}

void ControllerManager::update(const ros::Time& time, const ros::Duration& period) {
  last_time_ = time;
  for (auto& e : controllers_)
    if (e.state == State::Running) e.controller->update(time, period);
}

bool ControllerManager::load(const std::string& name, std::string& error) {
  if (find(name)) return fail("A controller named '" + name + "' was already loaded inside the controller manager", error);
  ros::NodeHandle controller_nh(robot_nh_, name);
  std::string type;
  ros_params::Reader params(controller_nh);
  if (!params.read("type", &type, "a controller type such as effort_controllers/JointPositionController")) {
    if (!params.ok()) return fail("Could not load controller '" + name + "': " + params.problems(), error);
    return fail("Could not load controller '" + name +
                    "' because the type was not specified. Did you load the controller configuration on the "
                    "parameter server (namespace: '" + controller_nh.getNamespace() + "')?",
                error);
  }
  std::unique_ptr<Controller> controller = createController(type);
  if (!controller) {
    return fail("Could not load controller '" + name + "' because controller type '" + type +
                    "' does not exist.\n  Use 'rosservice call " + robot_nh_.resolveName("controller_manager") +
                    "/list_controller_types' to get the available types. They are:" + joinLines(controllerTypes()),
                error);
  }
  std::string why;
  ros::NodeHandle root_nh(robot_nh_);
  if (!controller->init(hw_, root_nh, controller_nh, why))
    return fail("Initializing controller '" + name + "' failed: " + why, error);
  controllers_.push_back(Entry{name, type, std::move(controller), State::Initialized});
  ROS_DEBUG_STREAM("Loaded controller '" << name << "' of type " << type);
  return true;
}

bool ControllerManager::unload(const std::string& name, std::string& error) {
  Entry* e = find(name);
  if (!e)
    return fail("Could not unload controller with name '" + name + "' because no controller with this name exists",
                error);
  if (e->state == State::Running)
    return fail("Could not unload controller with name '" + name + "' because it is still running", error);
  controllers_.erase(controllers_.begin() + (e - controllers_.data()));
  return true;
}

bool ControllerManager::switchControllers(const std::vector<std::string>& start, const std::vector<std::string>& stop,
                                          int strictness, std::string& error) {
  const bool strict = strictness != 0 && strictness != kBestEffort;
  std::vector<Entry*> to_stop, to_start;
  for (const auto& name : stop) {
    Entry* e = find(name);
    if (!e || e->state != State::Running) {
      const std::string why = !e ? "Could not stop controller with name '" + name +
                                       "' because no controller with this name exists"
                                 : "Could not stop controller '" + name + "' since it is not running";
      if (strict) return fail(why, error);
      ROS_WARN_STREAM(why);
      continue;
    }
    to_stop.push_back(e);
  }
  for (const auto& name : start) {
    Entry* e = find(name);
    const bool restarting = e && contains(stop, name);
    if (!e || (e->state == State::Running && !restarting)) {
      const std::string why = !e ? "Could not start controller with name '" + name +
                                       "' because no controller with this name exists"
                                 : "Could not start controller '" + name + "' since it is already running";
      if (strict) return fail(why, error);
      ROS_WARN_STREAM(why);
      continue;
    }
    to_start.push_back(e);
  }
  // Resource conflicts among the controllers that would run afterwards.
  std::map<std::string, std::string> owner;  // joint -> controller
  for (auto& e : controllers_) {
    const bool runs = (e.state == State::Running &&
                       std::find(to_stop.begin(), to_stop.end(), &e) == to_stop.end()) ||
                      std::find(to_start.begin(), to_start.end(), &e) != to_start.end();
    if (!runs) continue;
    for (const auto& claimed : e.controller->claimedResources()) {
      for (const auto& joint : claimed.joints) {
        auto [it, fresh] = owner.emplace(joint, e.name);
        if (!fresh)
          return fail("Could not switch controllers: resource conflict for joint '" + joint + "' (" +
                          interfaceName(claimed.interface) + "), claimed by both '" + it->second + "' and '" + e.name +
                          "'. Stop one of them in the same switch_controller call.",
                      error);
      }
    }
  }
  for (Entry* e : to_stop) {
    e->controller->stopping(last_time_);
    e->state = State::Stopped;
  }
  for (Entry* e : to_start) {
    e->controller->starting(last_time_);
    e->state = State::Running;
  }
  updateDriven();
  return true;
}

void ControllerManager::updateDriven() {
  for (JointData& joint : hw_.joints()) joint.driven = false;
  for (const auto& e : controllers_)
    if (e.state == State::Running)
      for (const auto& claimed : e.controller->claimedResources())
        for (const std::string& name : claimed.joints)
          if (JointData* joint = hw_.joint(name)) joint->driven = true;
}

bool ControllerManager::onLoad(controller_manager_msgs::LoadController::Request& req,
                               controller_manager_msgs::LoadController::Response& res) {
  std::string error;
  res.ok = load(req.name, error);
  return true;
}

bool ControllerManager::onUnload(controller_manager_msgs::UnloadController::Request& req,
                                 controller_manager_msgs::UnloadController::Response& res) {
  std::string error;
  res.ok = unload(req.name, error);
  return true;
}

bool ControllerManager::onSwitch(controller_manager_msgs::SwitchController::Request& req,
                                 controller_manager_msgs::SwitchController::Response& res) {
  std::string error;
  // start_asap and timeout need no waiting here: the switch happens between two steps.
  res.ok = switchControllers(req.start_controllers, req.stop_controllers, req.strictness, error);
  return true;
}

bool ControllerManager::onList(controller_manager_msgs::ListControllers::Request&,
                               controller_manager_msgs::ListControllers::Response& res) {
  for (const auto& e : controllers_) {
    controller_manager_msgs::ControllerState state;
    state.name = e.name;
    state.type = e.type;
    state.state = stateName(e.state);
    for (const auto& claimed : e.controller->claimedResources()) {
      controller_manager_msgs::HardwareInterfaceResources resources;
      resources.hardware_interface = interfaceName(claimed.interface);
      resources.resources = claimed.joints;
      state.claimed_resources.push_back(resources);
    }
    res.controller.push_back(state);
  }
  return true;
}

bool ControllerManager::onListTypes(controller_manager_msgs::ListControllerTypes::Request&,
                                    controller_manager_msgs::ListControllerTypes::Response& res) {
  res.types = controllerTypes();
  res.base_classes.assign(res.types.size(), "controller_interface::ControllerBase");
  return true;
}

bool ControllerManager::onReload(controller_manager_msgs::ReloadControllerLibraries::Request& req,
                                 controller_manager_msgs::ReloadControllerLibraries::Response& res) {
  // Controllers are compiled in; "reloading" means starting from no loaded controllers.
  if (!controllers_.empty() && !req.force_kill) {
    std::string error;
    fail("Controller manager: Cannot reload controller libraries because there are still " +
             std::to_string(controllers_.size()) + " controllers loaded (call with force_kill: true to stop and "
             "unload them)",
         error);
    res.ok = false;
    return true;
  }
  for (auto& e : controllers_)
    if (e.state == State::Running) e.controller->stopping(last_time_);
  controllers_.clear();
  updateDriven();
  res.ok = true;
  return true;
}

}  // namespace sim_control
