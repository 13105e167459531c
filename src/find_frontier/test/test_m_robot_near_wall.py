#!/usr/bin/env python3
"""m_robot starts 2 cm from the Capstone maze's east wall, turned towards it, so that its padded
footprint already covers the wall's cells. Every move then touches an obstacle, as upstream's
local planners check a footprint, unless the obstacle layer frees the cells under the robot
(costmap_2d's footprint_clearing_enabled, on by default): without it move_base gives up with
"Failed to find a valid control. Even after executing recovery behaviors.". The robot must get
clear and reach a goal up the corridor without touching the wall."""
import math
import os
import unittest

import rospy
import rostest
from actionlib_msgs.msg import GoalStatus

from bullet_sim_testing.navigation import NavigationChecks

M_ROBOT_SIM = os.path.join(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))), 'm_robot_gazebo')
EAST_WALL_FACE = 0.405       # Wall_1's inner face (world x)
PADDED = (0.15, 0.12)        # costmap_common.yaml's footprint + footprint_padding: half length, half width


class MRobotNearWallTest(NavigationChecks, unittest.TestCase):
    MODEL = 'm_robot'
    WALLS = os.path.join(M_ROBOT_SIM, 'config', 'capstone_map_walls.yaml')
    OUTLINE = (0.26, 0.22)
    XY_TOLERANCE = 0.15
    MAP_IN_WORLD = (0.22, 0.0, 0.5)  # the test's spawn pose: the map frame starts there

    def test_it_gets_clear_of_the_wall_and_reaches_the_goal(self):
        x, y, yaw = self.world_pose()
        reach = x + PADDED[0] * math.cos(yaw) + PADDED[1] * math.sin(yaw)
        self.assertGreater(reach, EAST_WALL_FACE - 0.01, 'the padded footprint should start on the wall')
        self.assertEqual(self.contacts_since(0.0), [], 'the robot itself should start clear of the wall')
        gx, gy, gyaw = self.world_to_map(-0.1, 1.2, math.pi / 2)
        self.reach_goals([(gx, gy, gyaw)])


if __name__ == '__main__':
    rostest.rosrun('find_frontier', 'test_m_robot_near_wall', MRobotNearWallTest)
