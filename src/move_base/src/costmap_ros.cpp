#include "move_base/costmap_ros.h"

#include <cmath>
#include <limits>
#include <optional>
#include <set>
#include <sstream>

#include <geometry_msgs/PolygonStamped.h>
#include <sensor_msgs/point_cloud2_iterator.h>
#include <tf2/utils.h>
#include <tf2_geometry_msgs/tf2_geometry_msgs.h>

#include "move_base/ros_params.h"
#include "navigation_core/cost_values.h"
#include "navigation_core/legacy_costmap_params.h"

namespace move_base {

namespace nc = navigation_core;

struct CostmapROS::Source {
  std::string name, topic, sensor_frame, data_type;
  double expected_update_rate = 0.0;
  double observation_persistence = 0.0;
  bool inf_is_valid = false;
  nc::ObstacleLayerOptions options;
  ros::Time last_message;
  struct Raw {
    std::string frame;
    ros::Time stamp;
    std::vector<nc::Point3> points;  // in `frame`
  };
  std::deque<Raw> pending;  // waiting for their transform
  // A LaserScan's beam directions, kept while the scans' angles stay the same.
  struct BeamDirections {
    float angle_min = 0.0f, angle_increment = 0.0f;
    std::vector<double> cos, sin;
  } beams;
  // What each update applies, in the costmap's frame: as costmap_2d's observation buffer, the
  // latest observation when observation_persistence is 0, else those of the last that many seconds.
  std::deque<std::pair<ros::Time, nc::Observation>> kept;
};

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
  if (v.getType() == XmlRpc::XmlRpcValue::TypeString) return nc::parseFootprint(static_cast<std::string>(v));
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

// Points seen from `frame` at `stamp` in the costmap's global frame, with the sensor's origin;
// false while tf cannot tell where the sensor was then.
bool toGlobal(const tf2_ros::Buffer& tf, const std::string& global_frame, const std::string& frame,
              const ros::Time& stamp, const std::vector<nc::Point3>& points, nc::Observation& observation) {
  if (!tf.canTransform(global_frame, frame, stamp)) return false;
  geometry_msgs::TransformStamped t;
  try {
    t = tf.lookupTransform(global_frame, frame, stamp);
  } catch (const tf2::TransformException&) {
    return false;
  }
  tf2::Transform to_global;
  tf2::fromMsg(t.transform, to_global);
  const tf2::Vector3 origin = to_global * tf2::Vector3(0, 0, 0);
  observation.origin = {origin.x(), origin.y(), origin.z()};
  observation.points.clear();
  observation.points.reserve(points.size());
  for (const nc::Point3& p : points) {
    const tf2::Vector3 g = to_global * tf2::Vector3(p.x, p.y, p.z);
    observation.points.push_back({g.x(), g.y(), g.z()});
  }
  return true;
}

}  // namespace

CostmapROS::CostmapROS(const std::string& name, tf2_ros::Buffer& tf) : name_(name), tf_(tf), nh_("~" + name) {
  global_frame_ = frameId(param<std::string>(nh_, "global_frame", "map"));
  base_frame_ = frameId(param<std::string>(nh_, "robot_base_frame", "base_link"));
  transform_tolerance_ = param(nh_, "transform_tolerance", 0.3);
  update_frequency_ = param(nh_, "update_frequency", 5.0);
  publish_frequency_ = param(nh_, "publish_frequency", 0.0);
  rolling_window_ = param(nh_, "rolling_window", false);
  always_send_full_costmap_ = param(nh_, "always_send_full_costmap", false);

  options_.width = param(nh_, "width", 10.0);
  options_.height = param(nh_, "height", 10.0);
  options_.resolution = param(nh_, "resolution", 0.05);
  options_.origin_x = param(nh_, "origin_x", 0.0);
  options_.origin_y = param(nh_, "origin_y", 0.0);
  options_.rolling_window = rolling_window_;
  options_.track_unknown_space = param(nh_, "track_unknown_space", false);

  // The footprint, searched for up the namespaces as costmap_2d does.
  std::string found;
  XmlRpc::XmlRpcValue footprint;
  if (nh_.searchParam("footprint", found) && ros::param::get(found, footprint)) {
    try {
      footprint_ = footprintFrom(footprint, found);
    } catch (const std::exception& e) {
      ROS_ERROR("%s: %s. Using robot_radius instead.", found.c_str(), e.what());
    }
  }
  if (footprint_.empty()) footprint_ = nc::footprintFromRadius(searchParam(nh_, "robot_radius", 0.46));
  footprint_ = nc::padFootprint(footprint_, searchParam(nh_, "footprint_padding", 0.01));
  circumscribed_radius_ = nc::footprintRadii(footprint_).circumscribed;

  readLayers();
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
  if (update_frequency_ <= 0)
    ROS_WARN("%s/update_frequency is %g: the costmap will not be updated.", nh_.getNamespace().c_str(), update_frequency_);
  thread_ = std::thread([this] { updateLoop(); });
}

