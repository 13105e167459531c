#!/usr/bin/env python3
"""robot_state_publisher.test: what a user of robot_state_publisher sees on /tf and /tf_static for a
URDF with fixed, revolute, prismatic, continuous and mimic joints (test/sample_robot.urdf)."""
import math
import threading
import unittest

import rospy
import rostest
from bullet_sim_testing.mobile import yaw_of as yaw
from sensor_msgs.msg import JointState
from tf2_msgs.msg import TFMessage


class RobotStatePublisherTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node('robot_state_publisher_checks')
        cls.lock = threading.Lock()
        cls.tf, cls.static = [], []
        rospy.Subscriber('/tf', TFMessage, lambda m: cls.keep(cls.tf, m), queue_size=1000)
        rospy.Subscriber('/tf_static', TFMessage, lambda m: cls.keep(cls.static, m), queue_size=10)
        cls.states = rospy.Publisher('/joint_states', JointState, queue_size=100)
        cls.r2_states = rospy.Publisher('/r2/joint_states', JointState, queue_size=100)
        deadline = rospy.Time.now() + rospy.Duration(20)
        while (cls.states.get_num_connections() == 0 or cls.r2_states.get_num_connections() == 0) \
                and rospy.Time.now() < deadline:
            rospy.sleep(0.05)

    @classmethod
    def keep(cls, store, msg):
        with cls.lock:
            store.extend((rospy.get_time(), t) for t in msg.transforms)

    def received(self, store, child, since=0.0):
        with self.lock:
            return [t for when, t in store if t.child_frame_id == child and when >= since]

    def wait_for(self, store, child, since=0.0, timeout=10.0):
        deadline = rospy.get_time() + timeout
        while rospy.get_time() < deadline:
            found = self.received(store, child, since)
            if found:
                return found
            rospy.sleep(0.02)
        self.fail('no transform to %s within %.0f s' % (child, timeout))

    def send(self, publisher, names, positions, stamp=None):
        msg = JointState(name=names, position=positions)
        msg.header.stamp = stamp or rospy.Time.now()
        publisher.publish(msg)
        return msg.header.stamp

    def test_fixed_joint_once_on_tf_static(self):
        laser = self.wait_for(self.static, 'laser')[-1]
        self.assertEqual(laser.header.frame_id, 'base_link')
        self.assertAlmostEqual(laser.transform.translation.x, 0.1, places=9)
        self.assertAlmostEqual(laser.transform.translation.z, 0.2, places=9)
        self.assertAlmostEqual(yaw(laser.transform.rotation), math.pi / 2, places=9)
        self.assertEqual(self.received(self.tf, 'laser'), [])  # not on /tf with use_tf_static

    def test_moving_and_mimic_joints_from_joint_states(self):
        since = rospy.get_time()
        stamp = self.send(self.states, ['arm_joint', 'slide_joint', 'finger1_joint'], [0.7, 0.25, 0.3])
        arm = self.wait_for(self.tf, 'arm', since)[-1]
        self.assertEqual(arm.header.frame_id, 'base_link')
        self.assertEqual(arm.header.stamp, stamp)
        self.assertAlmostEqual(arm.transform.translation.x, 0.5, places=9)
        self.assertAlmostEqual(yaw(arm.transform.rotation), 0.7, places=9)
        slider = self.wait_for(self.tf, 'slider', since)[-1]
        self.assertEqual(slider.header.frame_id, 'arm')
        self.assertAlmostEqual(slider.transform.translation.x, 0.25, places=9)
        self.assertAlmostEqual(slider.transform.translation.y, 0.2, places=9)
        # finger2 mimics finger1 with multiplier -1, offset 0.1: -0.3 + 0.1
        finger2 = self.wait_for(self.tf, 'finger2', since)[-1]
        self.assertAlmostEqual(finger2.transform.translation.y, -0.2, places=9)
        self.assertEqual(self.received(self.tf, 'wheel', since), [])  # not in the message, not sent

    def test_publish_frequency_limits_each_joint(self):
        # 20 Hz: 30 messages 1 ms of stamp apart give one transform; a stamp 60 ms on gives another.
        # (Stamps in the past: as upstream, a stamp ahead of the clock is never held back.)
        start = rospy.Time.now() - rospy.Duration(0.5)
        since = rospy.get_time()
        for k in range(30):
            self.send(self.states, ['wheel_joint'], [0.01 * k], start + rospy.Duration(0.001 * k))
            rospy.sleep(0.002)
        self.send(self.states, ['wheel_joint'], [1.0], start + rospy.Duration(0.06))
        rospy.sleep(1.0)
        wheels = [t for t in self.received(self.tf, 'wheel', since)]
        self.assertEqual([t.header.stamp for t in wheels], [start, start + rospy.Duration(0.06)])

    def test_bad_messages_are_refused_and_the_node_goes_on(self):
        since = rospy.get_time()
        bad = JointState(name=['arm_joint', 'slide_joint'], position=[0.1])  # names without positions
        bad.header.stamp = rospy.Time.now()
        self.states.publish(bad)
        self.send(self.states, ['no_such_joint', 'arm_joint'], [1.0, -0.4])
        arm = self.wait_for(self.tf, 'arm', since)
        self.assertEqual(len(arm), 1)  # the bad message gave nothing, the unknown joint is skipped
        self.assertAlmostEqual(yaw(arm[0].transform.rotation), -0.4, places=9)

    def test_tf_prefix_and_fixed_joints_on_tf_under_the_old_name(self):
        # use_tf_static false: the fixed joint on /tf each period, dated half a second ahead.
        since = rospy.get_time()
        rospy.sleep(0.5)
        lasers = self.received(self.tf, 'r2/laser', since)
        self.assertGreaterEqual(len(lasers), 3)  # 10 Hz for 0.5 s
        self.assertLessEqual(len(lasers), 7)
        self.assertEqual(lasers[-1].header.frame_id, 'r2/base_link')
        ahead = lasers[-1].header.stamp.to_sec() - rospy.get_time()
        self.assertGreater(ahead, 0.2)
        self.assertLess(ahead, 0.55)
        self.send(self.r2_states, ['arm_joint'], [0.2])
        arm = self.wait_for(self.tf, 'r2/arm', since)[-1]
        self.assertEqual(arm.header.frame_id, 'r2/base_link')
        self.assertAlmostEqual(yaw(arm.transform.rotation), 0.2, places=9)


if __name__ == '__main__':
    rostest.rosrun('robot_state_publisher', 'robot_state_publisher_checks', RobotStatePublisherTest)
