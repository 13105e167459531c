// move_base, as `<node pkg="move_base" type="move_base" name="move_base">`.
#include <ros/ros.h>
#include <tf2_ros/transform_listener.h>

#include "move_base/move_base.h"
#include "publish_thread/no_delay.h"

int main(int argc, char** argv) {
  ros::init(argc, argv, "move_base");
  tf2_ros::Buffer buffer(ros::Duration(10));
  tf2_ros::TransformListener listener(buffer);
  publish_thread::sendWithoutDelay();  // subscribers get each message at once, even faster than real time
  ros::AsyncSpinner spinner(2);  // sensors, maps and services while the action runs its own thread
  spinner.start();
  try {
    move_base::MoveBase move_base(buffer);
    ros::waitForShutdown();
  } catch (const std::exception& e) {
    ROS_FATAL("move_base: %s", e.what());
    return 1;
  }
  return 0;
}
