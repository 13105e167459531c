#include "hector_style_mapping/ros/mapping_node.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include <geometry_msgs/PoseStamped.h>
#include <nav_msgs/Odometry.h>
#include <tf2/LinearMath/Transform.h>
#include <tf2/utils.h>
#include <tf2_geometry_msgs/tf2_geometry_msgs.h>

#include "hector_style_mapping/ros/map_message.h"
#include "hector_style_mapping/ros/scan_conversion.h"
#include "hector_style_mapping/ros/scan_input.h"

namespace hector_style_mapping {
namespace {

// Scans ROS itself may hold for the subscriber's thread (see the constructor).
constexpr int kTransportQueue = 1000;
// How long a scan may wait for the tf it needs.
const ros::Duration kTfWait(0.1);
// The trajectory gets a pose when the robot moved this far or turned this much since the last one.
constexpr double kTrajectoryStep = 0.01;        // m
constexpr double kTrajectoryTurnStep = 0.02;    // rad

NodeOptions loadOrThrow(const ros::NodeHandle& private_nh) {
  NodeOptions options;
  const std::string problems = loadNodeOptions(private_nh, &options);
  if (!problems.empty()) throw std::invalid_argument(problems);
  return options;
}

geometry_msgs::Quaternion yawQuaternion(double yaw) {
  geometry_msgs::Quaternion q;
  q.z = std::sin(yaw / 2.0);
  q.w = std::cos(yaw / 2.0);
  return q;
}

geometry_msgs::Pose poseMessage(const Pose2D& pose) {
  geometry_msgs::Pose p;
  p.position.x = pose.x;
  p.position.y = pose.y;
  p.orientation = yawQuaternion(pose.theta);
  return p;
}

tf2::Transform planar(const Pose2D& pose) {
  tf2::Quaternion q;
  q.setRPY(0.0, 0.0, pose.theta);
  return tf2::Transform(q, tf2::Vector3(pose.x, pose.y, 0.0));
}

}  // namespace

void ScanTiming::add(double ms) {
  ++scans;
  total_ms += ms;
  max_ms = std::max(max_ms, ms);
}

std::string ScanTiming::summary() const {
  char text[128];
  std::snprintf(text, sizeof text, "%ld scans processed, %.3f ms mean, %.3f ms max per scan, %ld skipped", scans,
                meanMs(), max_ms, skipped);
  return text;
}

MappingNode::MappingNode(ros::NodeHandle nh, ros::NodeHandle private_nh)
    : options_(loadOrThrow(private_nh)),
      nh_(nh),
      private_nh_(private_nh),
      // Loop closure's searches, optimisation and map redraw off the scan path: a live node never waits for them.
      slam_(options_.mapper, LoopClosureThreading::kBackground),
      tf_buffer_(ros::Duration(30.0)),
      tf_listener_(tf_buffer_) {
  for (const std::string& name : unknownParameters(private_nh_))
    ROS_WARN("hector_mapping: ignored %s: not a parameter of hector_mapping", name.c_str());

  // The subscriber's own thread only moves scans to waiting_scans_, where the queue policy is kept and counted;
  // ROS's own queue is longer, so that a burst the thread has not yet seen is not dropped uncounted.
  ros::SubscribeOptions scans = ros::SubscribeOptions::create<sensor_msgs::LaserScan>(
      options_.scan_topic, std::max(options_.scan_subscriber_queue_size, kTransportQueue),
      [this](const sensor_msgs::LaserScan::ConstPtr& scan) { scanCallback(scan); }, ros::VoidPtr(), &scan_callbacks_);
  scan_subscriber_ = nh_.subscribe(scans);
  sys_command_subscriber_ = nh_.subscribe(options_.sys_msg_topic, 2, &MappingNode::sysCommandCallback, this);
  initial_pose_subscriber_ = nh_.subscribe("initialpose", 2, &MappingNode::initialPoseCallback, this);

  map_publisher_ = nh_.advertise<nav_msgs::OccupancyGrid>("map", 1, true);
  map_metadata_publisher_ = nh_.advertise<nav_msgs::MapMetaData>("map_metadata", 1, true);
  pose_publisher_ = nh_.advertise<geometry_msgs::PoseStamped>("slam_out_pose", 10);
  pose_update_publisher_ = nh_.advertise<geometry_msgs::PoseWithCovarianceStamped>(options_.pose_update_topic, 10);
  if (options_.pub_odometry) odometry_publisher_ = nh_.advertise<nav_msgs::Odometry>("scanmatch_odom", 10);
  trajectory_publisher_ = nh_.advertise<nav_msgs::Path>("trajectory", 1, true);

  if (options_.advertise_map_service)
    dynamic_map_service_ = nh_.advertiseService("dynamic_map", &MappingNode::dynamicMapService, this);
  reset_map_service_ = nh_.advertiseService("reset_map", &MappingNode::resetMapService, this);

  trajectory_.header.frame_id = options_.map_frame;
  // Sim time, as upstream's ros::Rate: faster than real time, the map keeps up with the robot.
  map_timer_ = nh_.createTimer(ros::Duration(options_.map_pub_period), [this](const ros::TimerEvent&) { publishMap(); });
  if (options_.pub_map_odom_transform && options_.transform_pub_period > 0.0)
    transform_timer_ = nh_.createWallTimer(ros::WallDuration(options_.transform_pub_period),
                                           [this](const ros::WallTimerEvent&) { republishMapTransform(); });
  publishMap();  // the empty map, so that latecomers find one
  last_behind_report_ = ros::WallTime::now();
  behind_timer_ = nh_.createWallTimer(ros::WallDuration(1.0), [this](const ros::WallTimerEvent&) { reportFallingBehind(); });
  scan_path_ = std::thread([this] { matchScans(); });
  scan_spinner_ = std::make_unique<ros::AsyncSpinner>(1, &scan_callbacks_);
  scan_spinner_->start();

  const MapperOptions& m = options_.mapper;
  ROS_INFO("hector_mapping: %d x %d cells of %.3f m (%d levels), map frame origin at (%.2f, %.2f) of the map; "
           "scans on %s; tf %s -> %s%s", m.map_size, m.map_size, m.map_resolution, m.map_multi_res_levels,
           m.map_start_x, m.map_start_y, nh_.resolveName(options_.scan_topic).c_str(), options_.map_frame.c_str(),
           options_.odom_frame.c_str(), options_.pub_map_odom_transform ? "" : " (not published)");
}

MappingNode::~MappingNode() {
  scan_spinner_->stop();
  {
    std::lock_guard<std::mutex> lock(queue_mutex_);
    stopping_ = true;
  }
  scan_waiting_.notify_all();
  scan_path_.join();
}

ScanTiming MappingNode::timing() {
  ScanTiming timing;
  {
    std::lock_guard<std::mutex> lock(state_mutex_);
    timing = timing_;
  }
  std::lock_guard<std::mutex> lock(queue_mutex_);
  timing.skipped = skipped_total_;
  return timing;
}

void MappingNode::scanCallback(const sensor_msgs::LaserScan::ConstPtr& scan) {
  {
    std::lock_guard<std::mutex> lock(queue_mutex_);
    if (static_cast<int>(waiting_scans_.size()) >= options_.scan_subscriber_queue_size) {
      waiting_scans_.pop_front();
      ++skipped_since_report_;
      ++skipped_total_;
    }
    waiting_scans_.push_back(scan);
    newest_stamp_ = scan->header.stamp;  // the last received (not the largest: a bag may loop)
  }
  scan_waiting_.notify_one();
}

void MappingNode::matchScans() {
  while (true) {
    sensor_msgs::LaserScan::ConstPtr scan;
    {
      std::unique_lock<std::mutex> lock(queue_mutex_);
      scan_waiting_.wait(lock, [this] { return stopping_ || !waiting_scans_.empty(); });
      if (stopping_) return;
      scan = waiting_scans_.front();
      waiting_scans_.pop_front();
      most_behind_ = std::max(most_behind_, (newest_stamp_ - scan->header.stamp).toSec());
    }
    std::lock_guard<std::mutex> lock(state_mutex_);
    processScan(*scan);
  }
}

void MappingNode::reportFallingBehind() {
  const ros::WallTime now = ros::WallTime::now();
  const double seconds = (now - last_behind_report_).toSec();
  last_behind_report_ = now;
  long skipped, total;
  double most_behind;
  {
    std::lock_guard<std::mutex> lock(queue_mutex_);
    skipped = skipped_since_report_;
    total = skipped_total_;
    most_behind = most_behind_;
    skipped_since_report_ = 0;
    most_behind_ = 0.0;
  }
  if (skipped == 0) return;
  double mean_ms;
  {
    std::lock_guard<std::mutex> lock(state_mutex_);
    mean_ms = timing_.meanMs();
  }
  ROS_WARN("hector_mapping: cannot keep up with the scans on %s: %ld skipped in the last %.1f s, %ld in all (when "
           "scan_subscriber_queue_size, %d, are waiting, the oldest is dropped); the scans matched were up to %.3f s "
           "behind the newest received (by their stamps); %.1f ms a scan on average",
           scan_subscriber_.getTopic().c_str(), skipped, seconds, total, options_.scan_subscriber_queue_size,
           most_behind, mean_ms);
}

bool MappingNode::acceptStamp(const ros::Time& stamp) {
  const ros::Time previous = scan_stamps_.last();
  switch (scan_stamps_.accept(stamp)) {
    case StampOrder::kNewer:
      return true;
    case StampOrder::kClockRestarted:
      ROS_WARN("hector_mapping: time went back %.3f s (from %.3f to %.3f; a simulator or bag restart?): tf buffer "
               "cleared, mapping goes on in the same map (publish 'reset' on %s to start a new one)",
               (previous - stamp).toSec(), previous.toSec(), stamp.toSec(),
               nh_.resolveName(options_.sys_msg_topic).c_str());
      tf_buffer_.clear();
      have_map_transform_ = false;  // its stamp is from the old time line: never newer than what comes now
      return true;
    case StampOrder::kStale:
      break;
  }
  ROS_WARN_THROTTLE(5.0, "hector_mapping: scan stamped %.6f is not newer than the last one (%.6f): dropped",
                    stamp.toSec(), previous.toSec());
  return false;
}

bool MappingNode::laserInBase(const sensor_msgs::LaserScan& scan, Eigen::Isometry3d* laser_in_base) {
  try {
    const geometry_msgs::TransformStamped t =
        tf_buffer_.lookupTransform(options_.base_frame, scan.header.frame_id, scan.header.stamp, kTfWait);
    *laser_in_base = isometryOf(t.transform);
    return true;
  } catch (const tf2::TransformException& e) {
    ROS_WARN_THROTTLE(5.0, "hector_mapping: no tf from base_frame '%s' to the scan's frame '%s' at %.3f: %s. Scan "
                      "dropped. (Is robot_state_publisher or a static_transform_publisher running? Or set "
                      "~use_tf_scan_transformation false for a laser at the base origin.)",
                      options_.base_frame.c_str(), scan.header.frame_id.c_str(), scan.header.stamp.toSec(), e.what());
    return false;
  }
}

void MappingNode::processScan(const sensor_msgs::LaserScan& scan) {
  const ros::Time stamp = scan.header.stamp;
  const ros::Time previous_stamp = scan_stamps_.last();
  if (!acceptStamp(stamp)) return;
  // The scan rate sizes the correlative search's window; 0 (the first scan, a clock restart): not known.
  const double seconds_since_last_scan =
      !previous_stamp.isZero() && stamp > previous_stamp ? (stamp - previous_stamp).toSec() : 0.0;
  Eigen::Isometry3d laser_in_base = Eigen::Isometry3d::Identity();
  if (options_.use_tf_scan_transformation && !laserInBase(scan, &laser_in_base)) return;

  // Before the timing: it may wait for the odometry's tf. Without the prediction the lookup waits
  // until after the match, as before it existed.
  std::optional<geometry_msgs::TransformStamped> odometry;
  if (options_.use_odometry_prediction && options_.odom_frame != options_.base_frame)
    odometry = odometryAt(stamp);
  std::optional<Pose2D> planar_odometry;
  if (odometry)
    planar_odometry = Pose2D{odometry->transform.translation.x, odometry->transform.translation.y,
                             tf2::getYaw(odometry->transform.rotation)};

  const auto start = std::chrono::steady_clock::now();
  const ScanConversionReport report = scanToPoints(scan, laser_in_base, options_.filter, &scan_points_);
  const std::string topic = scan_subscriber_.getTopic();
  if (!report.error.empty()) {
    ROS_WARN_THROTTLE(5.0, "hector_mapping: scan on %s dropped: %s", topic.c_str(), report.error.c_str());
    return;
  }
  if (report.beams != report.expected_beams)
    ROS_WARN_THROTTLE(10.0, "hector_mapping: scan on %s has %d ranges where its angles make %d; beam i is taken "
                      "at angle_min + i * angle_increment", topic.c_str(), report.beams, report.expected_beams);
  if (report.nan > 0)
    ROS_WARN_THROTTLE(30.0, "hector_mapping: %d of %d ranges on %s are NaN (invalid measurements): ignored",
                      report.nan, report.beams, topic.c_str());
  if (report.used == 0) {
    ROS_WARN_THROTTLE(5.0, "hector_mapping: scan on %s has no usable beam (%d NaN, %d inf, %d out of range "
                      "%.2f..%.2f m, %d outside height %.2f..%.2f m): pose and map kept", topic.c_str(), report.nan,
                      report.infinite, report.out_of_range, options_.filter.laser_min_dist,
                      options_.filter.laser_max_dist, report.outside_height, options_.filter.laser_z_min_value,
                      options_.filter.laser_z_max_value);
    return;
  }

  Pose2D guess;
  const Pose2D* guess_pointer = nullptr;
  if (have_initial_pose_) {
    guess = initial_pose_;
    guess_pointer = &guess;
    have_initial_pose_ = false;
  } else if (options_.use_tf_pose_start_estimate) {
    try {
      const geometry_msgs::TransformStamped t =
          tf_buffer_.lookupTransform(options_.map_frame, options_.base_frame, stamp, kTfWait);
      guess = {t.transform.translation.x, t.transform.translation.y, tf2::getYaw(t.transform.rotation)};
      guess_pointer = &guess;
    } catch (const tf2::TransformException& e) {
      ROS_WARN_THROTTLE(5.0, "hector_mapping: use_tf_pose_start_estimate: no tf %s -> %s at %.3f (%s); starting "
                        "from the last pose", options_.map_frame.c_str(), options_.base_frame.c_str(), stamp.toSec(),
                        e.what());
    }
  } else if (options_.use_odometry_prediction && planar_odometry && last_scan_odometry_) {
    // The motion odometry saw since the last scan, applied to the last match: the matcher then only
    // corrects the odometry's small error, where from the last pose alone a fast turn can lose it.
    guess = compose(slam_.pose(), between(*last_scan_odometry_, *planar_odometry));
    guess_pointer = &guess;
  }
  slam_.update(scan_points_, guess_pointer, seconds_since_last_scan);
  last_scan_odometry_ = planar_odometry;
  publishPose(stamp);
  appendTrajectory(stamp);
  const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  timing_.add(ms);
  if (options_.output_timing)
    ROS_INFO("hector_mapping: scan %ld (%d points) took %.3f ms", timing_.scans, report.used, ms);
  if (!odometry && options_.odom_frame != options_.base_frame) odometry = odometryAt(stamp);
  publishMapTransform(stamp, odometry);
}

void MappingNode::publishPose(const ros::Time& stamp) {
  const Pose2D& pose = slam_.pose();
  geometry_msgs::PoseStamped out;
  out.header.stamp = stamp;
  out.header.frame_id = options_.map_frame;
  out.pose = poseMessage(pose);
  pose_publisher_.publish(out);

  geometry_msgs::PoseWithCovarianceStamped with_covariance;
  with_covariance.header = out.header;
  with_covariance.pose.pose = out.pose;
  // x, y, yaw of the 3x3 into the 6x6 (x y z roll pitch yaw), row-major.
  const int index[3] = {0, 1, 5};
  const Eigen::Matrix3d& c = slam_.covariance();
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) with_covariance.pose.covariance[index[i] * 6 + index[j]] = c(i, j);
  pose_update_publisher_.publish(with_covariance);

