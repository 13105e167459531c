#include "move_base/costmap_ros.h"

#include <cmath>
#include <limits>
#include <optional>

#include <geometry_msgs/PolygonStamped.h>
#include <map_msgs/OccupancyGridUpdate.h>
#include <nav_msgs/OccupancyGrid.h>
#include <tf2/utils.h>

#include "move_base/costmap_plugins.h"
#include "move_base/layer_registry.h"
#include "move_base/ros_params.h"
#include "navigation_core/cost_values.h"

namespace move_base {

namespace nc = navigation_core;

namespace {

// costmap_2d's translation of costs to OccupancyGrid values.
std::int8_t occupancyOf(std::uint8_t cost) {
  if (cost == nc::kFreeSpace) return 0;
  if (cost == nc::kInscribedInflatedObstacle) return 99;
  if (cost == nc::kLethalObstacle) return 100;
  if (cost == nc::kNoInformation) return -1;
  return static_cast<std::int8_t>(1 + (97 * (cost - 1)) / 251);
}

double number(const XmlRpc::XmlRpcValue& v, const std::string& where) {
  if (v.getType() == XmlRpc::XmlRpcValue::TypeDouble) return static_cast<double>(v);
  if (v.getType() == XmlRpc::XmlRpcValue::TypeInt) return static_cast<int>(v);
  throw std::invalid_argument(where + ": expected a number");
}

// The `footprint` parameter as a list of [x, y] pairs or as its string form.
nc::Footprint footprintFrom(XmlRpc::XmlRpcValue& v, const std::string& where) {
  if (v.getType() == XmlRpc::XmlRpcValue::TypeString) {
    try {
      return nc::parseFootprint(static_cast<std::string>(v));
    } catch (const std::exception& e) {
      throw std::invalid_argument(where + ": " + e.what());
    }
  }
  if (v.getType() != XmlRpc::XmlRpcValue::TypeArray || v.size() < 3)
    throw std::invalid_argument(where + ": expected a list of at least three [x, y] points");
  nc::Footprint footprint;
  for (int i = 0; i < v.size(); ++i) {
    const std::string point = where + "[" + std::to_string(i) + "]";
    if (v[i].getType() != XmlRpc::XmlRpcValue::TypeArray || v[i].size() != 2)
      throw std::invalid_argument(point + ": expected a point [x, y]");
    footprint.push_back({number(v[i][0], point), number(v[i][1], point)});
  }
  return footprint;
}

}  // namespace

CostmapROS::CostmapROS(const std::string& name, tf2_ros::Buffer& tf) : name_(name), tf_(tf), nh_("~" + name) {
  // Only wrong types are said here: the namespace also holds the layers' and pre-Hydro names.
  ros_params::Reader params(nh_);
  params.read("global_frame", &global_frame_);
  params.read("robot_base_frame", &base_frame_);
  global_frame_ = frameId(global_frame_);
  base_frame_ = frameId(base_frame_);
  params.read("transform_tolerance", &transform_tolerance_);
  params.read("update_frequency", &update_frequency_);
  params.read("publish_frequency", &publish_frequency_);
  params.read("rolling_window", &rolling_window_);
  params.read("always_send_full_costmap", &always_send_full_costmap_);

  params.read("width", &options_.width);
  params.read("height", &options_.height);
  params.read("resolution", &options_.resolution);
  params.read("origin_x", &options_.origin_x);
  params.read("origin_y", &options_.origin_y);
  options_.rolling_window = rolling_window_;
  params.read("track_unknown_space", &options_.track_unknown_space);

  // The footprint, searched for up the namespaces as costmap_2d does.
  XmlRpc::XmlRpcValue footprint;
  if (params.search("footprint", &footprint)) {
    try {
      footprint_ = footprintFrom(footprint, params.searchPath("footprint"));
    } catch (const std::exception& e) {
      ROS_ERROR("%s. Using robot_radius instead.", e.what());
    }
  }
  double robot_radius = 0.46, padding = 0.01;
  params.search("robot_radius", &robot_radius);
  params.search("footprint_padding", &padding);
  if (footprint_.empty()) footprint_ = nc::footprintFromRadius(robot_radius);
  footprint_ = nc::padFootprint(footprint_, padding);
  circumscribed_radius_ = nc::footprintRadii(footprint_).circumscribed;

  // Before the layers: what a costmap without an obstacle or inflation layer has.
  options_.obstacle_track_unknown_space = true;  // an all-unknown grid adds nothing
  options_.footprint_clearing_enabled = false;   // nor clears anything
  options_.inflate = false;
  for (const nc::LayerSpec& layer : costmapPlugins(nh_, params)) addLayer(layer);
  for (const std::string& problem : params.problemList()) ROS_ERROR("%s; using the default.", problem.c_str());
  layers_ = std::make_unique<nc::LayeredCostmap>(options_, footprint_);

  // As Costmap2DROS: nothing runs until tf knows where the robot is.
  std::string tf_error;
  while (ros::ok() && !tf_.canTransform(global_frame_, base_frame_, ros::Time(), ros::Duration(0.1), &tf_error)) {
    ROS_WARN_THROTTLE(5, "Timed out waiting for transform from %s to %s to become available before running costmap, "
                      "tf error: %s", base_frame_.c_str(), global_frame_.c_str(), tf_error.c_str());
    tf_error.clear();
  }

  costmap_pub_ = nh_.advertise<nav_msgs::OccupancyGrid>("costmap", 1, true);
  updates_pub_ = nh_.advertise<map_msgs::OccupancyGridUpdate>("costmap_updates", 1);
  footprint_pub_ = nh_.advertise<geometry_msgs::PolygonStamped>("footprint", 1);
  for (const auto& plugin : plugins_) plugin->start(*layers_);  // the costmap exists: its layers may feed it
  if (update_frequency_ <= 0)
    ROS_WARN("%s/update_frequency is %g: the costmap will not be updated.", nh_.getNamespace().c_str(), update_frequency_);
  thread_ = std::thread([this] { updateLoop(); });
}

CostmapROS::~CostmapROS() {
  running_ = false;
  if (thread_.joinable()) thread_.join();
}

void CostmapROS::addLayer(const nc::LayerSpec& spec) {
  ros_params::Reader params(ros::NodeHandle(nh_, spec.name));
  if (!params.get("enabled", true)) return;
  std::unique_ptr<CostmapLayer> plugin = makeLayer(spec.type);
  if (!plugin) {
    std::string known;
    for (const std::string& type : layerTypes()) known += (known.empty() ? "" : ", ") + type;
    ROS_ERROR("%s/plugins: layer %s has type %s, which this move_base does not have (it has %s); the layer is left "
              "out.", nh_.getNamespace().c_str(), spec.name.c_str(), spec.type.c_str(), known.c_str());
    return;
  }
  contexts_.push_back(LayerContext{spec.name, ros::NodeHandle(nh_, spec.name), tf_, global_frame_, transform_tolerance_,
                                   rolling_window_, options_, mutex_, kinds_seen_});
  plugin->configure(contexts_.back(), params);
  reportParams(params);
  plugins_.push_back(std::move(plugin));
}

bool CostmapROS::isCurrent() const {
  std::lock_guard<std::mutex> guard(mutex_);
  const ros::Time now = ros::Time::now();
  bool current = true;
  for (const auto& plugin : plugins_) current = plugin->isCurrent(now) && current;  // each says what is silent
  return current;
}

bool CostmapROS::waitingForMap() const {
  std::lock_guard<std::mutex> guard(mutex_);
  for (const auto& plugin : plugins_)
    if (plugin->waitingForMap()) return true;
  return false;
}

bool CostmapROS::robotPose(nc::Pose2& pose) const {
  geometry_msgs::TransformStamped t;
  try {
    t = tf_.lookupTransform(global_frame_, base_frame_, ros::Time(0));
  } catch (const tf2::TransformException& e) {
    ROS_WARN_THROTTLE(2, "%s: no transform from %s to %s yet: %s", nh_.getNamespace().c_str(), base_frame_.c_str(),
                      global_frame_.c_str(), e.what());
    return false;
  }
  const ros::Time now = ros::Time::now();
  if (!t.header.stamp.isZero() && (now - t.header.stamp).toSec() > transform_tolerance_) {
    ROS_WARN_THROTTLE(2, "Costmap2DROS transform timeout. Current time: %.4f, global_pose stamp: %.4f, tolerance: %.4f",
                      now.toSec(), t.header.stamp.toSec(), transform_tolerance_);
    return false;
  }
  pose.x = t.transform.translation.x;
  pose.y = t.transform.translation.y;
  pose.theta = tf2::getYaw(t.transform.rotation);
  return true;
}

void CostmapROS::resetObstacles() {
  std::lock_guard<std::mutex> guard(mutex_);
  layers_->resetObstacles();
  layers_->update();
}

void CostmapROS::resetObstaclesOutside(double x, double y, double size) {
  std::lock_guard<std::mutex> guard(mutex_);
  layers_->resetObstaclesOutside(x, y, size);
  layers_->update();
}

void CostmapROS::updateLoop() {
  if (update_frequency_ <= 0) return;
  ros::Rate rate(update_frequency_);
  ros::Time next_publish;
  unsigned last_x = 0, last_y = 0;
  double last_ox = std::numeric_limits<double>::quiet_NaN(), last_oy = last_ox;
  while (running_ && ros::ok()) {
    bool full = false;
    {
      std::lock_guard<std::mutex> guard(mutex_);
      updateMap();
      const nc::Costmap& c = layers_->master();
      full = always_send_full_costmap_ || c.sizeX() != last_x || c.sizeY() != last_y || c.originX() != last_ox ||
             c.originY() != last_oy;
      if (publish_frequency_ > 0 && ros::Time::now() >= next_publish) {
        publishCostmap(full);
        last_x = c.sizeX(), last_y = c.sizeY(), last_ox = c.originX(), last_oy = c.originY();
        next_publish = ros::Time::now() + ros::Duration(1.0 / publish_frequency_);
      }
    }
    if (!rate.sleep()) rate.reset();  // a jump in sim time: start the cycle anew
  }
}

void CostmapROS::updateMap() {
  nc::Pose2 pose;
  const bool have_pose = robotPose(pose);
  if (rolling_window_) {
    if (!have_pose) return;  // a rolling window needs to know where to be
    layers_->updateOrigin(pose.x, pose.y);
  }
  const ros::Time now = ros::Time::now();
  for (const auto& plugin : plugins_) plugin->prepare(now);
  for (const bool marking : {false, true})
    for (const auto& plugin : plugins_) plugin->addObservations(*layers_, marking);
  layers_->update(have_pose ? std::optional<nc::Pose2>(pose) : std::nullopt);
  if (have_pose) publishFootprint(pose);
}

void CostmapROS::publishCostmap(bool full) {
  const nc::Costmap& c = layers_->master();
  std::vector<std::int8_t> data(c.costs().size());
  for (std::size_t i = 0; i < data.size(); ++i) data[i] = occupancyOf(c.costs()[i]);
  const ros::Time now = ros::Time::now();
  // The whole grid, latched, for late subscribers; to those of the updates topic, the whole grid
  // as an update when its geometry has not changed.
  if (!full && updates_pub_.getNumSubscribers() > 0) {
    map_msgs::OccupancyGridUpdate update;
    update.header.frame_id = global_frame_;
    update.header.stamp = now;
    update.width = c.sizeX();
    update.height = c.sizeY();
    update.data = data;
    updates_pub_.publish(update);
  }
  {
    nav_msgs::OccupancyGrid grid;
    grid.header.frame_id = global_frame_;
    grid.header.stamp = now;
    grid.info.map_load_time = now;
    grid.info.resolution = static_cast<float>(c.resolution());
    grid.info.width = c.sizeX();
    grid.info.height = c.sizeY();
    grid.info.origin.position.x = c.originX();
    grid.info.origin.position.y = c.originY();
    grid.info.origin.orientation.w = 1.0;
    grid.data = std::move(data);
    costmap_pub_.publish(grid);
  }
}

void CostmapROS::publishFootprint(const nc::Pose2& pose) {
  geometry_msgs::PolygonStamped polygon;
  polygon.header.frame_id = global_frame_;
  polygon.header.stamp = ros::Time::now();
  const double c = std::cos(pose.theta), s = std::sin(pose.theta);
  for (const nc::Point2& p : footprint_) {
    geometry_msgs::Point32 q;
    q.x = static_cast<float>(pose.x + c * p.x - s * p.y);
    q.y = static_cast<float>(pose.y + s * p.x + c * p.y);
    polygon.polygon.points.push_back(q);
  }
  footprint_pub_.publish(polygon);
}

}  // namespace move_base