CostmapROS::~CostmapROS() {
  running_ = false;
  if (thread_.joinable()) thread_.join();
}

void CostmapROS::readLayers() {
  XmlRpc::XmlRpcValue plugins;
  std::vector<std::pair<std::string, std::string>> layers;  // name, type
  if (nh_.getParam("plugins", plugins)) {
    if (plugins.getType() != XmlRpc::XmlRpcValue::TypeArray) {
      ROS_ERROR("%s/plugins: expected a list of {name: ..., type: ...}; the costmap has no layers.",
                nh_.getNamespace().c_str());
    } else {
      for (int i = 0; i < plugins.size(); ++i) {
        if (plugins[i].getType() != XmlRpc::XmlRpcValue::TypeStruct || !plugins[i].hasMember("name") ||
            !plugins[i].hasMember("type")) {
          ROS_ERROR("%s/plugins[%d]: expected {name: ..., type: ...}; skipped.", nh_.getNamespace().c_str(), i);
          continue;
        }
        layers.emplace_back(static_cast<std::string>(plugins[i]["name"]), static_cast<std::string>(plugins[i]["type"]));
      }
    }
  } else {
    // Pre-Hydro parameters: moved into the layers' namespaces as costmap_2d moves them.
    std::vector<std::string> names;
    std::set<std::string> present;
    ros::param::getParamNames(names);
    const std::string prefix = nh_.getNamespace() + "/";
    for (const std::string& n : names)
      if (n.compare(0, prefix.size(), prefix) == 0) present.insert(n.substr(prefix.size(), n.find('/', prefix.size()) - prefix.size()));
    const nc::LegacyCostmapTranslation t = nc::translateLegacyCostmapParams(
        present, param(nh_, "static_map", false), param<std::string>(nh_, "map_type", ""),
        param<std::string>(nh_, "observation_sources", ""));
    for (const nc::ParamMove& m : t.moves) {
      XmlRpc::XmlRpcValue value;
      if (!nh_.getParam(m.from, value)) continue;
      nh_.setParam(m.to, value);
      if (!m.keep_original) nh_.deleteParam(m.from);
    }
    for (const nc::LayerSpec& l : t.plugins) layers.emplace_back(l.name, l.type);
  }

  bool have_obstacle_layer = false, have_inflation = false;
  for (const auto& [layer_name, type] : layers) {
    const ros::NodeHandle layer_nh(nh_, layer_name);
    if (!param(layer_nh, "enabled", true)) continue;
    if (type == "costmap_2d::StaticLayer") {
      has_static_layer_ = true;
      static_options_.track_unknown_space = param(layer_nh, "track_unknown_space", true);
      static_options_.unknown_cost_value = param(layer_nh, "unknown_cost_value", -1);
      static_options_.lethal_cost_threshold = param(layer_nh, "lethal_cost_threshold", 100);
      static_options_.trinary_costmap = param(layer_nh, "trinary_costmap", true);
      first_map_only_ = param(layer_nh, "first_map_only", false);
      if (param(layer_nh, "use_maximum", false))
        ROS_WARN("%s/use_maximum: not supported; the static map is written over the costmap.",
                 layer_nh.getNamespace().c_str());
      const std::string topic = param<std::string>(layer_nh, "map_topic", "map");
      ros::NodeHandle node;
      subscribers_.push_back(node.subscribe(topic, 1, &CostmapROS::onMap, this));
      if (param(layer_nh, "subscribe_to_updates", false))
        subscribers_.push_back(node.subscribe(topic + "_updates", 10, &CostmapROS::onMapUpdate, this));
    } else if (type == "costmap_2d::ObstacleLayer" || type == "costmap_2d::VoxelLayer") {
      if (type == "costmap_2d::VoxelLayer")
        ROS_WARN("%s: a costmap_2d::VoxelLayer is run as an obstacle layer (its columns flattened to 2D cells).",
                 layer_nh.getNamespace().c_str());
      readObstacleLayer(layer_nh, !have_obstacle_layer);
      have_obstacle_layer = true;
    } else if (type == "costmap_2d::InflationLayer") {
      have_inflation = true;
      options_.inflation.inflation_radius = param(layer_nh, "inflation_radius", 0.55);
      options_.inflation.cost_scaling_factor = param(layer_nh, "cost_scaling_factor", 10.0);
      options_.inflation.inflate_unknown = param(layer_nh, "inflate_unknown", false);
    } else {
      ROS_ERROR("%s/plugins: layer %s has type %s, which this move_base does not have (it has "
                "costmap_2d::StaticLayer, costmap_2d::ObstacleLayer, costmap_2d::VoxelLayer and "
                "costmap_2d::InflationLayer); the layer is left out.",
                nh_.getNamespace().c_str(), layer_name.c_str(), type.c_str());
    }
  }
  options_.inflate = have_inflation;
  if (!have_obstacle_layer) {
    options_.obstacle_track_unknown_space = true;  // an all-unknown grid adds nothing
    options_.footprint_clearing_enabled = false;   // nor clears anything
  }
}

