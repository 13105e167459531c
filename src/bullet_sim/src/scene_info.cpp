#include "bullet_sim/scene_info.h"

#include <algorithm>

#include "bullet_sim/scene_markers.h"
#include "bullet_sim_plugins/ros_conversions.h"
#include "publish_thread/publish_thread.h"

namespace bullet_sim {
namespace {

void appendModel(const PhysicsModel& model, const std::vector<LoadedPlugin>* plugins, const ros::Time& stamp,
                 visualization_msgs::MarkerArray& out) {
  const std::vector<std::string> links = model.linkNames();
  auto placeable = [&](const std::string& link) { return std::find(links.begin(), links.end(), link) != links.end(); };
  int id = 0;
  auto add = [&](visualization_msgs::Marker m, const std::string& link, const std::string& text) {
    m.header.frame_id = model.name() + "::" + link;
    m.header.stamp = stamp;
    m.ns = model.name();
    m.id = id++;
    m.text = text;
    out.markers.push_back(std::move(m));
  };
  for (const LinkDescription& link : model.description().links) {
    if (!placeable(link.name)) continue;
    for (const VisualShape& visual : link.visuals)
      add(visualMarker(visual, Eigen::Isometry3d::Identity()), link.name, visual.name.empty() ? link.name : visual.name);
  }
  if (!plugins) return;
  for (const LoadedPlugin& p : *plugins) {
    const std::optional<SensorTopic> sensor = p.plugin->sensorTopic();
    if (!sensor || !placeable(sensor->link)) continue;
    visualization_msgs::Marker m;
    m.type = visualization_msgs::Marker::LINE_LIST;  // no points: the client draws from the topic
    m.action = visualization_msgs::Marker::ADD;
    m.pose = toPoseMsg(sensor->pose);
    m.scale.x = sensor->range;
    // Gazebo draws rays blue; a camera's view grey.
    m.color.a = 0.5f;
    if (sensor->kind == "laser") m.color.b = 1.0f;
    else m.color.r = m.color.g = m.color.b = 0.5f;
    add(m, sensor->link, sensor->kind + ":" + sensor->topic);
  }
}

}  // namespace

SceneInfo::SceneInfo() {
  ros::NodeHandle gazebo("/gazebo");
  publisher_ = gazebo.advertise<visualization_msgs::MarkerArray>("scene_info", 1, /*latch=*/true);
}

void SceneInfo::publish(const PhysicsWorld& world, const ModelPlugins& plugins) {
  publish_thread::publish(publisher_, sceneInfo(world, plugins));
}

visualization_msgs::MarkerArray sceneInfo(const PhysicsWorld& world, const ModelPlugins& plugins) {
  visualization_msgs::MarkerArray scene;
  visualization_msgs::Marker clear;  // whatever a client drew before goes
  clear.action = visualization_msgs::Marker::DELETEALL;
  scene.markers.push_back(clear);
  const ros::Time stamp(world.time());
  for (const std::string& name : world.modelNames()) {
    const auto found = plugins.find(name);
    appendModel(*world.findModel(name), found == plugins.end() ? nullptr : &found->second, stamp, scene);
  }
  return scene;
}

}  // namespace bullet_sim
