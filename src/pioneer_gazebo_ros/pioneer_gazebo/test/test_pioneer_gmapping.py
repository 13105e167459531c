#!/usr/bin/env python3
"""The Pioneer report's `rosrun gmapping slam_gmapping scan:=/pioneer/laser/scan` maps the Pioneer's
maze (pioneer_gmapping.launch): driven along the mapping rostest's path, the pose slam_gmapping gives
(tf map -> base_link) stays within 5 cm / 2 degrees of the ground truth (final and RMS), and the saved
map's walls line up with the maze's. Its map frame is the odom frame at the start: the world's."""
import os
import unittest

import rostest
from bullet_sim_testing.mapping import MappingRunChecks

PACKAGE = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


class PioneerGmappingTest(MappingRunChecks, unittest.TestCase):
    MODEL = 'pioneer'
    CMD_VEL = '/pioneer/cmd_vel'
    WALLS = os.path.join(PACKAGE, 'config', 'pioneer_maze_walls.yaml')
    LASER_RANGE = 30.0
    TOUR = os.path.join(PACKAGE, 'config', 'mapping_tour.yaml')
    POSE_TOPIC = None
    TF_POSE = ('map', 'base_link')
    MAP_IN_WORLD = (0.0, 0.0, 0.0)


if __name__ == '__main__':
    rostest.rosrun('pioneer_gazebo', 'test_pioneer_gmapping', PioneerGmappingTest)