void CostmapROS::readObstacleLayer(const ros::NodeHandle& layer_nh, bool first) {
  if (first) {
    options_.obstacle_track_unknown_space = param(layer_nh, "track_unknown_space", options_.track_unknown_space);
    options_.footprint_clearing_enabled = param(layer_nh, "footprint_clearing_enabled", true);
  }
  const double layer_max_height = param(layer_nh, "max_obstacle_height", 2.0);
  std::istringstream names(param<std::string>(layer_nh, "observation_sources", ""));
  std::string source_name;
  while (names >> source_name) {
    const ros::NodeHandle source_nh(layer_nh, source_name);
    auto source = std::make_unique<Source>();
    Source& s = *source;
    s.name = source_name;
    s.topic = param<std::string>(source_nh, "topic", source_name);
    s.sensor_frame = frameId(param<std::string>(source_nh, "sensor_frame", ""));
    s.data_type = param<std::string>(source_nh, "data_type", "PointCloud");
    s.expected_update_rate = param(source_nh, "expected_update_rate", 0.0);
    s.observation_persistence = param(source_nh, "observation_persistence", 0.0);
    s.inf_is_valid = param(source_nh, "inf_is_valid", false);
    s.options.min_obstacle_height = param(source_nh, "min_obstacle_height", 0.0);
    s.options.max_obstacle_height = std::min(layer_max_height, param(source_nh, "max_obstacle_height", 2.0));
    s.options.marking = param(source_nh, "marking", true);
    s.options.clearing = param(source_nh, "clearing", false);
    s.options.obstacle_range = searchParam(source_nh, "obstacle_range", 2.5);
    s.options.raytrace_range = searchParam(source_nh, "raytrace_range", 3.0);
    ros::NodeHandle node;
    if (s.data_type == "LaserScan") {
      subscribers_.push_back(node.subscribe<sensor_msgs::LaserScan>(
          s.topic, 50, [this, &s](const sensor_msgs::LaserScanConstPtr& m) { onScan(s, m); }));
    } else if (s.data_type == "PointCloud2") {
      subscribers_.push_back(node.subscribe<sensor_msgs::PointCloud2>(
          s.topic, 50, [this, &s](const sensor_msgs::PointCloud2ConstPtr& m) { onCloud(s, m); }));
    } else {
      ROS_ERROR("%s/data_type: \"%s\" is not supported here (expected LaserScan or PointCloud2); source %s is "
                "left out.", source_nh.getNamespace().c_str(), s.data_type.c_str(), source_name.c_str());
      continue;
    }
    ROS_INFO("%s: observation source %s (%s on %s).", nh_.getNamespace().c_str(), source_name.c_str(),
             s.data_type.c_str(), s.topic.c_str());
    sources_.push_back(std::move(source));
  }
}

