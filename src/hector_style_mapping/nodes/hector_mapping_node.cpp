// hector_mapping's node: `rosrun hector_style_mapping hector_mapping` (or `rosrun hector_mapping hector_mapping`).
#include <cstdio>
#include <memory>
#include <stdexcept>

#include <ros/ros.h>

#include "publish_thread/no_delay.h"

#include "hector_style_mapping/ros/mapping_node.h"

int main(int argc, char** argv) {
  ros::init(argc, argv, "hector_mapping");
  ros::NodeHandle nh;
  publish_thread::sendWithoutDelay();  // subscribers get each message at once, even faster than real time
  ros::NodeHandle private_nh("~");
  std::unique_ptr<hector_style_mapping::MappingNode> node;
  try {
    node = std::make_unique<hector_style_mapping::MappingNode>(nh, private_nh);
  } catch (const std::invalid_argument& e) {
    ROS_FATAL("hector_mapping: cannot start with these parameters:\n%s", e.what());
    return 1;
  }
  ros::spin();
  // rosconsole is down once spin() returns (ros::shutdown), hence plain stdout.
  std::printf("hector_mapping: %s\n", node->timing().summary().c_str());
  return 0;
}
