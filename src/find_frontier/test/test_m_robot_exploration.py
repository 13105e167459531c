#!/usr/bin/env python3
"""m_robot explores the Capstone maze on its own (m_robot_world.launch + nav_run.launch: the mapper,
move_base and find_frontier; or explore.launch, explore_lite's explore in find_frontier's place, with
the test's ~status naming /explore/status): the node reports completion, the map then knows at
least 95 % of the maze's reachable free area, the robot never touched a wall, every goal left room for the
robot, and the map lines up with the walls."""
import os
import unittest

import rostest

from bullet_sim_testing.exploration_checks import ExplorationChecks

M_ROBOT_SIM = os.path.join(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))), 'm_robot_gazebo')


class MRobotExplorationTest(ExplorationChecks, unittest.TestCase):
    MODEL = 'm_robot'
    WALLS = os.path.join(M_ROBOT_SIM, 'config', 'capstone_map_walls.yaml')
    OUTLINE = (0.26, 0.22)      # base 0.24 long, wheels 0.22 across; the camera's 0.02 m lip ahead
    INSCRIBED = 0.12            # the padded footprint's (costmap_common.yaml)
    STATUS = '/find_frontier/status'
    LASER_RANGE = 6.0
    # Goals keep the footprint's circumscribed radius from mapped walls and from unknown space
    # (where an unseen wall may stand): 0.18 m from the true walls, the map a cell off at worst.
    GOAL_CLEARANCE = 0.13


if __name__ == '__main__':
    rostest.rosrun('find_frontier', 'test_m_robot_exploration', MRobotExplorationTest)
