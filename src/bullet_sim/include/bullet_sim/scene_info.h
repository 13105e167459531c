#pragma once
// /gazebo/scene_info (visualization_msgs/MarkerArray, latched): what a client needs to draw the
// world once (sim_studio, as gzclient gets the scene from gzserver); /gazebo/pose_info then moves
// the links. Published whole, beginning with a DELETEALL marker, when the set of models changes
// (the simulator calls publish() after a spawn or a delete), not every step. For every model
// (`ns` = its name):
//  - each visual of each link: header.frame_id "model::link", the pose in that link's frame, `id`
//    unique within the model, `text` the visual's name (the link's when it has none), type, scale,
//    colour and mesh resource as /gazebo/scene_markers draws them (scene_markers.h);
//  - each laser and camera plugin's sensor: a LINE_LIST with no points, frame_id its "model::link",
//    the sensor's pose in the link, `text` "laser:" or "camera:" + its LaserScan or Image topic's
//    resolved name, scale.x its range (a laser's range max, a camera's far clip), so that a client
//    can draw the rays or the view from the topic.
// Links a client cannot place (a fixed robot's "world" link, which pose_info does not list) are
// left out. The layout is documented in docs/SIMULATOR.md.
#include <ros/ros.h>
#include <visualization_msgs/MarkerArray.h>

#include <map>
#include <string>
#include <vector>

#include "bullet_sim_core/physics_world.h"
#include "bullet_sim_plugins/plugin_loader.h"

namespace bullet_sim {

using ModelPlugins = std::map<std::string, std::vector<LoadedPlugin>>;  // by model name

class SceneInfo {
 public:
  SceneInfo();
  void publish(const PhysicsWorld& world, const ModelPlugins& plugins);

 private:
  ros::Publisher publisher_;
};

visualization_msgs::MarkerArray sceneInfo(const PhysicsWorld& world, const ModelPlugins& plugins);

}  // namespace bullet_sim