  if (options_.pub_odometry) {
    nav_msgs::Odometry odometry;
    odometry.header = out.header;
    odometry.child_frame_id = options_.base_frame;
    odometry.pose = with_covariance.pose;
    odometry_publisher_.publish(odometry);
  }
}

std::optional<geometry_msgs::TransformStamped> MappingNode::odometryAt(const ros::Time& stamp) {
  try {
    return tf_buffer_.lookupTransform(options_.odom_frame, options_.base_frame, stamp, kTfWait);
  } catch (const tf2::TransformException& e) {
    ROS_WARN_THROTTLE(5.0, "hector_mapping: no tf %s -> %s at %.3f (%s): map -> %s not updated",
                      options_.odom_frame.c_str(), options_.base_frame.c_str(), stamp.toSec(), e.what(),
                      options_.odom_frame.c_str());
    return std::nullopt;
  }
}

void MappingNode::publishMapTransform(const ros::Time& stamp,
                                      const std::optional<geometry_msgs::TransformStamped>& odometry) {
  if (options_.pub_map_scanmatch_transform) {
    geometry_msgs::TransformStamped scanmatch;
    scanmatch.header.stamp = stamp;
    scanmatch.header.frame_id = options_.map_frame;
    scanmatch.child_frame_id = options_.tf_map_scanmatch_transform_frame_name;
    scanmatch.transform = tf2::toMsg(planar(slam_.pose()));
    tf_broadcaster_.sendTransform(scanmatch);
  }
  if (!options_.pub_map_odom_transform) return;
  tf2::Transform map_to_odom = planar(slam_.pose());  // map -> base, when there is no odometry frame
  if (options_.odom_frame != options_.base_frame) {
    if (!odometry) return;
    tf2::Transform odom_to_base;
    tf2::fromMsg(odometry->transform, odom_to_base);
    // The map pose is planar; the base keeps its height and tilt from odometry, so that map -> odom
    // stays planar for a level odometry frame.
    double roll, pitch, yaw;
    odom_to_base.getBasis().getRPY(roll, pitch, yaw);
    tf2::Quaternion q;
    q.setRPY(roll, pitch, slam_.pose().theta);
    const tf2::Transform map_to_base(q, tf2::Vector3(slam_.pose().x, slam_.pose().y, odom_to_base.getOrigin().z()));
    map_to_odom = map_to_base * odom_to_base.inverse();
  }
  map_transform_.header.frame_id = options_.map_frame;
  map_transform_.child_frame_id = options_.odom_frame;
  map_transform_.transform = tf2::toMsg(map_to_odom);
  // When the re-publication timer has already sent this transform at the scan's stamp or later,
  // the new value waits for its next tick: tf rejects two transforms at one stamp (TF_REPEATED_DATA).
  if (have_map_transform_ && stamp <= map_transform_.header.stamp) return;
  map_transform_.header.stamp = stamp;
  have_map_transform_ = true;
  tf_broadcaster_.sendTransform(map_transform_);
}

