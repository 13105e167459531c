#!/usr/bin/env python3
"""m_robot navigates the Capstone maze with move_base (find_frontier's move_base.launch) on the map
the mapper builds as it goes: it reaches goals across the maze without touching a wall, a goal in a
wall is aborted with move_base's text after its recoveries, a new goal preempts the current one, and
goals with a bad orientation or frame are refused at once."""
import math
import os
import unittest

import rospy
import rostest
from actionlib_msgs.msg import GoalStatus

from bullet_sim_testing.navigation import NavigationChecks

M_ROBOT_SIM = os.path.join(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))), 'm_robot_gazebo')


class MRobotNavigationTest(NavigationChecks, unittest.TestCase):
    MODEL = 'm_robot'
    WALLS = os.path.join(M_ROBOT_SIM, 'config', 'capstone_map_walls.yaml')
    OUTLINE = (0.26, 0.22)   # base 0.24 long, wheels 0.22 across; the camera's 0.02 m lip ahead
    XY_TOLERANCE = 0.15      # planner.yaml's xy_goal_tolerance
    RTF = 2.0  # 115 s -> 58 s; at 3x the local planner found no trajectory for a second in one run of two

    def test_1_it_reaches_goals_across_the_maze(self):
        # Up the east side, west along the north strip, down the west side, back to the start.
        self.reach_goals([(-0.1, 3.0, math.pi / 2), (-2.0, 4.0, math.pi), (-2.0, 1.0, -math.pi / 2),
                          (-0.3, 0.3, 0.0)])

    def test_2_a_goal_in_a_wall_is_aborted_after_the_recoveries(self):
        start = rospy.get_time()
        state, text = self.send_and_wait(self.goal(-1.041, 2.716), timeout=300)  # Wall_19's middle
        self.assertEqual(state, GoalStatus.ABORTED)
        self.assertEqual(text, 'Failed to find a valid plan. Even after executing recovery behaviors.')
        # planner_patience (5 s) before each of the 4 recoveries and after the last: 25 s at least.
        self.assertGreaterEqual(rospy.get_time() - start, 25.0)
        self.assertEqual(self.contacts_since(start), [])

    def test_3_a_new_goal_preempts_the_current_one(self):
        self.client.send_goal(self.goal(-2.0, 4.0, math.pi))
        rospy.sleep(3.0)
        first = self.current_goal_id()
        state, text = self.send_and_wait(self.goal(-0.1, 1.0, -math.pi / 2))
        self.assertEqual(self.result_of(first)[0], GoalStatus.PREEMPTED)
        self.assertEqual(state, GoalStatus.SUCCEEDED, text)
        px, py, _ = self.world_pose()
        self.assertLessEqual(math.hypot(px + 0.1, py - 1.0), self.XY_TOLERANCE + self.MAPPER_ERROR)

    def test_4_a_goal_with_a_nan_orientation_is_refused(self):
        goal = self.goal(-0.3, 1.0)
        goal.target_pose.pose.orientation.w = float('nan')
        state, text = self.send_and_wait(goal, timeout=10)
        self.assertEqual(state, GoalStatus.ABORTED)
        self.assertEqual(text, 'Aborting on goal because it was sent with an invalid quaternion')

    def test_5_a_goal_in_an_unknown_frame_is_refused_naming_it(self):
        state, text = self.send_and_wait(self.goal(-0.3, 1.0, frame='no_such_frame'), timeout=10)
        self.assertEqual(state, GoalStatus.ABORTED)
        self.assertIn('no_such_frame', text)


if __name__ == '__main__':
    rostest.rosrun('find_frontier', 'test_m_robot_navigation', MRobotNavigationTest)
