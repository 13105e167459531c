#!/usr/bin/env python3
"""A laser spawned by launch file (xacro -> spawn_model) in a closed room: every beam agrees
with the ray-geometry distance to the walls within the configured noise."""
import math
import unittest

import numpy as np
import rospy
import rostest
from sensor_msgs.msg import LaserScan

from bullet_sim_testing.gazebo import Gazebo

# laser_room.world's inner wall faces and laser_post's placement (see laser_room.test).
WALLS_X = (-2.0, 3.0)
WALLS_Y = (-1.5, 2.5)
LASER_X, LASER_Y, LASER_YAW = 0.3, 0.2, 0.3
SAMPLES, RANGE_MIN, RANGE_MAX, SIGMA = 181, 0.10, 3.0, 0.01


def distance_to_walls(x, y, heading):
    dx, dy = math.cos(heading), math.sin(heading)
    hits = []
    for wall in WALLS_X:
        if abs(dx) > 1e-12 and (wall - x) / dx > 0:
            hits.append((wall - x) / dx)
    for wall in WALLS_Y:
        if abs(dy) > 1e-12 and (wall - y) / dy > 0:
            hits.append((wall - y) / dy)
    return min(hits)


class LaserRoomTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node('test_laser_room')
        cls.gz = Gazebo()

    def test_ranges_match_the_room_geometry(self):
        scan = rospy.wait_for_message('/laser_post/scan', LaserScan, timeout=30)
        self.assertEqual(scan.header.frame_id, 'laser_link')
        self.assertGreater(scan.header.stamp.to_sec(), 0.0)
        self.assertEqual(len(scan.ranges), SAMPLES)
        self.assertAlmostEqual(scan.angle_increment, (scan.angle_max - scan.angle_min) / (SAMPLES - 1), places=6)
        self.assertAlmostEqual(scan.range_max, RANGE_MAX, places=6)
        errors, beyond = [], 0
        for i, measured in enumerate(scan.ranges):
            expected = distance_to_walls(LASER_X, LASER_Y, LASER_YAW + scan.angle_min + i * scan.angle_increment)
            if expected > RANGE_MAX + 5 * SIGMA:
                self.assertEqual(measured, float('inf'), 'beam %d: expected +inf (REP 117), got %f' % (i, measured))
                beyond += 1
            elif expected < RANGE_MAX - 5 * SIGMA:
                self.assertLess(abs(measured - expected), 5 * SIGMA, 'beam %d: %f vs %f' % (i, measured, expected))
                errors.append(measured - expected)
        errors = np.array(errors)
        print('laser: %d beams compared, mean error %.4f m, std %.4f m (noise sigma %.3f), %d beams beyond range'
              % (len(errors), errors.mean(), errors.std(), SIGMA, beyond))
        self.assertGreater(len(errors), 100)
        self.assertGreater(beyond, 0)
        self.assertLess(abs(errors.mean()), 0.004)
        self.assertLess(errors.std(), 2 * SIGMA)
        self.assertGreater(errors.std(), 0.5 * SIGMA)  # the noise is there

    def test_scans_arrive_at_the_update_rate_in_sim_time(self):
        stamps = []
        sub = rospy.Subscriber('/laser_post/scan', LaserScan, lambda m: stamps.append(m.header.stamp.to_sec()))
        deadline = rospy.Time.now() + rospy.Duration(2.0)
        while rospy.Time.now() < deadline and not rospy.is_shutdown():
            rospy.sleep(0.05)
        sub.unregister()
        self.assertGreater(len(stamps), 10)
        periods = np.diff(stamps)
        self.assertAlmostEqual(float(np.median(periods)), 1.0 / 20, places=3)


if __name__ == '__main__':
    rostest.rosrun('bullet_sim', 'test_laser_room', LaserRoomTest)