void MappingNode::republishMapTransform() {
  // As hector_mapping: the latest map -> odom, stamped now, so that tf users are never left behind
  // between scans. Never twice at one stamp (tf would complain), e.g. while the simulation is paused.
  const ros::Time now = ros::Time::now();
  std::lock_guard<std::mutex> lock(state_mutex_);
  if (!have_map_transform_ || now <= map_transform_.header.stamp) return;
  map_transform_.header.stamp = now;
  tf_broadcaster_.sendTransform(map_transform_);
}

void MappingNode::followLoopClosure() {
  if (slam_.loopClosureAdoptions() == trajectory_closures_) return;
  trajectory_closures_ = slam_.loopClosureAdoptions();
  for (std::size_t i = 0; i < trajectory_.poses.size() && i < anchored_trajectory_.size(); ++i)
    trajectory_.poses[i].pose = poseMessage(anchored_trajectory_.pose(i, slam_.keyframePoses()));
}

void MappingNode::appendTrajectory(const ros::Time& stamp) {
  followLoopClosure();
  const Pose2D& pose = slam_.pose();
  if (!trajectory_.poses.empty()) {
    const geometry_msgs::Pose& last = trajectory_.poses.back().pose;
    const double turned = std::abs(normalizeAngle(pose.theta - tf2::getYaw(last.orientation)));
    if (std::hypot(pose.x - last.position.x, pose.y - last.position.y) < kTrajectoryStep &&
        turned < kTrajectoryTurnStep)
      return;
  }
  geometry_msgs::PoseStamped p;
  p.header.stamp = stamp;
  p.header.frame_id = options_.map_frame;
  p.pose = poseMessage(pose);
  trajectory_.poses.push_back(p);
  anchored_trajectory_.append(pose, slam_.keyframePoses());
}

