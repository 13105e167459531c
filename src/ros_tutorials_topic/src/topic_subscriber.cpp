// The lecture's subscriber: logs the stamp and the count of every MsgTutorial on ros_tutorial_msg.
#include "ros/ros.h"
#include "ros_tutorials_topic/MsgTutorial.h"

void onMessage(const ros_tutorials_topic::MsgTutorial::ConstPtr& msg) {
  ROS_INFO("receive msg = %d", msg->stamp.sec);
  ROS_INFO("receive msg = %d", msg->stamp.nsec);
  ROS_INFO("receive msg = %d", msg->data);
}

int main(int argc, char** argv) {
  ros::init(argc, argv, "topic_subscriber");
  ros::NodeHandle nh;
  ros::Subscriber subscriber = nh.subscribe("ros_tutorial_msg", 100, onMessage);
  ros::spin();
  return 0;
}
