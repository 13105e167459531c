#ifndef HECTOR_STYLE_MAPPING_ROS_MAPPING_NODE_H
#define HECTOR_STYLE_MAPPING_ROS_MAPPING_NODE_H

#include <condition_variable>
#include <deque>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <utility>

#include <geometry_msgs/PoseWithCovarianceStamped.h>
#include <geometry_msgs/TransformStamped.h>
#include <nav_msgs/GetMap.h>
#include <nav_msgs/OccupancyGrid.h>
#include <nav_msgs/Path.h>
#include <ros/callback_queue.h>
#include <ros/ros.h>
#include <sensor_msgs/LaserScan.h>
#include <std_msgs/String.h>
#include <std_srvs/Trigger.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/transform_broadcaster.h>
#include <tf2_ros/transform_listener.h>

#include "hector_style_mapping/ros/node_options.h"
#include "hector_style_mapping/ros/scan_input.h"
#include "hector_style_mapping_core/anchored_trajectory.h"
#include "hector_style_mapping_core/slam_processor.h"

namespace hector_style_mapping {

// Per-scan processing time (conversion + matching + map update + pose output), wall clock.
struct ScanTiming {
  long scans = 0;
  double total_ms = 0.0;
  double max_ms = 0.0;
  void add(double ms);
  long skipped = 0;  // dropped from a full scan queue
  double meanMs() const { return scans ? total_ms / scans : 0.0; }
  // "N scans processed, X ms mean, Y ms max per scan, K skipped" (scripts/bench_mapping.py reads it).
  std::string summary() const;
};

// hector_mapping's ROS interface around SlamProcessor (topics, tf, services: see the package README).
//
// Threads: scans are matched in a thread of their own (the scan path), loop closure works in another
// (SlamProcessor's background worker), and everything else (map publishing, services, the other topics) runs
// in the thread that calls ros::spin(); state_mutex_ is held by each in turn. A scan waits in a queue of
// scan_subscriber_queue_size scans (upstream's meaning: how many may wait while the node is busy); when it is
// full, the oldest waiting is dropped, and the node says so once a second (scans skipped, how far behind).
// The next scan matched then has a search window sized to the time since the last match.
class MappingNode {
 public:
  // Throws std::invalid_argument, naming every bad parameter, when the configuration cannot be used.
  MappingNode(ros::NodeHandle nh, ros::NodeHandle private_nh);
  ~MappingNode();  // stops the scan path (the scans still waiting are dropped)

  ScanTiming timing();

 private:
  // Subscriber thread: queues the scan (dropping the oldest waiting when the queue is full).
  void scanCallback(const sensor_msgs::LaserScan::ConstPtr& scan);
  // The scan path: takes the scans from the queue, in order, and matches each.
  void matchScans();
  void processScan(const sensor_msgs::LaserScan& scan);
  // Every second (a wall timer) in which scans were skipped: how many, and how far behind the newest scan
  // received the scans matched were.
  void reportFallingBehind();
  void sysCommandCallback(const std_msgs::String::ConstPtr& command);
  void initialPoseCallback(const geometry_msgs::PoseWithCovarianceStamped::ConstPtr& pose);
  bool dynamicMapService(nav_msgs::GetMap::Request& request, nav_msgs::GetMap::Response& response);
  bool resetMapService(std_srvs::Trigger::Request& request, std_srvs::Trigger::Response& response);
  void publishMap();
  void republishMapTransform();

  // Where the laser of `scan` is in the base frame at its stamp; false (and a warning) when tf cannot say.
  bool laserInBase(const sensor_msgs::LaserScan& scan, Eigen::Isometry3d* laser_in_base);
  // False for a scan to drop because of its stamp (older than the last, or a duplicate).
  bool acceptStamp(const ros::Time& stamp);
  void publishPose(const ros::Time& stamp);
  // tf odom_frame -> base_frame at `stamp`; nothing (and a warning) when tf cannot say.
  std::optional<geometry_msgs::TransformStamped> odometryAt(const ros::Time& stamp);
  // map -> odom from the matched pose and the odometry at the scan (map -> base without an odometry frame).
  void publishMapTransform(const ros::Time& stamp, const std::optional<geometry_msgs::TransformStamped>& odometry);
  void appendTrajectory(const ros::Time& stamp);
  // After a loop closed: the trajectory's poses from their keyframes' new estimates, as the map.
  void followLoopClosure();
  void reset(const std::string& why);
  void resetState();  // reset() under state_mutex_

  NodeOptions options_;
  ros::NodeHandle nh_, private_nh_;
  SlamProcessor slam_;
  tf2_ros::Buffer tf_buffer_;
  tf2_ros::TransformListener tf_listener_;
  tf2_ros::TransformBroadcaster tf_broadcaster_;

  ros::Subscriber scan_subscriber_, sys_command_subscriber_, initial_pose_subscriber_;
  ros::Publisher map_publisher_, map_metadata_publisher_, pose_publisher_, pose_update_publisher_;
  ros::Publisher odometry_publisher_, trajectory_publisher_;
  ros::ServiceServer dynamic_map_service_, reset_map_service_;
  ros::Timer map_timer_;              // sim time
  ros::WallTimer transform_timer_;    // wall time: a paused or fast simulation still gets its tf

  ScanStamps scan_stamps_;
  bool have_initial_pose_ = false;
  Pose2D initial_pose_;
  std::optional<Pose2D> last_scan_odometry_;  // odom -> base (planar) at the last matched scan
  geometry_msgs::TransformStamped map_transform_;  // the last map -> odom (or -> base) sent
  bool have_map_transform_ = false;
  nav_msgs::Path trajectory_;
  AnchoredTrajectory anchored_trajectory_;  // trajectory_'s poses, held to the keyframes
  int trajectory_closures_ = 0;  // SlamProcessor::loopClosureAdoptions() when trajectory_ last followed them
  // SlamProcessor::mapUpdateCount() and loopClosureAdoptions() when map_message_ was filled.
  std::pair<int, int> published_map_version_{-1, -1};
  nav_msgs::OccupancyGrid map_message_;  // the last map converted, re-sent with a new stamp while unchanged
  ScanPoints scan_points_;  // reused: no allocation per scan
  ScanTiming timing_;

  // Guards everything above that both the scan path and the ros::spin() thread touch.
  mutable std::mutex state_mutex_;

  // The scan queue, filled by the subscriber's own thread, emptied by the scan path.
  std::mutex queue_mutex_;
  std::condition_variable scan_waiting_;
  std::deque<sensor_msgs::LaserScan::ConstPtr> waiting_scans_;
  bool stopping_ = false;
  long skipped_since_report_ = 0;  // under queue_mutex_
  long skipped_total_ = 0;         // under queue_mutex_
  ros::Time newest_stamp_;         // of the last scan received, under queue_mutex_
  double most_behind_ = 0.0;       // s, newest_stamp_ - a scan's stamp as it is taken, since the last report
  ros::WallTime last_behind_report_;
  ros::WallTimer behind_timer_;
  ros::CallbackQueue scan_callbacks_;
  std::unique_ptr<ros::AsyncSpinner> scan_spinner_;
  std::thread scan_path_;
};

}  // namespace hector_style_mapping

#endif  // HECTOR_STYLE_MAPPING_ROS_MAPPING_NODE_H