void MappingNode::publishMap() {
  const ros::Time now = ros::Time::now();
  nav_msgs::Path trajectory;
  bool map_changed = false;
  {
    // Only the conversion holds the scan path up (a few ms for a 2048-cell map); publishing does not.
    std::lock_guard<std::mutex> lock(state_mutex_);
    // A loop closed after the last scan (the robot stopped, the log ended) is not left waiting for the next.
    if (slam_.adoptClosedLoop()) followLoopClosure();
    trajectory = trajectory_;
    // As hector_mapping: the map goes out every map_pub_period with the current stamp, converted
    // again only when it changed. The stamp tells subscribers the map is up to date at that time
    // (an explorer waiting for a map made after its robot arrived, say).
    // A closed loop redraws the map without a map update.
    const std::pair<int, int> version(slam_.mapUpdateCount(), slam_.loopClosureAdoptions());
    if (version != published_map_version_) {
      published_map_version_ = version;
      map_message_.header.frame_id = options_.map_frame;
      fillOccupancyGrid(slam_.map().finest(), &map_message_);
      map_changed = true;
    }
  }
  trajectory.header.stamp = now;
  trajectory_publisher_.publish(trajectory);
  if (map_changed) {
    map_message_.info.map_load_time = now;
    map_metadata_publisher_.publish(map_message_.info);
  }
  map_message_.header.stamp = now;
  map_publisher_.publish(map_message_);
}

