#!/usr/bin/env python3
"""The lecture's subscriber in rospy: logs the stamp and the count of every MsgTutorial on
ros_tutorial_msg."""
import rospy

from ros_tutorials_topic.msg import MsgTutorial


def on_message(msg):
    rospy.loginfo('receive msg = %d', msg.stamp.secs)
    rospy.loginfo('receive msg = %d', msg.stamp.nsecs)
    rospy.loginfo('receive msg = %d', msg.data)


def main():
    rospy.init_node('topic_subscriber')
    rospy.Subscriber('ros_tutorial_msg', MsgTutorial, on_message, queue_size=100)
    rospy.spin()


if __name__ == '__main__':
    main()
