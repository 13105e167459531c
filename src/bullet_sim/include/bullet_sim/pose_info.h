#pragma once
// /gazebo/pose_info (gazebo_msgs/LinkStates): every link's world pose and twist, named
// "model::link", for a client that draws the world (sim_studio), as Gazebo's ~/pose/info feeds
// gzclient. At most 60 times a second of wall time whatever the speed, only while someone
// subscribes, and also while the simulation is paused (at the paused loop's pace), so that a model
// moved while paused (set_model_state, reset_world, spawn, ...) shows at once.
#include <gazebo_msgs/LinkStates.h>
#include <ros/ros.h>

#include "bullet_sim_core/physics_world.h"
#include "bullet_sim_plugins/counted_publisher.h"

namespace bullet_sim {

class PoseInfo {
 public:
  explicit PoseInfo(const PhysicsWorld& world);
  // Publishes if someone subscribes and 1/60 s of wall time has passed since the last message.
  void publish();

 private:
  const PhysicsWorld& world_;
  CountedPublisher publisher_;
  ros::WallTime last_;
};

// Every link of every model, "model::link", in the world frame: what /gazebo/link_states and
// /gazebo/pose_info carry.
gazebo_msgs::LinkStates linkStates(const PhysicsWorld& world);

}  // namespace bullet_sim
