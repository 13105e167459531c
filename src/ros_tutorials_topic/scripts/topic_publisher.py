#!/usr/bin/env python3
"""The lecture's publisher in rospy: a MsgTutorial on ros_tutorial_msg ten times a second, stamped
with the time and counting from 0, each one logged."""
import rospy

from ros_tutorials_topic.msg import MsgTutorial


def main():
    rospy.init_node('topic_publisher')
    publisher = rospy.Publisher('ros_tutorial_msg', MsgTutorial, queue_size=100)
    rate = rospy.Rate(10)
    count = 0
    while not rospy.is_shutdown():
        msg = MsgTutorial(stamp=rospy.Time.now(), data=count)
        rospy.loginfo('send msg = %d', msg.stamp.secs)
        rospy.loginfo('send msg = %d', msg.stamp.nsecs)
        rospy.loginfo('send msg = %d', msg.data)
        publisher.publish(msg)
        count += 1
        try:
            rate.sleep()
        except rospy.ROSInterruptException:
            break


if __name__ == '__main__':
    main()
