#pragma once
// /gazebo/joint_cmd (bullet_sim_msgs/JointCmd): Gazebo's joint control panel for ROS clients
// (sim_studio's "Joints" panel, as gzclient's sends msgs::JointCmd to a model's JointController).
// Each joint's commands are held by a JointCommandController (bullet_sim_core) and applied before
// every physics step: a force, a position PID and a velocity PID, added up. A command for a model
// or joint that does not exist, or with a number that is not one, is a ROS warning naming it (at
// most once a second of wall time per name: rosconsole's throttle runs on sim time, which stands
// still while paused) and applies nothing. Deleting a model drops its commands; reset_world and
// reset_simulation drop them all, as Gazebo's Model::Reset resets its JointController.
#include <bullet_sim_msgs/JointCmd.h>
#include <ros/ros.h>

#include <map>
#include <string>

#include "bullet_sim_core/joint_command_controller.h"
#include "bullet_sim_core/physics_world.h"

namespace bullet_sim {

class JointCommandTopic {
 public:
  explicit JointCommandTopic(PhysicsWorld& world);  // subscribes to /gazebo/joint_cmd
  void beforeStep(double dt);                        // every held command's effort onto its joint
  void forgetModel(const std::string& model);
  void clear();

 private:
  void onCommand(const bullet_sim_msgs::JointCmd& msg);
  void warn(const std::string& name, const std::string& problem);
  struct Held {
    std::string model;
    int joint = -1;  // PhysicsModel::jointIndex
    JointCommandController controller;
  };
  PhysicsWorld& world_;
  ros::Subscriber subscriber_;
  std::map<std::string, Held> held_;  // by "model::joint"
  std::map<std::string, ros::WallTime> warned_;  // when each name was last warned about
};

// The message as a command (its set_* flags as what is present).
JointCommand jointCommand(const bullet_sim_msgs::JointCmd& msg);

}  // namespace bullet_sim