bool MappingNode::dynamicMapService(nav_msgs::GetMap::Request&, nav_msgs::GetMap::Response& response) {
  response.map.header.stamp = ros::Time::now();
  response.map.header.frame_id = options_.map_frame;
  std::lock_guard<std::mutex> lock(state_mutex_);
  fillOccupancyGrid(slam_.map().finest(), &response.map);
  response.map.info.map_load_time = response.map.header.stamp;
  return true;
}

void MappingNode::reset(const std::string& why) {
  {
    std::lock_guard<std::mutex> lock(state_mutex_);
    resetState();
  }
  publishMap();  // the empty map goes out now
  ROS_INFO("hector_mapping: map and pose reset (%s)", why.c_str());
}

void MappingNode::resetState() {
  slam_.reset();
  last_scan_odometry_.reset();
  trajectory_.poses.clear();
  anchored_trajectory_.clear();
  trajectory_closures_ = 0;
  have_initial_pose_ = false;
  published_map_version_ = {-1, -1};  // converted again, empty
}

bool MappingNode::resetMapService(std_srvs::Trigger::Request&, std_srvs::Trigger::Response& response) {
  reset("reset_map service");
  response.success = true;
  response.message = "map and pose reset";
  return true;
}

void MappingNode::sysCommandCallback(const std_msgs::String::ConstPtr& command) {
  if (command->data == "reset") reset("'reset' on " + sys_command_subscriber_.getTopic());
  else ROS_DEBUG("hector_mapping: syscommand '%s' ignored (only 'reset' is known)", command->data.c_str());
}

void MappingNode::initialPoseCallback(const geometry_msgs::PoseWithCovarianceStamped::ConstPtr& pose) {
  geometry_msgs::PoseStamped in_map;
  in_map.header = pose->header;
  in_map.pose = pose->pose.pose;
  if (!pose->header.frame_id.empty() && pose->header.frame_id != options_.map_frame) {
    try {
      in_map = tf_buffer_.transform(in_map, options_.map_frame, kTfWait);
    } catch (const tf2::TransformException& e) {
      ROS_WARN("hector_mapping: initialpose in frame '%s' cannot be put into '%s' (%s): ignored",
               pose->header.frame_id.c_str(), options_.map_frame.c_str(), e.what());
      return;
    }
  }
  std::lock_guard<std::mutex> lock(state_mutex_);
  initial_pose_ = {in_map.pose.position.x, in_map.pose.position.y, tf2::getYaw(in_map.pose.orientation)};
  have_initial_pose_ = true;
  ROS_INFO("hector_mapping: next scan starts from the initial pose x %.3f y %.3f yaw %.3f", initial_pose_.x,
           initial_pose_.y, initial_pose_.theta);
}

}  // namespace hector_style_mapping
