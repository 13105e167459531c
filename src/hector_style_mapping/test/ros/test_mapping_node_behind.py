#!/usr/bin/env python3
"""hector_mapping fed by `rosbag play --clock`, as a user plays a log into it.

A bag of the synthetic room (test_mapping_node's), the robot driving a circle of 1 m radius with a
1440-beam laser at 50 Hz, is played twice: at 1x (0.5 m/s and 0.5 rad/s) the node keeps up (a scan costs
it a few ms of the 20 ms between scans) and matches every scan, with no warning; at 50x (0.4 ms between
scans) it cannot: it says so ("cannot keep up ... N skipped ... the scans matched were up to X s behind
the newest received"), skips the oldest waiting scans (every scan played is either matched or counted as
skipped), and still tracks: the pose of the last scan it matched is within a map cell of the truth.

Tracking while skipping holds while the drive between two matched scans stays inside the search window
(1.4 rad): a match of M s of the wall clock is M x 50 s of the log. At 0.5 rad/s that is lost past a 56 ms
match, which a loaded CI machine reached (47 ms); so the fast play drives at 0.1 m/s and 0.1 rad/s, lost
only past a 280 ms match.
"""
import math
import os
import re
import subprocess
import sys
import tempfile
import threading
import time
import unittest

import numpy as np
import rosbag
import rospy
import rostest
from geometry_msgs.msg import PoseStamped
from rosgraph_msgs.msg import Log
from sensor_msgs.msg import LaserScan
from std_msgs.msg import String

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from test_mapping_node import LASER_X, ROOM, yaw_of  # noqa: E402  (the same synthetic room)

BEAMS = 1440
RATE = 50.0  # scans per second of the log
FAST, SLOW = 0.5, 0.1  # m/s and rad/s alike: a circle of 1 m radius
BEHIND = re.compile(r'cannot keep up with the scans on /scan: (\d+) skipped in the last [\d.]+ s, (\d+) in all.*'
                    r'up to ([\d.]+) s behind the newest received')


def ranges_from(x, y, yaw):
    """The laser's ranges of ROOM from a robot at (x, y, yaw), BEAMS over the full circle (vectorised)."""
    ox, oy = x + LASER_X * math.cos(yaw), y + LASER_X * math.sin(yaw)
    a = yaw - math.pi + np.arange(BEAMS) * 2 * math.pi / BEAMS
    dx, dy = np.cos(a), np.sin(a)
    best = np.full(BEAMS, np.inf)
    for (x1, y1), (x2, y2) in ROOM:
        ex, ey = x2 - x1, y2 - y1
        den = dx * ey - dy * ex
        with np.errstate(divide='ignore', invalid='ignore'):
            t = ((x1 - ox) * ey - (y1 - oy) * ex) / den
            u = ((x1 - ox) * dy - (y1 - oy) * dx) / den
        hit = (np.abs(den) > 1e-12) & (t > 0) & (u >= 0) & (u <= 1)
        best = np.where(hit, np.minimum(best, t), best)
    return best


def truth_at(t, speed):
    """The robot's pose t s into the drive at `speed` m/s and rad/s: from the origin facing +x, a circle of
    1 m radius to the left."""
    yaw = speed * t
    return math.sin(yaw), 1 - math.cos(yaw), yaw


def write_bag(path, start, scans, speed):
    with rosbag.Bag(path, 'w') as bag:
        for i in range(scans):
            t = i / RATE
            scan = LaserScan()
            scan.header.seq = i
            scan.header.stamp = rospy.Time.from_sec(start + t)
            scan.header.frame_id = 'laser'
            scan.angle_min, scan.angle_increment = -math.pi, 2 * math.pi / BEAMS
            scan.angle_max = scan.angle_min + scan.angle_increment * (BEAMS - 1)
            scan.range_min, scan.range_max = 0.05, 20.0
            scan.ranges = ranges_from(*truth_at(t, speed)).tolist()
            bag.write('/scan', scan, scan.header.stamp)


class BehindTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node('test_mapping_node_behind')
        cls.lock = threading.Lock()
        cls.poses, cls.warnings = [], []
        rospy.Subscriber('/slam_out_pose', PoseStamped, cls.keep_pose, queue_size=10000)
        rospy.Subscriber('/rosout', Log, cls.keep_log, queue_size=1000)
        cls.syscommand = rospy.Publisher('/syscommand', String, queue_size=1, latch=True)
        cls.dir = tempfile.mkdtemp(prefix='mapping_node_behind_')

    @classmethod
    def keep_pose(cls, msg):
        with cls.lock:
            cls.poses.append(msg)

    @classmethod
    def keep_log(cls, msg):
        if msg.name == '/hector_mapping' and msg.level == Log.WARN and 'cannot keep up' in msg.msg:
            with cls.lock:
                cls.warnings.append(msg.msg)

    def play(self, start, scans, speed, rate):
        """Plays the drive at `speed` (stamps from `start` s) at `rate` times the log's pace; the poses the node
        answered, and its warnings."""
        path = os.path.join(self.dir, 'drive_%g.bag' % start)
        write_bag(path, start, scans, speed)
        with self.lock:
            del self.poses[:]
            del self.warnings[:]
        # rosbag's outgoing queue (100 by default) holds the whole drive: at 50x it publishes faster than a busy
        # machine's transport takes, and a scan it drops the node never sees, to count or to match.
        subprocess.check_call(['rosbag', 'play', '--clock', '--quiet', '-d', '1', '--queue', '1000', '-r', str(rate),
                               path],
                              stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, timeout=90)
        time.sleep(1.5)  # the last answers, and the report of the last second
        with self.lock:
            return list(self.poses), list(self.warnings)

    def error(self, pose, start, speed):
        x, y, yaw = truth_at(pose.header.stamp.to_sec() - start, speed)
        p = pose.pose
        return math.hypot(p.position.x - x, p.position.y - y), \
            abs(math.remainder(yaw_of(p.orientation) - yaw, 2 * math.pi))

    def test_1_at_1x_every_scan_is_matched(self):
        scans = 200
        poses, warnings = self.play(10.0, scans, FAST, 1.0)
        self.assertEqual(warnings, [])
        self.assertEqual(len(poses), scans)
        self.assertEqual(len({p.header.stamp for p in poses}), scans)
        worst = max(self.error(p, 10.0, FAST)[0] for p in poses)
        self.assertLess(worst, 0.05)

    def test_2_at_50x_it_says_it_is_behind_and_still_tracks(self):
        self.syscommand.publish(String('reset'))
        time.sleep(0.5)
        scans = 1000  # 20 s of the log, 2 rad of the circle
        poses, warnings = self.play(100.0, scans, SLOW, 50.0)
        self.assertGreaterEqual(len(warnings), 1, 'no "cannot keep up" warning')
        reports = [BEHIND.search(w) for w in warnings]
        self.assertTrue(all(reports), warnings)
        skipped_in_all = max(int(r.group(2)) for r in reports)
        # Matched scans were at most the queue (5 scans, 0.1 s of the log) behind the newest, and one or
        # two behind at least.
        most_behind = max(float(r.group(3)) for r in reports)
        self.assertGreaterEqual(most_behind, 1.0 / RATE - 1e-6)
        self.assertLessEqual(most_behind, 6.0 / RATE + 1e-6)
        # Every scan played is matched or counted as skipped (at 1x, none was skipped).
        self.assertEqual(len(poses) + skipped_in_all, scans)
        self.assertGreater(skipped_in_all, scans // 2)  # 0.4 ms between scans, a few ms a match
        self.assertGreater(len(poses), 10)  # it went on matching
        last = max(poses, key=lambda p: p.header.stamp)
        self.assertGreater(last.header.stamp.to_sec() - 100.0, 0.8 * (scans - 1) / RATE)  # near the end
        # Tracking, not lost (lost is metres and radians off: 2.9 m in a CI run of the old 100x play at 0.5 rad/s,
        # whose slowest match, 47 ms, left 4.7 s of the drive between two matched scans). A CI run ended 0.04 rad
        # off, likely loop closure's 0.01 rad constraints between keyframes, adopted whenever the worker finds them.
        distance, angle = self.error(last, 100.0, SLOW)
        self.assertLess(distance, 0.05)
        self.assertLess(angle, 0.06)


if __name__ == '__main__':
    rostest.rosrun('hector_style_mapping', 'mapping_node_behind', BehindTest)
