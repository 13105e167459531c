#!/usr/bin/env python3
"""hector_mapping with an odometry frame: the motion odometry reports between two scans is each
scan's first guess (use_odometry_prediction, off by default as in upstream), so jumps far beyond what the matcher
alone can follow (0.4 m and 0.5 rad between scans) are tracked; without it the same run is lost.
"""
import math
import os
import sys
import threading
import time
import unittest

import rospy
import rostest
import tf2_ros
from geometry_msgs.msg import PoseStamped, TransformStamped
from sensor_msgs.msg import LaserScan

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from test_mapping_node import ranges_from, yaw_of  # noqa: E402  (the same synthetic room)

BEAMS = 360
# Start, settle, then 4 jumps of 0.4 m ahead and 0.5 rad left between consecutive scans.
START = [(0.0, 0.0, 0.0)] * 3


def jumps():
    x, y, yaw, path = 0.0, 0.0, 0.0, []
    for _ in range(4):
        x, y, yaw = x + 0.4 * math.cos(yaw), y + 0.4 * math.sin(yaw), yaw + 0.5
        path.append((x, y, yaw))
    return path


class TwoMappers:
    """Two mappers, each in its own namespace, fed the same synthetic scans of the room (a mixin for the
    tests on scans far apart: this one and test_mapping_node_search)."""

    def start(self, node_name, namespaces):
        rospy.init_node(node_name)
        self.scans = rospy.Publisher('/scan', LaserScan, queue_size=10)
        self.lock = threading.Lock()
        self.poses = dict.fromkeys(namespaces)
        for ns in namespaces:
            rospy.Subscriber('/%s/slam_out_pose' % ns, PoseStamped, self.keep, callback_args=ns)
        deadline = time.time() + 20
        while self.scans.get_num_connections() < len(namespaces) and time.time() < deadline:
            time.sleep(0.05)

    def keep(self, msg, ns):
        with self.lock:
            self.poses[ns] = msg

    def publish_scan(self, stamp, x, y, yaw):
        """The scan a laser on a robot at (x, y, yaw) takes of the room, stamped `stamp`."""
        scan = LaserScan()
        scan.header.stamp, scan.header.frame_id = stamp, 'laser'
        scan.angle_min, scan.angle_increment = -math.pi, 2 * math.pi / BEAMS
        scan.angle_max = scan.angle_min + scan.angle_increment * (BEAMS - 1)
        scan.range_min, scan.range_max = 0.05, 20.0
        scan.ranges = ranges_from(x, y, yaw, BEAMS)
        self.scans.publish(scan)

    def wait_for_answers(self, stamp):
        """Until every mapper has published its pose for the scan stamped `stamp`."""
        deadline = time.time() + 5
        while time.time() < deadline:
            with self.lock:
                if all(p is not None and p.header.stamp == stamp for p in self.poses.values()):
                    return
            time.sleep(0.01)
        self.fail('a mapper did not answer the scan at %.3f' % stamp.to_sec())

    def error(self, ns, truth):
        with self.lock:
            p = self.poses[ns].pose
        return math.hypot(p.position.x - truth[0], p.position.y - truth[1]), \
            abs(math.remainder(yaw_of(p.orientation) - truth[2], 2 * math.pi))


class OdometryPredictionTest(TwoMappers, unittest.TestCase):
    def setUp(self):
        self.start('test_mapping_node_odometry', ['with_odometry', 'without_odometry'])
        self.tf = tf2_ros.TransformBroadcaster()

    def play(self, x, y, yaw):
        """Odometry (exact) and a scan at one stamp, then time for both mappers to match it."""
        stamp = rospy.Time.now()
        t = TransformStamped()
        t.header.stamp, t.header.frame_id, t.child_frame_id = stamp, 'odom', 'base_link'
        t.transform.translation.x, t.transform.translation.y = x, y
        t.transform.rotation.z, t.transform.rotation.w = math.sin(yaw / 2), math.cos(yaw / 2)
        self.tf.sendTransform(t)
        time.sleep(0.05)
        self.publish_scan(stamp, x, y, yaw)
        self.wait_for_answers(stamp)

    def test_jumps_are_tracked_with_odometry_and_lost_without(self):
        for pose in START + jumps():
            self.play(*pose)
        truth = jumps()[-1]
        distance, angle = self.error('with_odometry', truth)
        # Exact odometry: the match only has the map's own error to correct (a cell is 0.05 m).
        self.assertLess(distance, 0.05)
        self.assertLess(angle, 0.03)
        distance, angle = self.error('without_odometry', truth)
        # From the last pose alone, 0.4 m and 0.5 rad is beyond the matcher's reach.
        self.assertTrue(distance > 0.2 or angle > 0.1, (distance, angle))


if __name__ == '__main__':
    rostest.rosrun('hector_style_mapping', 'mapping_node_odometry', OdometryPredictionTest)
