#include "observation_source.h"

#include <sensor_msgs/point_cloud2_iterator.h>
#include <tf2_geometry_msgs/tf2_geometry_msgs.h>

#include <algorithm>
#include <cmath>

#include "move_base/ros_params.h"

namespace move_base {

namespace nc = navigation_core;

namespace {

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

ObservationSource::ObservationSource(const std::string& name, const LayerContext& context,
                                     ros_params::Reader& params, double layer_max_obstacle_height)
    : context_(context), name_(name), topic_(name) {
  params.read("topic", &topic_);
  params.read("sensor_frame", &sensor_frame_);
  sensor_frame_ = frameId(sensor_frame_);
  params.read("data_type", &data_type_);
  params.read("expected_update_rate", &expected_update_rate_);
  params.read("observation_persistence", &observation_persistence_);
  params.read("inf_is_valid", &inf_is_valid_);
  params.read("min_obstacle_height", &options_.min_obstacle_height);
  params.read("max_obstacle_height", &options_.max_obstacle_height);
  options_.max_obstacle_height = std::min(layer_max_obstacle_height, options_.max_obstacle_height);
  params.read("marking", &options_.marking);
  options_.clearing = false;  // an observation source's default, unlike the layer options'
  params.read("clearing", &options_.clearing);
  params.search("obstacle_range", &options_.obstacle_range);
  params.search("raytrace_range", &options_.raytrace_range);
  if (!supported())
    ROS_ERROR("%s: \"%s\" is not supported here (expected LaserScan or PointCloud2); source %s is left out.",
              params.path("data_type").c_str(), data_type_.c_str(), name_.c_str());
}

void ObservationSource::subscribe() {
  ros::NodeHandle node;
  if (data_type_ == "LaserScan")
    subscriber_ = node.subscribe(topic_, 50, &ObservationSource::onScan, this);
  else
    subscriber_ = node.subscribe(topic_, 50, &ObservationSource::onCloud, this);
}

void ObservationSource::onScan(const sensor_msgs::LaserScanConstPtr& scan) {
  // As laser_geometry projects a scan: readings in [range_min, range_max); with inf_is_valid an
  // infinite reading (REP 117: nothing within range) becomes one just short of range_max, which
  // clears along its ray.
  const std::size_t n = scan->ranges.size();
  if (beams_.cos.size() != n || beams_.angle_min != scan->angle_min ||
      beams_.angle_increment != scan->angle_increment) {
    beams_.angle_min = scan->angle_min;
    beams_.angle_increment = scan->angle_increment;
    beams_.cos.resize(n);
    beams_.sin.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      const double a = scan->angle_min + i * scan->angle_increment;
      beams_.cos[i] = std::cos(a);
      beams_.sin[i] = std::sin(a);
    }
  }
  std::vector<nc::Point3> points;
  points.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    float r = scan->ranges[i];
    if (inf_is_valid_ && std::isinf(r) && r > 0) r = scan->range_max - 1e-4f;
    if (!(r >= scan->range_min && r < scan->range_max)) continue;
    points.push_back({r * beams_.cos[i], r * beams_.sin[i], 0.0});
  }
  queue(scan->header.frame_id, scan->header.stamp, std::move(points));
}

void ObservationSource::onCloud(const sensor_msgs::PointCloud2ConstPtr& cloud) {
  std::vector<nc::Point3> points;
  try {
    sensor_msgs::PointCloud2ConstIterator<float> x(*cloud, "x"), y(*cloud, "y"), z(*cloud, "z");
    for (; x != x.end(); ++x, ++y, ++z) points.push_back({*x, *y, *z});
  } catch (const std::exception& e) {
    ROS_ERROR_THROTTLE(5, "%s: a PointCloud2 on %s without float x, y, z fields: %s",
                       context_.nh.getNamespace().c_str(), topic_.c_str(), e.what());
    return;
  }
  queue(cloud->header.frame_id, cloud->header.stamp, std::move(points));
}

void ObservationSource::queue(const std::string& frame, const ros::Time& stamp, std::vector<nc::Point3> points) {
  std::lock_guard<std::mutex> guard(context_.mutex);
  last_message_ = ros::Time::now();
  pending_.push_back({frameId(sensor_frame_.empty() ? frame : sensor_frame_), stamp, std::move(points)});
  while (pending_.size() > 50) pending_.pop_front();
}

bool ObservationSource::isCurrent(const ros::Time& now) const {
  if (expected_update_rate_ <= 0) return true;
  const double silent = (now - last_message_).toSec();
  if (silent <= expected_update_rate_) return true;
  ROS_WARN_THROTTLE(2, "The %s observation buffer has not been updated for %.2f seconds, and it should be "
                    "updated every %.2f seconds.", topic_.c_str(), silent, expected_update_rate_);
  return false;
}

void ObservationSource::keep(const ros::Time& now) {
  const std::string& global_frame = context_.global_frame;
  nc::Observation observation;
  if (observation_persistence_ <= 0) {
    // Only the latest matters: the newest message whose transform has come, and nothing older.
    for (std::size_t k = pending_.size(); k-- > 0;) {
      if (!toGlobal(context_.tf, global_frame, pending_[k].frame, pending_[k].stamp, pending_[k].points, observation))
        continue;
      kept_.clear();
      kept_.emplace_back(pending_[k].stamp, std::move(observation));
      pending_.erase(pending_.begin(), pending_.begin() + static_cast<std::ptrdiff_t>(k) + 1);
      break;
    }
  } else {
    while (!pending_.empty() && toGlobal(context_.tf, global_frame, pending_.front().frame, pending_.front().stamp,
                                         pending_.front().points, observation)) {
      kept_.emplace_back(pending_.front().stamp, std::move(observation));
      pending_.pop_front();
    }
    while (!kept_.empty() && (now - kept_.front().first).toSec() > observation_persistence_) kept_.pop_front();
  }
  // What has waited longer than its transform can take is dropped, saying why.
  while (!pending_.empty() && (now - pending_.front().stamp).toSec() > 1.0 + context_.transform_tolerance) {
    const Raw& raw = pending_.front();
    try {
      context_.tf.lookupTransform(global_frame, raw.frame, raw.stamp);
    } catch (const tf2::TransformException& e) {
      ROS_WARN_THROTTLE(5, "%s: dropped an observation from %s (frame %s): %s", context_.nh.getNamespace().c_str(),
                        topic_.c_str(), raw.frame.c_str(), e.what());
    }
    pending_.pop_front();
  }
}

void ObservationSource::addTo(nc::LayeredCostmap& costmap, bool marking) const {
  nc::ObstacleLayerOptions pass = options_;
  (marking ? pass.clearing : pass.marking) = false;
  if (!(marking ? pass.marking : pass.clearing)) return;
  for (const auto& kept : kept_) costmap.addObservation(kept.second, pass);
}

}  // namespace move_base
