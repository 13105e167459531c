#!/usr/bin/env python3
"""The Pioneer explores its maze on its own (explore.launch: pioneer_navigation.launch with slam_gmapping,
and explore_lite's explore): explore reports completion, the map then knows at least 95 % of the maze's reachable
free area, the robot never touched a wall, every goal left room for the robot, and the map lines
up with the walls."""
import os
import unittest

import rospkg
import rostest

from bullet_sim_testing.exploration_checks import ExplorationChecks

PIONEER_SIM = rospkg.RosPack().get_path('pioneer_gazebo')


class PioneerExploreTest(ExplorationChecks, unittest.TestCase):
    MODEL = 'pioneer'
    WALLS = os.path.join(PIONEER_SIM, 'config', 'pioneer_maze_walls.yaml')
    OUTLINE = (0.44, 0.38)      # the top plate; the tyres reach 0.19 m either side
    OUTLINE_CENTRE_X = -0.045   # the plate's centre is behind the axle (base_link)
    MAP_IN_WORLD = (0.0, 0.0, 0.0)  # slam_gmapping's map frame is the world's (explore.launch's mapper)
    START = (-3.2, -3.2)
    INSCRIBED = 0.2             # the padded footprint's (costmap_common_params.yaml)
    STATUS = '/explore/status'
    LASER_RANGE = 30.0
    TIMEOUT = 1500.0
    # Goals keep the footprint's circumscribed radius from mapped walls and from unknown space
    # (where an unseen wall may stand): 0.36 m from the true walls, the map a cell off at worst.
    GOAL_CLEARANCE = 0.3


if __name__ == '__main__':
    rostest.rosrun('pioneer_2dnav', 'test_pioneer_explore', PioneerExploreTest)
