#!/usr/bin/env python3
"""katana_arm.launch: the controllers come up through the spawner, the arm follows a
FollowJointTrajectory goal within upstream's 0.02 rad goal tolerance, the weightless links hold
the stretched arm up while gravity acts on the cans, the base laser sees the cans, and an
unknown KATANA_TYPE stops the launch with the list of types."""
import math
import os
import subprocess
import sys
import time
import unittest

import actionlib
import rospy
import rostest
from control_msgs.msg import FollowJointTrajectoryAction, FollowJointTrajectoryGoal
from controller_manager_msgs.srv import ListControllers
from sensor_msgs.msg import JointState, LaserScan
from trajectory_msgs.msg import JointTrajectoryPoint

from bullet_sim_testing.gazebo import Gazebo, set_real_time_factor

ARM = ['katana_motor1_pan_joint', 'katana_motor2_lift_joint', 'katana_motor3_lift_joint',
       'katana_motor4_lift_joint', 'katana_motor5_wrist_roll_joint']
FINGERS = ['katana_r_finger_joint', 'katana_l_finger_joint']
TABLE = 0.4             # the launch file's table_height
CANS = [(0.31, -0.18), (0.38, 0.0), (0.31, 0.18)]  # its default cans
GOAL_TOLERANCE = 0.02   # katana_arm_controller.yaml, upstream's


class KatanaArmTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node('test_katana_arm')
        cls.gazebo = Gazebo()
        cls.arm = actionlib.SimpleActionClient('/katana_arm_controller/follow_joint_trajectory',
                                               FollowJointTrajectoryAction)
        # Waits in wall time: bring-up takes what it takes, however fast sim time runs.
        deadline = time.monotonic() + 60
        while not cls.arm.wait_for_server(rospy.Duration(0.5)) and time.monotonic() < deadline:
            pass
        assert cls.arm.wait_for_server(rospy.Duration(0.1)), 'no katana_arm_controller action after 60 s'
        for i in range(len(CANS)):  # spawn_cans has run
            while not cls.gazebo.state('can_%d' % (i + 1)).success and time.monotonic() < deadline:
                time.sleep(0.1)
        set_real_time_factor(0.0)  # then as fast as it goes

    def joints(self):
        msg = rospy.wait_for_message('/joint_states', JointState, 10)
        return dict(zip(msg.name, msg.position))

    def move(self, points):
        goal = FollowJointTrajectoryGoal()
        goal.trajectory.joint_names = ARM
        for t, q in points:
            goal.trajectory.points.append(JointTrajectoryPoint(positions=q, time_from_start=rospy.Duration(t)))
        self.arm.send_goal(goal)
        self.assertTrue(self.arm.wait_for_result(rospy.Duration(60)))
        return self.arm.get_state(), self.arm.get_result()

    def test_1_spawner_started_the_controllers(self):
        listed = rospy.ServiceProxy('/controller_manager/list_controllers', ListControllers)().controller
        running = {c.name: c.type for c in listed if c.state == 'running'}
        self.assertEqual(running.get('katana_arm_controller'), 'effort_controllers/JointTrajectoryController')
        self.assertEqual(running.get('joint_state_controller'), 'joint_state_controller/JointStateController')
        self.assertEqual(set(self.joints()), set(ARM + FINGERS))

    def test_2_follows_a_trajectory_within_the_goal_tolerance(self):
        start = self.joints()
        target = [0.6, 1.0, -1.3, 0.4, 0.5]
        via = [0.3, 0.5, -0.6, 0.2, 0.25]
        state, result = self.move([(2.0, via), (4.0, target)])
        self.assertEqual(state, actionlib.GoalStatus.SUCCEEDED, result.error_string)
        self.assertEqual(result.error_code, 0)
        end = self.joints()
        for name, want in zip(ARM, target):
            self.assertLess(abs(end[name] - want), GOAL_TOLERANCE, name)
            self.assertGreater(abs(end[name] - start[name]), 0.3, name)  # it really moved

    def test_3_weightless_arm_holds_still_while_cans_feel_gravity(self):
        stretched = [0.0, 0.0, 0.0, 0.0, 0.0]  # straight out, level: the most torque gravity could need
        state, result = self.move([(3.0, stretched)])
        self.assertEqual(state, actionlib.GoalStatus.SUCCEEDED, result.error_string)
        before = self.joints()
        rospy.sleep(3.0)
        after = self.joints()
        # 4.3 kg stretched 0.3 m out would need about 10 N m at the shoulder: the 1.5 N m motor and
        # its P gain of 4 N m/rad would let it fall to the table. Weightless, it settles on the goal.
        for name in ARM:
            self.assertLess(abs(after[name]), 0.01, name)
            self.assertLessEqual(abs(after[name]), abs(before[name]) + 0.002, name)
        # The cans do feel gravity: they stand on the table top, neither sunk nor floating.
        for i in range(len(CANS)):
            z = self.gazebo.state('can_%d' % (i + 1)).pose.position.z
            self.assertAlmostEqual(z, TABLE, delta=0.002)

    def test_4_laser_sees_the_cans(self):
        scan = rospy.wait_for_message('/rrbot/laser/scan', LaserScan, 10)
        self.assertEqual((scan.header.frame_id, len(scan.ranges)), ('hokuyo_link', 720))
        # Each can at (x, y) from the laser (over the base's origin) fills the beams of its
        # silhouette, 2 asin(R / d) wide, at its distance less its radius (noise 0.01 m).
        for x, y in CANS:
            d = math.hypot(x, y)
            beam = int(round((math.atan2(y, x) - scan.angle_min) / scan.angle_increment))
            self.assertAlmostEqual(scan.ranges[beam], d - 0.033, delta=0.04)
            half = math.asin(0.033 / d) / scan.angle_increment
            for outside in (beam - int(half) - 4, beam + int(half) + 4):
                self.assertTrue(math.isinf(scan.ranges[outside]), (x, y, outside, scan.ranges[outside]))

    def test_5_unknown_katana_type_lists_the_types(self):
        env = dict(os.environ, KATANA_TYPE='katana_300_6m180')
        run = subprocess.run(['roslaunch', 'katana_arm_gazebo', 'katana_arm.launch'], env=env,
                             stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, timeout=60)
        self.assertIn('KATANA_TYPE is "katana_300_6m180", which is not an arm this workspace has. '
                      'Types: katana_450_6m90a', run.stdout)
        self.assertIn('REQUIRED process [katana_type_check', run.stdout)


if __name__ == '__main__':
    rostest.rosrun('katana_arm_gazebo', 'test_katana_arm', KatanaArmTest, sys.argv)
