// slam_gmapping's node: `rosrun odometry_slam slam_gmapping` (or `rosrun gmapping slam_gmapping`).
#include <cstdio>
#include <memory>
#include <stdexcept>

#include <ros/ros.h>

#include "publish_thread/no_delay.h"

#include "odometry_slam/ros/slam_gmapping_node.h"

int main(int argc, char** argv) {
  ros::init(argc, argv, "slam_gmapping");
  ros::NodeHandle nh;
  publish_thread::sendWithoutDelay();  // subscribers get each message at once, even faster than real time
  ros::NodeHandle private_nh("~");
  std::unique_ptr<odometry_slam::SlamGmappingNode> node;
  try {
    node = std::make_unique<odometry_slam::SlamGmappingNode>(nh, private_nh);
  } catch (const std::invalid_argument& e) {
    ROS_FATAL("slam_gmapping: cannot start with these parameters:\n%s", e.what());
    return 1;
  }
  ros::spin();
  // rosconsole is down once spin() returns (ros::shutdown), hence plain stdout.
  std::printf("slam_gmapping: %d scans mapped, %d matches refused for the odometry\n", node->slam().processedScans(),
              node->slam().refusedMatches());
  return 0;
}
