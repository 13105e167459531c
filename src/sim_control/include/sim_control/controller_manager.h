#pragma once
// ros_control's controller manager: owns the controllers of one robot, runs the running ones
// each control period, and answers the controller_manager_msgs services under
// <robot namespace>/controller_manager. Requests are handled in the simulator's thread between
// steps, so a switch takes effect at once, also while physics is paused.
#include <controller_manager_msgs/ListControllerTypes.h>
#include <controller_manager_msgs/ListControllers.h>
#include <controller_manager_msgs/LoadController.h>
#include <controller_manager_msgs/ReloadControllerLibraries.h>
#include <controller_manager_msgs/SwitchController.h>
#include <controller_manager_msgs/UnloadController.h>
#include <ros/ros.h>

#include <memory>
#include <string>
#include <vector>

#include "sim_control/controller.h"
#include "sim_control/robot_hw.h"

namespace sim_control {

class ControllerManager {
 public:
  // robot_nh is the robot's namespace (gazebo_ros_control's robotNamespace).
  ControllerManager(RobotHW& hw, const ros::NodeHandle& robot_nh);
  ~ControllerManager();

  void update(const ros::Time& time, const ros::Duration& period);

  // The service operations, also callable directly. They return false and set `error` to the
  // message ros_control users know (and log it, as upstream does).
  bool load(const std::string& name, std::string& error);
  bool unload(const std::string& name, std::string& error);
  bool switchControllers(const std::vector<std::string>& start, const std::vector<std::string>& stop, int strictness,
                         std::string& error);

  enum class State { Initialized, Running, Stopped };
  struct Entry {
    std::string name, type;
    std::unique_ptr<Controller> controller;
    State state = State::Initialized;
  };
  const std::vector<Entry>& controllers() const { return controllers_; }

 private:
  Entry* find(const std::string& name);
  void updateDriven();  // each joint's driven flag from the running controllers' claims
  bool fail(const std::string& message, std::string& error);

  bool onLoad(controller_manager_msgs::LoadController::Request&, controller_manager_msgs::LoadController::Response&);
  bool onUnload(controller_manager_msgs::UnloadController::Request&,
                controller_manager_msgs::UnloadController::Response&);
  bool onSwitch(controller_manager_msgs::SwitchController::Request&,
                controller_manager_msgs::SwitchController::Response&);
  bool onList(controller_manager_msgs::ListControllers::Request&, controller_manager_msgs::ListControllers::Response&);
  bool onListTypes(controller_manager_msgs::ListControllerTypes::Request&,
                   controller_manager_msgs::ListControllerTypes::Response&);
  bool onReload(controller_manager_msgs::ReloadControllerLibraries::Request&,
                controller_manager_msgs::ReloadControllerLibraries::Response&);

  RobotHW& hw_;
  ros::NodeHandle robot_nh_;
  ros::Time last_time_;
  std::vector<Entry> controllers_;
  std::vector<ros::ServiceServer> services_;
};

std::string stateName(ControllerManager::State state);

}  // namespace sim_control
