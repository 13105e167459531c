// The lecture's publisher: a MsgTutorial on ros_tutorial_msg ten times a second, stamped with the
// time and counting from 0, each one logged.
#include "ros/ros.h"
#include "ros_tutorials_topic/MsgTutorial.h"

int main(int argc, char** argv) {
  ros::init(argc, argv, "topic_publisher");
  ros::NodeHandle nh;
  ros::Publisher publisher = nh.advertise<ros_tutorials_topic::MsgTutorial>("ros_tutorial_msg", 100);
  ros::Rate rate(10);
  ros_tutorials_topic::MsgTutorial msg;
  for (int count = 0; ros::ok(); ++count) {
    msg.stamp = ros::Time::now();
    msg.data = count;
    ROS_INFO("send msg = %d", msg.stamp.sec);
    ROS_INFO("send msg = %d", msg.stamp.nsec);
    ROS_INFO("send msg = %d", msg.data);
    publisher.publish(msg);
    rate.sleep();
  }
  return 0;
}
