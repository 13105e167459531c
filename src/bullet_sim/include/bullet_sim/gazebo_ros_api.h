#pragma once
// The /gazebo services and topics of gazebo_ros (gazebo_ros_api_plugin), over our simulator:
// same names, same message types, same meaning of their fields. Requests that cannot be
// honoured answer success=false with a status_message that says why; nothing throws out.
#include <gazebo_msgs/ApplyBodyWrench.h>
#include <gazebo_msgs/ApplyJointEffort.h>
#include <gazebo_msgs/BodyRequest.h>
#include <gazebo_msgs/DeleteModel.h>
#include <gazebo_msgs/GetJointProperties.h>
#include <gazebo_msgs/GetLinkProperties.h>
#include <gazebo_msgs/GetLinkState.h>
#include <gazebo_msgs/GetModelProperties.h>
#include <gazebo_msgs/GetModelState.h>
#include <gazebo_msgs/GetPhysicsProperties.h>
#include <gazebo_msgs/GetWorldProperties.h>
#include <gazebo_msgs/JointRequest.h>
#include <gazebo_msgs/ModelState.h>
#include <gazebo_msgs/SetModelConfiguration.h>
#include <gazebo_msgs/SetLinkState.h>
#include <gazebo_msgs/SetModelState.h>
#include <gazebo_msgs/SetPhysicsProperties.h>
#include <gazebo_msgs/SpawnModel.h>
#include <ros/ros.h>
#include <std_srvs/Empty.h>
#include <bullet_sim_msgs/StepWorld.h>

#include <Eigen/Geometry>
#include <vector>

#include "bullet_sim/physics_reconfigure.h"
#include "bullet_sim/simulator.h"
#include "bullet_sim_plugins/counted_publisher.h"

namespace bullet_sim {

class GazeboRosApi {
 public:
  explicit GazeboRosApi(Simulator& sim);
  void afterStep(const ros::Time& now);  // publishes model_states / link_states
  void publishStates(bool force);        // also while paused, so that late subscribers see the world

 private:
  struct TimedJointEffort {
    std::string model, joint;
    double effort;
    ros::Time start, end;  // end zero: until cleared
  };
  struct TimedWrench {
    std::string model, link;
    Eigen::Vector3d force, torque, point;  // world frame; point relative to the link origin
    ros::Time start, end;
  };

  void applyTimedForces(const ros::Time& now);
  // "" or "world" -> identity; "model" or "model::link" -> its pose. False if unknown.
  bool entityPose(const std::string& name, Eigen::Isometry3d& pose, Twist* twist = nullptr) const;

  bool spawnUrdf(gazebo_msgs::SpawnModel::Request& req, gazebo_msgs::SpawnModel::Response& res);
  bool spawnSdf(gazebo_msgs::SpawnModel::Request& req, gazebo_msgs::SpawnModel::Response& res);
  bool spawn(gazebo_msgs::SpawnModel::Request& req, gazebo_msgs::SpawnModel::Response& res, bool urdf_service);
  bool deleteModel(gazebo_msgs::DeleteModel::Request& req, gazebo_msgs::DeleteModel::Response& res);
  bool getModelState(gazebo_msgs::GetModelState::Request& req, gazebo_msgs::GetModelState::Response& res);
  bool setModelState(gazebo_msgs::SetModelState::Request& req, gazebo_msgs::SetModelState::Response& res);
  bool applyModelState(const gazebo_msgs::ModelState& state, std::string& status);
  // A state message's pose and twist in the world frame; false, with status naming `what`'s bad
  // field, if a number is not finite or the reference frame does not exist.
  bool worldState(const geometry_msgs::Pose& pose_msg, const geometry_msgs::Twist& twist_msg,
                  const std::string& reference_frame, const std::string& what, Eigen::Isometry3d& pose, Twist& twist,
                  std::string& status) const;
  void setModelStateTopic(const gazebo_msgs::ModelState::ConstPtr& msg);
  bool getLinkState(gazebo_msgs::GetLinkState::Request& req, gazebo_msgs::GetLinkState::Response& res);
  bool setLinkState(gazebo_msgs::SetLinkState::Request& req, gazebo_msgs::SetLinkState::Response& res);
  bool applyLinkState(const gazebo_msgs::LinkState& state, std::string& status);
  void setLinkStateTopic(const gazebo_msgs::LinkState::ConstPtr& msg);
  bool getModelProperties(gazebo_msgs::GetModelProperties::Request& req, gazebo_msgs::GetModelProperties::Response& res);
  bool getJointProperties(gazebo_msgs::GetJointProperties::Request& req, gazebo_msgs::GetJointProperties::Response& res);
  bool getLinkProperties(gazebo_msgs::GetLinkProperties::Request& req, gazebo_msgs::GetLinkProperties::Response& res);
  bool getWorldProperties(gazebo_msgs::GetWorldProperties::Request& req, gazebo_msgs::GetWorldProperties::Response& res);
  bool getPhysicsProperties(gazebo_msgs::GetPhysicsProperties::Request& req,
                            gazebo_msgs::GetPhysicsProperties::Response& res);
  bool setPhysicsProperties(gazebo_msgs::SetPhysicsProperties::Request& req,
                            gazebo_msgs::SetPhysicsProperties::Response& res);
  bool applyJointEffort(gazebo_msgs::ApplyJointEffort::Request& req, gazebo_msgs::ApplyJointEffort::Response& res);
  bool applyBodyWrench(gazebo_msgs::ApplyBodyWrench::Request& req, gazebo_msgs::ApplyBodyWrench::Response& res);
  bool clearJointForces(gazebo_msgs::JointRequest::Request& req, gazebo_msgs::JointRequest::Response& res);
  bool clearBodyWrenches(gazebo_msgs::BodyRequest::Request& req, gazebo_msgs::BodyRequest::Response& res);
  bool setModelConfiguration(gazebo_msgs::SetModelConfiguration::Request& req,
                             gazebo_msgs::SetModelConfiguration::Response& res);
  bool pausePhysics(std_srvs::Empty::Request&, std_srvs::Empty::Response&);
  bool unpausePhysics(std_srvs::Empty::Request&, std_srvs::Empty::Response&);
  bool stepWorld(bullet_sim_msgs::StepWorld::Request& req, bullet_sim_msgs::StepWorld::Response& res);
  bool resetSimulation(std_srvs::Empty::Request&, std_srvs::Empty::Response&);
  bool resetWorld(std_srvs::Empty::Request&, std_srvs::Empty::Response&);

  Simulator& sim_;
  ros::NodeHandle node_;  // /gazebo
  std::vector<ros::ServiceServer> services_;
  ros::Subscriber set_model_state_sub_, set_link_state_sub_;
  CountedPublisher model_states_pub_, link_states_pub_;
  ros::WallTime last_states_wall_;
  std::vector<TimedJointEffort> joint_efforts_;
  std::vector<TimedWrench> wrenches_;
  PhysicsReconfigure reconfigure_;  // the same physics through dynamic_reconfigure
};

}  // namespace bullet_sim
