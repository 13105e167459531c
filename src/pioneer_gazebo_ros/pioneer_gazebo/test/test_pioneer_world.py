#!/usr/bin/env python3
"""pioneer_world.launch: the maze loads, the Pioneer rests level on its wheels and caster where
it was spawned, its Hokuyo publishes 720 beams at 40 Hz that agree with the ray geometry of
config/pioneer_maze_walls.yaml, and robot_state_publisher gives the laser's frame."""
import math
import os
import sys
import unittest

import numpy as np
import rospy
import rostest
import tf2_ros
from gazebo_msgs.srv import GetLinkState, GetModelState, GetWorldProperties
from sensor_msgs.msg import CameraInfo, Image, LaserScan

PACKAGE = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(PACKAGE, 'src'))  # pioneer_gazebo.maze_walls, built or not

from pioneer_gazebo.maze_walls import load_maze, scan_ranges  # noqa: E402

SPAWN_X, SPAWN_Y = -3.2, -3.2  # pioneer_world.launch's defaults
SIGMA = 0.01                   # the Hokuyo's gaussian noise


def rpy(q):
    roll = math.atan2(2 * (q.w * q.x + q.y * q.z), 1 - 2 * (q.x * q.x + q.y * q.y))
    pitch = math.asin(max(-1.0, min(1.0, 2 * (q.w * q.y - q.z * q.x))))
    yaw = math.atan2(2 * (q.w * q.z + q.x * q.y), 1 - 2 * (q.y * q.y + q.z * q.z))
    return roll, pitch, yaw


class PioneerWorldTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node('test_pioneer_world')
        for name in ('get_model_state', 'get_link_state', 'get_world_properties'):
            rospy.wait_for_service('/gazebo/' + name, timeout=30)
        cls.get_model_state = rospy.ServiceProxy('/gazebo/get_model_state', GetModelState)
        cls.get_link_state = rospy.ServiceProxy('/gazebo/get_link_state', GetLinkState)
        cls.get_world_properties = rospy.ServiceProxy('/gazebo/get_world_properties', GetWorldProperties)
        deadline = rospy.Time.now() + rospy.Duration(30)
        while 'pioneer' not in cls.get_world_properties().model_names:
            if rospy.Time.now() > deadline:
                raise AssertionError('model pioneer was not spawned')
            rospy.sleep(0.1)
        rospy.sleep(1.0)  # let it settle on its wheels

    def test_maze_is_loaded(self):
        models = self.get_world_properties().model_names
        self.assertIn('pioneer_maze', models)
        self.assertIn('ground_plane', models)

    def test_robot_rests_level_where_it_was_spawned(self):
        samples = []
        for _ in range(20):
            s = self.get_model_state(model_name='pioneer', relative_entity_name='world')
            self.assertTrue(s.success, s.status_message)
            samples.append((s.pose.position.x, s.pose.position.y, s.pose.position.z) + rpy(s.pose.orientation))
            rospy.sleep(0.15)
        a = np.array(samples)
        print('rest: x %.5f y %.5f z %.5f roll %.5f pitch %.5f yaw %.5f; drift over %.1f s: %s'
              % (tuple(a[-1]) + (3.0, np.ptp(a, axis=0).round(6).tolist())))
        self.assertLess(np.abs(a[:, 0] - SPAWN_X).max(), 0.005)
        self.assertLess(np.abs(a[:, 1] - SPAWN_Y).max(), 0.005)
        self.assertLess(np.abs(a[:, 2]).max(), 0.003)       # base_link on the floor
        self.assertLess(np.abs(a[:, 3:5]).max(), 0.005)     # level: three points on the floor
        self.assertLess(np.abs(a[:, 5]).max(), 0.005)       # facing east
        self.assertLess(np.ptp(a, axis=0).max(), 0.001)     # and not creeping

    def test_laser_sees_the_maze(self):
        scan = rospy.wait_for_message('/pioneer/laser/scan', LaserScan, timeout=30)
        self.assertEqual(scan.header.frame_id, 'hokuyo_link')
        self.assertEqual(len(scan.ranges), 720)
        self.assertAlmostEqual(scan.angle_min, -math.pi, places=5)
        self.assertAlmostEqual(scan.angle_max, math.pi, places=5)
        self.assertAlmostEqual(scan.range_min, 0.1, places=5)
        self.assertAlmostEqual(scan.range_max, 30.0, places=5)
        laser = self.get_link_state(link_name='pioneer::hokuyo_link', reference_frame='world').link_state.pose
        yaw = rpy(laser.orientation)[2]
        maze = load_maze(os.path.join(PACKAGE, 'config', 'pioneer_maze_walls.yaml'))
        expected = np.array(scan_ranges(maze.walls, laser.position.x, laser.position.y, yaw, scan.angle_min,
                                        scan.angle_increment, len(scan.ranges)))
        errors = np.array(scan.ranges) - expected
        print('laser at (%.3f, %.3f, %.3f): 720 beams, error mean %.4f m, std %.4f m, max %.4f m'
              % (laser.position.x, laser.position.y, laser.position.z, errors.mean(), errors.std(),
                 np.abs(errors).max()))
        self.assertTrue(np.all(np.isfinite(scan.ranges)), 'a closed maze: every beam hits a wall')
        self.assertLess(np.abs(errors).max(), 6 * SIGMA)
        self.assertLess(abs(errors.mean()), 0.003)
        self.assertLess(errors.std(), 1.5 * SIGMA)

    def test_laser_rate_is_40_hz_in_sim_time(self):
        stamps = []
        sub = rospy.Subscriber('/pioneer/laser/scan', LaserScan, lambda m: stamps.append(m.header.stamp.to_sec()))
        rospy.sleep(2.0)
        sub.unregister()
        self.assertGreater(len(stamps), 20)
        self.assertAlmostEqual(float(np.median(np.diff(stamps))), 1.0 / 40, places=3)

    def test_robot_state_publisher_gives_the_laser_frame(self):
        buffer = tf2_ros.Buffer()
        tf2_ros.TransformListener(buffer)
        t = buffer.lookup_transform('base_link', 'hokuyo_link', rospy.Time(0), rospy.Duration(10))
        laser = self.get_link_state(link_name='pioneer::hokuyo_link', reference_frame='pioneer::base_link')
        p = laser.link_state.pose.position
        self.assertAlmostEqual(t.transform.translation.x, p.x, places=4)
        self.assertAlmostEqual(t.transform.translation.z, p.z, places=4)

    def test_camera_publishes_800x800_at_30_hz(self):
        image = rospy.wait_for_message('/pioneer/camera1/image_raw', Image, timeout=20)
        info = rospy.wait_for_message('/pioneer/camera1/camera_info', CameraInfo, timeout=10)
        self.assertEqual((image.width, image.height), (800, 800))
        self.assertEqual(image.header.frame_id, 'camera_optical_link')
        self.assertEqual((info.width, info.height), (800, 800))
        # 80 degrees wide: fx = 400 / tan(40 deg)
        self.assertAlmostEqual(info.K[0], 400.0 / math.tan(math.radians(40)), delta=1.0)
        stamps = []
        sub = rospy.Subscriber('/pioneer/camera1/image_raw', Image, lambda m: stamps.append(m.header.stamp.to_sec()))
        rospy.sleep(2.0)
        sub.unregister()
        self.assertGreater(len(stamps), 5)
        print('camera: %d x %d %s, %.1f Hz in sim time' % (image.width, image.height, image.encoding,
                                                           1.0 / float(np.median(np.diff(stamps)))))
        self.assertAlmostEqual(float(np.median(np.diff(stamps))), 1.0 / 30, delta=0.002)


if __name__ == '__main__':
    rostest.rosrun('pioneer_gazebo', 'test_pioneer_world', PioneerWorldTest)
