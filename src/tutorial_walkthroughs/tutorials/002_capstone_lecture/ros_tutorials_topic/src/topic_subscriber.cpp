// The lecture's topic_subscriber.cpp. Fixed: the slide's "ros Tutorial_sub" and
// "ros tutorial msg" (spaces where the publisher's names have underscores: the first does not
// compile, the second is not a valid topic name) are ros_tutorial_sub and "ros_tutorial_msg".
#include "ros/ros.h"
#include "ros_tutorials_topic/MsgTutorial.h"

void msgCallback(const ros_tutorials_topic::MsgTutorial::ConstPtr& msg)
{
    ROS_INFO("recievemsg= %d", msg->stamp.sec);
    ROS_INFO("recievemsg= %d", msg->stamp.nsec);
    ROS_INFO("recievemsg= %d", msg->data);
}

int main(int argc, char **argv)
{
    ros::init(argc, argv, "topic_subscriber");
    ros::NodeHandle nh;
    ros::Subscriber ros_tutorial_sub = nh.subscribe("ros_tutorial_msg", 100, msgCallback);
    ros::spin();
    return 0;
}
