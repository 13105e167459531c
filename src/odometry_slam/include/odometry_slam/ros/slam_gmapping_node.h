#ifndef ODOMETRY_SLAM_ROS_SLAM_GMAPPING_NODE_H
#define ODOMETRY_SLAM_ROS_SLAM_GMAPPING_NODE_H

#include <optional>

#include <Eigen/Geometry>
#include <nav_msgs/GetMap.h>
#include <nav_msgs/OccupancyGrid.h>
#include <ros/ros.h>
#include <sensor_msgs/LaserScan.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/transform_broadcaster.h>
#include <tf2_ros/transform_listener.h>

#include "hector_style_mapping/ros/scan_input.h"
#include "odometry_slam/odometry_slam.h"
#include "odometry_slam/ros/gmapping_options.h"

namespace odometry_slam {

// slam_gmapping's ROS interface around OdometrySlam: `scan` in, `map` + `map_metadata` (latched), `~entropy`,
// the `dynamic_map` service and tf map -> odom out, from tf odom -> base_frame (README.md).
class SlamGmappingNode {
 public:
  // The map grows by whole steps of this size as the robot sees more (README.md: "the map's extent").
  static constexpr double kMapGrowthStep = 5.0;  // m
  static constexpr double kMapMargin = 1.0;      // m of unknown kept round what was seen

  // Throws std::invalid_argument, naming every bad parameter, when the configuration cannot be used.
  SlamGmappingNode(ros::NodeHandle nh, ros::NodeHandle private_nh);

  const OdometrySlam& slam() const { return slam_; }

 private:
  void scanCallback(const sensor_msgs::LaserScan::ConstPtr& scan);
  // False for a scan to drop because of its stamp (not newer than the last, unless the clock restarted).
  bool acceptStamp(const ros::Time& stamp);
  bool laserInBase(const sensor_msgs::LaserScan& scan, Eigen::Isometry3d* laser_in_base);
  std::optional<Pose2D> odometryAt(const ros::Time& stamp);
  void publishMap();
  void publishTransform();
  bool dynamicMapService(nav_msgs::GetMap::Request& request, nav_msgs::GetMap::Response& response);

  GmappingOptions options_;
  ros::NodeHandle nh_, private_nh_;
  OdometrySlam slam_;
  tf2_ros::Buffer tf_buffer_;
  tf2_ros::TransformListener tf_listener_;
  tf2_ros::TransformBroadcaster tf_broadcaster_;

  ros::Subscriber scan_subscriber_;
  ros::Publisher map_publisher_, map_metadata_publisher_, entropy_publisher_;
  ros::ServiceServer dynamic_map_service_;
  ros::Timer transform_timer_;  // ROS time, as upstream's loop

  long scans_received_ = 0;
  hector_style_mapping::ScanStamps scan_stamps_;
  ros::Time last_map_stamp_, last_transform_stamp_;
  bool ranges_known_ = false;  // maxRange and maxUrange fixed from the first scan
  double max_range_ = 0.0, max_usable_range_ = 0.0;
  nav_msgs::OccupancyGrid map_;  // the last published map (dynamic_map answers with it)
  bool have_map_ = false;
  ScanPoints points_;  // reused: no allocation per scan
};

}  // namespace odometry_slam

#endif  // ODOMETRY_SLAM_ROS_SLAM_GMAPPING_NODE_H
