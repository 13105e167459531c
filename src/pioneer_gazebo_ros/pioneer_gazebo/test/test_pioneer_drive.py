#!/usr/bin/env python3
"""The Pioneer 3-DX in its maze (pioneer_world.launch): the diff drive covers the commanded
distance with agreeing odometry, turns in place and stops at a wall; the Hokuyo agrees with the
maze's geometry; camera1 sends 800x800 images that change as it turns; tf reaches the sensors'
frames from odom."""
import os
import unittest

import rostest
from bullet_sim_testing.mobile import MobileRobotChecks

PACKAGE = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


class PioneerDriveTest(MobileRobotChecks, unittest.TestCase):
    MODEL = 'pioneer'
    CMD_VEL = '/pioneer/cmd_vel'
    ODOM = '/pioneer/odom'
    SCAN = '/pioneer/laser/scan'
    CAMERA = '/pioneer/camera1'
    IMAGE_SIZE = (800, 800)
    WALLS = os.path.join(PACKAGE, 'config', 'pioneer_maze_walls.yaml')
    LASER_SIGMA = 0.01
    SENSOR_FRAMES = ('base_link', 'hokuyo_link', 'camera_optical_link')
    SPAWN_Z = 0.0                   # base_link on the floor
    MAZE_POSE = (-3.2, -3.2, 0.0)   # the launch file's spawn point


if __name__ == '__main__':
    rostest.rosrun('pioneer_gazebo', 'test_pioneer_drive', PioneerDriveTest)
