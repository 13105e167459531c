#pragma once
// gzclient's view for rviz: every model's visuals as visualization_msgs/MarkerArray in frame
// "world" on /gazebo/scene_markers, at about 10 Hz of wall time while someone subscribes, so
// rviz shows the world (walls, obstacles, robots) and not only what a robot's sensors see.
#include <ros/ros.h>
#include <visualization_msgs/MarkerArray.h>

#include "bullet_sim_core/physics_world.h"
#include "bullet_sim_plugins/counted_publisher.h"

namespace bullet_sim {

class SceneMarkers {
 public:
  explicit SceneMarkers(PhysicsWorld& world);
  void publish(bool force = false);  // at most every 0.1 s of wall time unless forced

 private:
  PhysicsWorld& world_;
  CountedPublisher publisher_;
  ros::WallTime last_;
};

// The markers for one model (namespace = model name), poses at the current state.
void appendModelMarkers(const PhysicsModel& model, const ros::Time& stamp, visualization_msgs::MarkerArray& out);

// One visual as a marker: its type, size, colour and mesh resource, posed in the frame that
// `frame_pose` places (its link's world pose for the world frame, identity for the link's own
// frame). Header, namespace, id and text are the caller's. /gazebo/scene_info draws with these too.
visualization_msgs::Marker visualMarker(const VisualShape& visual, const Eigen::Isometry3d& frame_pose);

}  // namespace bullet_sim
