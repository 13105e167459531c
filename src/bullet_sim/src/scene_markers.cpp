#include "bullet_sim/scene_markers.h"

#include "bullet_sim_plugins/ros_conversions.h"

namespace bullet_sim {
namespace {
const ros::WallDuration kMarkerPeriod(0.1);
}  // namespace

SceneMarkers::SceneMarkers(PhysicsWorld& world) : world_(world) {
  ros::NodeHandle gazebo("/gazebo");
  publisher_.advertise<visualization_msgs::MarkerArray>(gazebo, "scene_markers", 1);
}

visualization_msgs::Marker visualMarker(const VisualShape& visual, const Eigen::Isometry3d& frame_pose) {
  visualization_msgs::Marker m;
  m.action = visualization_msgs::Marker::ADD;
  Eigen::Isometry3d pose = frame_pose * visual.origin;
  m.color.r = visual.rgba[0];
  m.color.g = visual.rgba[1];
  m.color.b = visual.rgba[2];
  m.color.a = visual.rgba[3];
  const Geometry& g = visual.geometry;
  switch (g.type) {
    case GeometryType::Box:
      m.type = visualization_msgs::Marker::CUBE;
      m.scale = toVector3Msg(g.box_size);
      break;
    case GeometryType::Cylinder:
      m.type = visualization_msgs::Marker::CYLINDER;
      m.scale = toVector3Msg(Eigen::Vector3d(2 * g.radius, 2 * g.radius, g.length));
      break;
    case GeometryType::Sphere:
      m.type = visualization_msgs::Marker::SPHERE;
      m.scale = toVector3Msg(Eigen::Vector3d::Constant(2 * g.radius));
      break;
    case GeometryType::Plane:
      // A thin slab just below the surface, so it does not hide what lies on it.
      m.type = visualization_msgs::Marker::CUBE;
      m.scale = toVector3Msg(Eigen::Vector3d(g.plane_size.x(), g.plane_size.y(), 0.001));
      pose = pose * Eigen::Translation3d(0, 0, -0.001);
      break;
    case GeometryType::Mesh:
      m.type = visualization_msgs::Marker::MESH_RESOURCE;
      m.mesh_resource = "file://" + g.mesh_file;
      m.scale = toVector3Msg(g.mesh_scale);
      break;
  }
  m.pose = toPoseMsg(pose);
  return m;
}

void appendModelMarkers(const PhysicsModel& model, const ros::Time& stamp, visualization_msgs::MarkerArray& out) {
  int id = 0;
  for (const LinkDescription& link : model.description().links) {
    if (!model.hasLink(link.name)) continue;
    const Eigen::Isometry3d link_pose = model.linkPose(link.name);
    for (const VisualShape& visual : link.visuals) {
      visualization_msgs::Marker m = visualMarker(visual, link_pose);
      m.header.frame_id = "world";
      m.header.stamp = stamp;
      m.ns = model.name();
      m.id = id++;
      out.markers.push_back(std::move(m));
    }
  }
}

void SceneMarkers::publish(bool force) {
  if (!publisher_.hasSubscribers()) return;
  const ros::WallTime now = ros::WallTime::now();
  if (!force && now - last_ < kMarkerPeriod) return;
  last_ = now;
  visualization_msgs::MarkerArray markers;
  visualization_msgs::Marker clear;  // models may have been deleted since the last message
  clear.action = visualization_msgs::Marker::DELETEALL;
  markers.markers.push_back(clear);
  const ros::Time stamp(world_.time());
  for (const std::string& name : world_.modelNames()) appendModelMarkers(*world_.findModel(name), stamp, markers);
  publisher_.publish(std::move(markers));
}

}  // namespace bullet_sim
