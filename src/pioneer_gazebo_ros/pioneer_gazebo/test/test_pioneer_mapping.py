#!/usr/bin/env python3
"""The Pioneer 3-DX maps its 8 x 8 m maze with the Hokuyo alone (pioneer_mapping.launch): driven
along a scripted path through nine of its cells, the mapper's pose stays within 5 cm / 2 degrees of
the ground truth (final and RMS), and the saved map's walls line up with the maze's."""
import os
import unittest

import rostest
from bullet_sim_testing.mapping import MappingRunChecks

PACKAGE = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


class PioneerMappingTest(MappingRunChecks, unittest.TestCase):
    MODEL = 'pioneer'
    CMD_VEL = '/pioneer/cmd_vel'
    WALLS = os.path.join(PACKAGE, 'config', 'pioneer_maze_walls.yaml')
    LASER_RANGE = 30.0
    TOUR = os.path.join(PACKAGE, 'config', 'mapping_tour.yaml')


if __name__ == '__main__':
    rostest.rosrun('pioneer_gazebo', 'test_pioneer_mapping', PioneerMappingTest)