void CostmapROS::onMap(const nav_msgs::OccupancyGridConstPtr& map) {
  std::lock_guard<std::mutex> guard(mutex_);
  if (first_map_only_ && have_map_) return;
  const auto& info = map->info;
  if (map->data.size() != static_cast<std::size_t>(info.width) * info.height || info.resolution <= 0) {
    ROS_ERROR("%s: the map on its map_topic is malformed (%zu values for %u x %u cells, resolution %g); ignored.",
              nh_.getNamespace().c_str(), map->data.size(), info.width, info.height, info.resolution);
    return;
  }
  if (std::abs(tf2::getYaw(info.origin.orientation)) > 1e-3)
    ROS_WARN_ONCE("%s: the map's origin is rotated; the rotation is ignored, as costmap_2d does.",
                  nh_.getNamespace().c_str());
  map_ = *map;
  map_frame_ = frameId(map->header.frame_id);
  if (!rolling_window_ && !map_frame_.empty() && map_frame_ != global_frame_)
    ROS_WARN_THROTTLE(10, "%s: the map is in frame %s, the costmap's global_frame is %s; the map is used as if "
                      "it were in %s.", nh_.getNamespace().c_str(), map_frame_.c_str(), global_frame_.c_str(),
                      global_frame_.c_str());
  layers_->setStaticMap(nc::staticCostmap(map_.data, info.width, info.height, info.resolution, info.origin.position.x,
                                          info.origin.position.y, static_options_));
  have_map_ = true;
}

void CostmapROS::onMapUpdate(const map_msgs::OccupancyGridUpdateConstPtr& update) {
  std::lock_guard<std::mutex> guard(mutex_);
  if (!have_map_ || (first_map_only_ && have_map_)) return;
  const auto& info = map_.info;
  if (update->x < 0 || update->y < 0 || update->x + update->width > info.width ||
      update->y + update->height > info.height ||
      update->data.size() != static_cast<std::size_t>(update->width) * update->height) {
    ROS_ERROR("%s: a map update outside the map or malformed; ignored.", nh_.getNamespace().c_str());
    return;
  }
  for (unsigned y = 0; y < update->height; ++y)
    for (unsigned x = 0; x < update->width; ++x)
      map_.data[(update->y + y) * info.width + update->x + x] = update->data[y * update->width + x];
  layers_->setStaticMap(nc::staticCostmap(map_.data, info.width, info.height, info.resolution, info.origin.position.x,
                                          info.origin.position.y, static_options_));
}

void CostmapROS::onScan(Source& source, const sensor_msgs::LaserScanConstPtr& scan) {
  // As laser_geometry projects a scan: readings in [range_min, range_max); with inf_is_valid an
  // infinite reading (REP 117: nothing within range) becomes one just short of range_max, which
  // clears along its ray.
  Source::BeamDirections& beams = source.beams;
  const std::size_t n = scan->ranges.size();
  if (beams.cos.size() != n || beams.angle_min != scan->angle_min || beams.angle_increment != scan->angle_increment) {
    beams.angle_min = scan->angle_min;
    beams.angle_increment = scan->angle_increment;
    beams.cos.resize(n);
    beams.sin.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      const double a = scan->angle_min + i * scan->angle_increment;
      beams.cos[i] = std::cos(a);
      beams.sin[i] = std::sin(a);
    }
  }
  std::vector<nc::Point3> points;
  points.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    float r = scan->ranges[i];
    if (source.inf_is_valid && std::isinf(r) && r > 0) r = scan->range_max - 1e-4f;
    if (!(r >= scan->range_min && r < scan->range_max)) continue;
    points.push_back({r * beams.cos[i], r * beams.sin[i], 0.0});
  }
  queue(source, scan->header.frame_id, scan->header.stamp, std::move(points));
}

