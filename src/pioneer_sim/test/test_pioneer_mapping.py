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
    SPEED = 0.4
    # Cell centres (config/pioneer_maze_walls.yaml's drawing), from the start cell (-3.2, -3.2):
    # east along the south row, north up the middle, west and back down, up the west column to
    # the north-west corner, east along the top row, then down into the east half.
    WAYPOINTS = [(0.0, -3.2), (0.0, -1.6), (0.0, 0.0), (-1.6, 0.0), (-1.6, -1.6), (-3.2, -1.6), (-3.2, 3.2),
                 (0.0, 3.2), (0.0, 1.6), (1.6, 1.6), (1.6, 0.0)]


if __name__ == '__main__':
    rostest.rosrun('pioneer_sim', 'test_pioneer_mapping', PioneerMappingTest)
