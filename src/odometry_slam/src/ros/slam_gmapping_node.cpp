#include "odometry_slam/ros/slam_gmapping_node.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <std_msgs/Float64.h>
#include <tf2/LinearMath/Transform.h>
#include <tf2/utils.h>
#include <tf2_geometry_msgs/tf2_geometry_msgs.h>

#include "hector_style_mapping/ros/scan_conversion.h"
#include "hector_style_mapping/ros/scan_input.h"

namespace odometry_slam {
namespace {

namespace hsm = hector_style_mapping;

// How long a scan may wait for the tf it needs.
const ros::Duration kTfWait(0.1);

GmappingOptions loadOrThrow(const ros::NodeHandle& private_nh) {
  GmappingOptions options;
  const std::string problems = loadGmappingOptions(private_nh, &options);
  if (!problems.empty()) throw std::invalid_argument(problems);
  return options;
}

// Beams beyond `usable` (from the laser) become free rays cut to that length.
void cutToUsableRange(double usable, ScanPoints* scan) {
  scan->free_rays.clear();
  auto kept = scan->points.begin();
  for (const Eigen::Vector2d& point : scan->points) {
    const Eigen::Vector2d ray = point - scan->origin;
    const double length = ray.norm();
    if (length > usable) scan->free_rays.push_back(scan->origin + ray * (usable / length));
    else *kept++ = point;
  }
  scan->points.erase(kept, scan->points.end());
}

}  // namespace

SlamGmappingNode::SlamGmappingNode(ros::NodeHandle nh, ros::NodeHandle private_nh)
    : options_(loadOrThrow(private_nh)),
      nh_(nh),
      private_nh_(private_nh),
      slam_(options_.slam),
      tf_buffer_(ros::Duration(30.0)),
      tf_listener_(tf_buffer_) {
  for (const std::string& name : unknownGmappingParameters(private_nh_))
    ROS_WARN("slam_gmapping: ignored %s: not a parameter of slam_gmapping", name.c_str());
  if (!options_.particle_filter_parameters_set.empty()) {
    std::string names;
    for (const std::string& name : options_.particle_filter_parameters_set) names += (names.empty() ? "" : ", ") + name;
    ROS_INFO("slam_gmapping: %s: parameters of gmapping's particle filter, which this slam_gmapping does not "
             "have (it refines the odometry by scan matching; see odometry_slam's README); ignored", names.c_str());
  }

  scan_subscriber_ = nh_.subscribe("scan", 5, &SlamGmappingNode::scanCallback, this);
  map_publisher_ = nh_.advertise<nav_msgs::OccupancyGrid>("map", 1, true);
  map_metadata_publisher_ = nh_.advertise<nav_msgs::MapMetaData>("map_metadata", 1, true);
  entropy_publisher_ = private_nh_.advertise<std_msgs::Float64>("entropy", 1, true);
  dynamic_map_service_ = nh_.advertiseService("dynamic_map", &SlamGmappingNode::dynamicMapService, this);
  if (options_.transform_publish_period > 0.0)
    transform_timer_ = nh_.createTimer(ros::Duration(options_.transform_publish_period),
                                       [this](const ros::TimerEvent&) { publishTransform(); });

  const OdometrySlamOptions& s = options_.slam;
  const hsm::OccupancyGridMap& finest = slam_.map().finest();
  ROS_INFO("slam_gmapping: %d x %d cells of %.3f m over x %.1f .. %.1f, y %.1f .. %.1f m; a scan every %.2f m, "
           "%.2f rad%s; scans on %s; tf %s -> %s from %s -> %s", finest.sizeX(), finest.sizeY(), s.delta, s.xmin,
           s.xmax, s.ymin, s.ymax, s.linear_update, s.angular_update,
           s.temporal_update >= 0.0 ? (" or " + std::to_string(s.temporal_update) + " s").c_str() : "",
           scan_subscriber_.getTopic().c_str(), options_.map_frame.c_str(), options_.odom_frame.c_str(),
           options_.odom_frame.c_str(), options_.base_frame.c_str());
}

bool SlamGmappingNode::acceptStamp(const ros::Time& stamp) {
  const ros::Time previous = scan_stamps_.last();
  switch (scan_stamps_.accept(stamp)) {
    case hsm::StampOrder::kNewer:
      return true;
    case hsm::StampOrder::kClockRestarted:
      ROS_WARN("slam_gmapping: time went back %.3f s (from %.3f to %.3f; a simulator or bag restart?): tf buffer "
               "cleared, mapping goes on in the same map", (previous - stamp).toSec(), previous.toSec(),
               stamp.toSec());
      tf_buffer_.clear();
      last_map_stamp_ = last_transform_stamp_ = ros::Time();
      return true;
    case hsm::StampOrder::kStale:
      break;
  }
  ROS_WARN_THROTTLE(5.0, "slam_gmapping: scan stamped %.6f is not newer than the last one (%.6f): dropped",
                    stamp.toSec(), previous.toSec());
  return false;
}

bool SlamGmappingNode::laserInBase(const sensor_msgs::LaserScan& scan, Eigen::Isometry3d* laser_in_base) {
  try {
    const geometry_msgs::TransformStamped t =
        tf_buffer_.lookupTransform(options_.base_frame, scan.header.frame_id, scan.header.stamp, kTfWait);
    *laser_in_base = hsm::isometryOf(t.transform);
    return true;
  } catch (const tf2::TransformException& e) {
    ROS_WARN_THROTTLE(5.0, "slam_gmapping: no tf from base_frame '%s' to the scan's frame '%s' at %.3f: %s. Scan "
                      "skipped. (Is robot_state_publisher or a static_transform_publisher running?)",
                      options_.base_frame.c_str(), scan.header.frame_id.c_str(), scan.header.stamp.toSec(), e.what());
    return false;
  }
}

std::optional<Pose2D> SlamGmappingNode::odometryAt(const ros::Time& stamp) {
  try {
    const geometry_msgs::TransformStamped t =
        tf_buffer_.lookupTransform(options_.odom_frame, options_.base_frame, stamp, kTfWait);
    return Pose2D{t.transform.translation.x, t.transform.translation.y, tf2::getYaw(t.transform.rotation)};
  } catch (const tf2::TransformException& e) {
    ROS_WARN_THROTTLE(5.0, "slam_gmapping: needs the robot's odometry as tf %s -> %s (~odom_frame -> ~base_frame), "
                      "and there is none at %.3f: %s. Scans are skipped until it comes. (Does the robot's driver "
                      "or simulator publish odometry tf? Are ~odom_frame and ~base_frame its frame names?)",
                      options_.odom_frame.c_str(), options_.base_frame.c_str(), stamp.toSec(), e.what());
    return std::nullopt;
  }
}

void SlamGmappingNode::scanCallback(const sensor_msgs::LaserScan::ConstPtr& scan) {
  if (++scans_received_ % options_.throttle_scans != 0) return;
  const ros::Time stamp = scan->header.stamp;
  if (!acceptStamp(stamp)) return;
  if (!ranges_known_) {
    max_range_ = options_.max_range.value_or(scan->range_max - 0.01);
    max_usable_range_ = options_.max_usable_range.value_or(max_range_);
    ranges_known_ = true;
    ROS_INFO("slam_gmapping: beams up to maxRange %.2f m are used, those beyond maxUrange %.2f m only to clear "
             "space", max_range_, max_usable_range_);
  }
  Eigen::Isometry3d laser_in_base = Eigen::Isometry3d::Identity();
  if (!laserInBase(*scan, &laser_in_base)) return;
  const std::optional<Pose2D> odometry = odometryAt(stamp);
  if (!odometry) return;

  hsm::ScanFilter filter;
  filter.laser_min_dist = 0.0;  // the scan's own range_min applies
  filter.laser_max_dist = max_range_;
  filter.laser_z_min_value = -std::numeric_limits<double>::infinity();
  filter.laser_z_max_value = std::numeric_limits<double>::infinity();
  const hsm::ScanConversionReport report = hsm::scanToPoints(*scan, laser_in_base, filter, &points_);
  if (!report.error.empty()) {
    ROS_WARN_THROTTLE(5.0, "slam_gmapping: scan on %s skipped: %s", scan_subscriber_.getTopic().c_str(),
                      report.error.c_str());
    return;
  }
  if (report.beams != report.expected_beams)
    ROS_WARN_THROTTLE(10.0, "slam_gmapping: scan on %s has %d ranges where its angles make %d; beam i is taken "
                      "at angle_min + i * angle_increment", scan_subscriber_.getTopic().c_str(), report.beams,
                      report.expected_beams);
  cutToUsableRange(max_usable_range_, &points_);

  const OdometrySlam::Outcome outcome = slam_.addScan(points_, *odometry, stamp.toSec());
  if (outcome == OdometrySlam::Outcome::kSkipped) return;
  if (outcome == OdometrySlam::Outcome::kNoPoints) {
    ROS_WARN_THROTTLE(5.0, "slam_gmapping: scan on %s has no usable beam (%d NaN, %d inf, %d out of range, "
                      "maxRange %.2f m): map kept", scan_subscriber_.getTopic().c_str(), report.nan,
                      report.infinite, report.out_of_range, max_range_);
    return;
  }
  if (outcome == OdometrySlam::Outcome::kMatchRefused)
    ROS_WARN_THROTTLE(10.0, "slam_gmapping: a scan match strayed further from the odometry than its error model "
                      "(srr, srt, str, stt) allows; the odometry was kept (%d of %d scans so far)",
                      slam_.refusedMatches(), slam_.processedScans());
  std_msgs::Float64 entropy;
  entropy.data = slam_.poseEntropy();
  entropy_publisher_.publish(entropy);
  if (!have_map_ || (stamp - last_map_stamp_).toSec() > options_.map_update_interval) {
    last_map_stamp_ = stamp;
    publishMap();
  }
  publishTransform();
}

void SlamGmappingNode::publishMap() {
  const HitCounts& counts = slam_.hitCounts();
  const CellBox& seen = counts.seenBox();
  if (seen.empty()) return;
  const hsm::OccupancyGridMap& finest = slam_.map().finest();
  const double resolution = finest.resolution();
  // What was seen, plus a margin, out to whole growth steps: the map's size changes only now and then.
  const int margin = static_cast<int>(std::ceil(kMapMargin / resolution));
  const int step = std::max(1, static_cast<int>(std::lround(kMapGrowthStep / resolution)));
  const auto down = [step](int v) { return static_cast<int>(std::floor(static_cast<double>(v) / step)) * step; };
  const auto up = [step](int v) { return static_cast<int>(std::ceil(static_cast<double>(v) / step)) * step; };
  CellBox box{std::max(0, down(seen.x0 - margin)), std::max(0, down(seen.y0 - margin)),
              std::min(counts.sizeX(), up(seen.x1 + margin)), std::min(counts.sizeY(), up(seen.y1 + margin))};

  map_.header.stamp = ros::Time::now();
  map_.header.frame_id = options_.map_frame;
  map_.info.map_load_time = map_.header.stamp;
  map_.info.resolution = static_cast<float>(resolution);
  map_.info.width = static_cast<unsigned>(box.width());
  map_.info.height = static_cast<unsigned>(box.height());
  map_.info.origin = geometry_msgs::Pose();
  map_.info.origin.position.x = finest.origin().x() + box.x0 * resolution;
  map_.info.origin.position.y = finest.origin().y() + box.y0 * resolution;
  map_.info.origin.orientation.w = 1.0;
  counts.states(box, slam_.occThresh(), &map_.data);
  have_map_ = true;
  map_publisher_.publish(map_);
  map_metadata_publisher_.publish(map_.info);
}

void SlamGmappingNode::publishTransform() {
  if (options_.transform_publish_period <= 0.0) return;
  // As gmapping: stamped ahead by tf_delay, so users looking up "now" find it; never twice at one stamp (tf
  // would complain), e.g. while the simulation is paused.
  const ros::Time stamp = ros::Time::now() + ros::Duration(options_.tf_delay);
  if (stamp <= last_transform_stamp_) return;
  last_transform_stamp_ = stamp;
  const Pose2D& m = slam_.mapToOdom();
  tf2::Quaternion q;
  q.setRPY(0.0, 0.0, m.theta);
  geometry_msgs::TransformStamped t;
  t.header.stamp = stamp;
  t.header.frame_id = options_.map_frame;
  t.child_frame_id = options_.odom_frame;
  t.transform = tf2::toMsg(tf2::Transform(q, tf2::Vector3(m.x, m.y, 0.0)));
  tf_broadcaster_.sendTransform(t);
}

bool SlamGmappingNode::dynamicMapService(nav_msgs::GetMap::Request&, nav_msgs::GetMap::Response& response) {
  if (!have_map_) {
    ROS_WARN("slam_gmapping: dynamic_map asked before the first scan was mapped: no map yet");
    return false;
  }
  response.map = map_;
  return true;
}

}  // namespace odometry_slam