void CostmapROS::onCloud(Source& source, const sensor_msgs::PointCloud2ConstPtr& cloud) {
  std::vector<nc::Point3> points;
  try {
    sensor_msgs::PointCloud2ConstIterator<float> x(*cloud, "x"), y(*cloud, "y"), z(*cloud, "z");
    for (; x != x.end(); ++x, ++y, ++z) points.push_back({*x, *y, *z});
  } catch (const std::exception& e) {
    ROS_ERROR_THROTTLE(5, "%s: a PointCloud2 on %s without float x, y, z fields: %s", nh_.getNamespace().c_str(),
                       source.topic.c_str(), e.what());
    return;
  }
  queue(source, cloud->header.frame_id, cloud->header.stamp, std::move(points));
}

void CostmapROS::queue(Source& source, const std::string& frame, const ros::Time& stamp,
                       std::vector<nc::Point3> points) {
  std::lock_guard<std::mutex> guard(mutex_);
  source.last_message = ros::Time::now();
  source.pending.push_back({frameId(source.sensor_frame.empty() ? frame : source.sensor_frame), stamp, std::move(points)});
  while (source.pending.size() > 50) source.pending.pop_front();
}

bool CostmapROS::isCurrent() const {
  std::lock_guard<std::mutex> guard(mutex_);
  const ros::Time now = ros::Time::now();
  bool current = true;
  for (const auto& s : sources_) {
    if (s->expected_update_rate <= 0) continue;
    const double silent = (now - s->last_message).toSec();
    if (silent > s->expected_update_rate) {
      ROS_WARN_THROTTLE(2, "The %s observation buffer has not been updated for %.2f seconds, and it should be "
                        "updated every %.2f seconds.", s->topic.c_str(), silent, s->expected_update_rate);
      current = false;
    }
  }
  return current;
}

bool CostmapROS::waitingForMap() const {
  std::lock_guard<std::mutex> guard(mutex_);
  return has_static_layer_ && !have_map_;
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

void CostmapROS::keepObservations(Source& s, const ros::Time& now) {
  nc::Observation observation;
  if (s.observation_persistence <= 0) {
    // Only the latest matters: the newest message whose transform has come, and nothing older.
    for (std::size_t k = s.pending.size(); k-- > 0;) {
      if (!toGlobal(tf_, global_frame_, s.pending[k].frame, s.pending[k].stamp, s.pending[k].points, observation)) continue;
      s.kept.clear();
      s.kept.emplace_back(s.pending[k].stamp, std::move(observation));
      s.pending.erase(s.pending.begin(), s.pending.begin() + static_cast<std::ptrdiff_t>(k) + 1);
      break;
    }
  } else {
    while (!s.pending.empty() && toGlobal(tf_, global_frame_, s.pending.front().frame, s.pending.front().stamp,
                                                 s.pending.front().points, observation)) {
      s.kept.emplace_back(s.pending.front().stamp, std::move(observation));
      s.pending.pop_front();
    }
    while (!s.kept.empty() && (now - s.kept.front().first).toSec() > s.observation_persistence) s.kept.pop_front();
  }
  // What has waited longer than its transform can take is dropped, saying why.
  while (!s.pending.empty() && (now - s.pending.front().stamp).toSec() > 1.0 + transform_tolerance_) {
    const Source::Raw& raw = s.pending.front();
    try {
      tf_.lookupTransform(global_frame_, raw.frame, raw.stamp);
    } catch (const tf2::TransformException& e) {
      ROS_WARN_THROTTLE(5, "%s: dropped an observation from %s (frame %s): %s", nh_.getNamespace().c_str(),
                        s.topic.c_str(), raw.frame.c_str(), e.what());
    }
    s.pending.pop_front();
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
  for (auto& s : sources_) keepObservations(*s, now);
  // As costmap_2d's obstacle layer: every source's clearing first, then every source's marking, so
  // that one sensor's free rays do not erase what another (or an older kept message) saw.
  for (const bool marking : {false, true}) {
    for (const auto& s : sources_) {
      nc::ObstacleLayerOptions pass = s->options;
      (marking ? pass.clearing : pass.marking) = false;
      if (!(marking ? pass.marking : pass.clearing)) continue;
      for (const auto& kept : s->kept) layers_->addObservation(kept.second, pass);
    }
  }
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
