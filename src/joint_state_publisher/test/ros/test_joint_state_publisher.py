#!/usr/bin/env python3
"""joint_state_publisher.test: what a user of joint_state_publisher sees on joint_states for
test/sample_arm.urdf, and what a node that cannot start says."""
import os
import subprocess
import threading
import time
import unittest

import rospy
import rostest
from sensor_msgs.msg import JointState

NAMES = ['wheel_joint', 'shoulder', 'slide', 'mirror_joint']


class JointStatePublisherTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node('joint_state_publisher_checks')
        cls.lock = threading.Lock()
        cls.messages = []
        rospy.Subscriber('/joint_states', JointState, cls.keep, queue_size=100)
        cls.source = rospy.Publisher('/driver/joint_states', JointState, queue_size=10)
        deadline = time.time() + 20
        while cls.source.get_num_connections() == 0 and time.time() < deadline:
            time.sleep(0.05)

    @classmethod
    def keep(cls, msg):
        with cls.lock:
            cls.messages.append((time.time(), msg))

    def since(self, start):
        with self.lock:
            return [m for when, m in self.messages if when >= start]

    def wait_for(self, condition, timeout=10.0):
        start = time.time()
        while time.time() < start + timeout:
            found = [m for m in self.since(start) if condition(m)]
            if found:
                return found[-1]
            time.sleep(0.02)
        self.fail('no joint_states message as expected within %.0f s' % timeout)

    def test_1_default_positions_in_the_urdfs_order_at_the_rate(self):
        msg = self.wait_for(lambda m: True)
        self.assertEqual(list(msg.name), NAMES)
        # zeros gives the wheel 0.7; the slide's range (0.2, 0.6) excludes 0: its middle; the mirror
        # follows the shoulder at 0: -2 * 0 + 0.1.
        for got, want in zip(msg.position, [0.7, 0.0, 0.4, 0.1]):
            self.assertAlmostEqual(got, want, places=9)
        self.assertEqual(list(msg.velocity), [])
        self.assertEqual(list(msg.effort), [])
        self.assertLess(abs(msg.header.stamp.to_sec() - time.time()), 1.0)
        start = time.time()
        time.sleep(2.0)
        rate = len(self.since(start)) / 2.0
        self.assertGreater(rate, 17.0)  # rate 20
        self.assertLess(rate, 23.0)

    def test_2_a_source_topic_sets_its_joints_and_the_mimic_follows(self):
        source = JointState(name=['shoulder', 'not_in_the_urdf', 'mirror_joint'], position=[0.5, 9.0, 9.0],
                            velocity=[0.25, 9.0, 9.0])
        source.header.stamp = rospy.Time.now()
        self.source.publish(source)
        msg = self.wait_for(lambda m: abs(m.position[1] - 0.5) < 1e-9)
        self.assertAlmostEqual(msg.position[3], -2 * 0.5 + 0.1, places=9)  # a mimic joint is not set by sources
        self.assertEqual(len(msg.velocity), 4)
        self.assertAlmostEqual(msg.velocity[1], 0.25, places=9)
        self.assertAlmostEqual(msg.velocity[3], -0.5, places=9)
        self.assertAlmostEqual(msg.velocity[0], 0.0, places=9)
        self.assertAlmostEqual(msg.position[0], 0.7, places=9)  # the others keep theirs

    def run_alone(self, *params):
        """The node started by hand with private parameters; its exit status and what it printed."""
        env = dict(os.environ)
        run = subprocess.run(['rosrun', 'joint_state_publisher', 'joint_state_publisher', '__name:=lonely'] +
                             list(params), capture_output=True, text=True, timeout=30, env=env)
        return run.returncode, run.stdout + run.stderr

    def test_3_a_node_that_cannot_start_says_why(self):
        rospy.delete_param('/lonely') if rospy.has_param('/lonely') else None
        code, out = self.run_alone('_robot_description:=<robot><joint name="j" type="revolute">'
                                   '<limit lower="abc"/></joint></robot>')
        self.assertNotEqual(code, 0)
        self.assertIn("joint 'j': <limit lower=\"abc\">: expected a number", out)
        code, out = self.run_alone('_robot_description:=not xml <')
        self.assertNotEqual(code, 0)
        self.assertIn('robot_description is not XML', out)
        code, out = self.run_alone('_robot_description:=<robot/>', '_rate:=0')
        self.assertNotEqual(code, 0)
        self.assertIn('parameter rate: expected a rate > 0 Hz', out)
        code, out = self.run_alone('_robot_description:=<robot/>', '_rate:=fast', '_use_mimic_tags:=3')
        self.assertNotEqual(code, 0)  # a wrong type is an error, not the default
        self.assertIn("/lonely/rate: expected a rate > 0 Hz, got the string 'fast'", out)
        self.assertIn('/lonely/use_mimic_tags: expected true or false, got 3', out)


if __name__ == '__main__':
    rostest.rosrun('joint_state_publisher', 'joint_state_publisher_checks', JointStatePublisherTest)
