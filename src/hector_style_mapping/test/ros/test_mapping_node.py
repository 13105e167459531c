#!/usr/bin/env python3
"""hector_mapping (this package's node) as a user sees it, fed synthetic scans of a room.

Its interface (latched map and map_metadata, slam_out_pose, poseupdate, the map -> base_link and
map -> scanmatcher_frame tf, dynamic_map); that it follows the laser as it moves; that bad input
(NaN/inf ranges, fewer or changing beams, angle_increment 0, stamps going back, a frame without tf,
no usable beam) gets a clear, throttled warning and never stops it; reset_map and syscommand
'reset' mid-run; and that bad parameters stop it at start with a message naming them.
"""
import math
import os
import subprocess
import tempfile
import threading
import time
import unittest

import numpy as np
import PyKDL
import rospy
import rostest
import tf2_ros
from geometry_msgs.msg import PoseStamped, PoseWithCovarianceStamped
from nav_msgs.msg import MapMetaData, OccupancyGrid
from nav_msgs.srv import GetMap
from rosgraph_msgs.msg import Log
from sensor_msgs.msg import LaserScan
from std_msgs.msg import String
from std_srvs.srv import Trigger
from tf2_msgs.msg import TFMessage

LASER_X = 0.1  # the launch file's base_link -> laser


def _turned(segments, angle):
    c, s = math.cos(angle), math.sin(angle)
    return [tuple((c * x - s * y, s * x + c * y) for x, y in segment) for segment in segments]


# The room, in the map frame (the robot starts at the origin facing +x): walls from x -2.5 to 3.5
# and y -1.7 to 2.3 and a 0.6 x 0.4 m box at (1.5, 1.0), turned 10 degrees about the origin. Not
# grid-aligned on purpose: noise-free walls along the grid with their faces on cell boundaries are
# the mapper's known worst case (half a cell; test_mapping_core and docs/MAPPING.md), and this test
# is about the node.
ROOM = _turned([((-2.5, -1.7), (3.5, -1.7)), ((3.5, -1.7), (3.5, 2.3)), ((3.5, 2.3), (-2.5, 2.3)),
                ((-2.5, 2.3), (-2.5, -1.7)), ((1.2, 0.8), (1.8, 0.8)), ((1.8, 0.8), (1.8, 1.2)),
                ((1.8, 1.2), (1.2, 1.2)), ((1.2, 1.2), (1.2, 0.8))], math.radians(10))


def ranges_from(x, y, yaw, beams, fov=2 * math.pi):
    """Ranges of a laser LASER_X ahead of a robot at (x, y, yaw), beam i at -fov/2 + i * fov / beams."""
    ox, oy = x + LASER_X * math.cos(yaw), y + LASER_X * math.sin(yaw)
    out = []
    for i in range(beams):
        a = yaw - fov / 2 + i * fov / beams
        dx, dy = math.cos(a), math.sin(a)
        best = math.inf
        for (x1, y1), (x2, y2) in ROOM:
            ex, ey = x2 - x1, y2 - y1
            den = dx * ey - dy * ex
            if abs(den) < 1e-12:
                continue
            t = ((x1 - ox) * ey - (y1 - oy) * ex) / den
            u = ((x1 - ox) * dy - (y1 - oy) * dx) / den
            if t > 0 and 0 <= u <= 1:
                best = min(best, t)
        out.append(best)
    return out


def yaw_of(q):
    return PyKDL.Rotation.Quaternion(q.x, q.y, q.z, q.w).GetRPY()[2]


class MappingNodeTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node('test_mapping_node')
        cls.scan_pub = rospy.Publisher('/scan', LaserScan, queue_size=50)
        cls.sys_pub = rospy.Publisher('/syscommand', String, queue_size=2, latch=False)
        cls.lock = threading.Lock()
        cls.poses, cls.pose_updates, cls.logs, cls.map_tf_stamps = [], [], [], []
        pose_subscribers = [
            rospy.Subscriber('/slam_out_pose', PoseStamped, lambda m: cls._keep(cls.poses, m)),
            rospy.Subscriber('/poseupdate', PoseWithCovarianceStamped, lambda m: cls._keep(cls.pose_updates, m))]
        rospy.Subscriber('/tf', TFMessage, cls._on_tf)
        rospy.Subscriber('/rosout', Log, lambda m: cls._keep(cls.logs, m) if m.name.endswith('hector_mapping') else None)
        cls.tf = tf2_ros.Buffer()
        cls.tf_listener = tf2_ros.TransformListener(cls.tf)
        rospy.wait_for_service('/dynamic_map', timeout=30)
        cls.get_map = rospy.ServiceProxy('/dynamic_map', GetMap)
        cls.reset_map = rospy.ServiceProxy('/reset_map', Trigger)
        deadline = time.time() + 10
        # Connected both ways before the first scan, so that its pose is not published to nobody.
        while (cls.scan_pub.get_num_connections() == 0 or any(
                sub.get_num_connections() == 0 for sub in pose_subscribers)) and time.time() < deadline:
            time.sleep(0.05)
        cls.last_stamp = rospy.Time.now()

    @classmethod
    def _on_tf(cls, msg):
        for t in msg.transforms:
            if t.header.frame_id == 'map' and t.child_frame_id == 'base_link':
                cls._keep(cls.map_tf_stamps, t.header.stamp)

    @classmethod
    def _keep(cls, store, msg):
        with cls.lock:
            store.append(msg)

    # --- helpers --------------------------------------------------------------------------------

    def scan(self, ranges, frame='laser', stamp=None, angle_min=-math.pi, increment=None, declared_beams=None):
        """Publishes a scan; by default stamped after the previous one, angles for len(ranges) beams."""
        n = declared_beams if declared_beams is not None else len(ranges)
        increment = 2 * math.pi / max(n, 1) if increment is None else increment
        msg = LaserScan()
        if stamp is None:
            stamp = max(rospy.Time.now(), type(self).last_stamp + rospy.Duration(0.01))
            type(self).last_stamp = stamp
        msg.header.stamp, msg.header.frame_id = stamp, frame
        msg.angle_min, msg.angle_increment = angle_min, increment
        msg.angle_max = angle_min + increment * (n - 1)
        msg.range_min, msg.range_max = 0.05, 20.0
        msg.ranges = ranges
        self.scan_pub.publish(msg)
        time.sleep(0.03)

    def drive(self, path, beams=360):
        for x, y, yaw in path:
            self.scan(ranges_from(x, y, yaw, beams))

    def latest_pose(self, after=None, timeout=5.0):
        deadline = time.time() + timeout
        while time.time() < deadline:
            with self.lock:
                if self.poses and (after is None or self.poses[-1].header.stamp >= after):
                    p = self.poses[-1].pose
                    return p.position.x, p.position.y, yaw_of(p.orientation)
            time.sleep(0.02)
        self.fail('no slam_out_pose within %.0f s' % timeout)

    def warnings_containing(self, text, since):
        with self.lock:
            return [m.msg for m in self.logs if m.level >= Log.WARN and text in m.msg and m.header.stamp >= since]

    def known_cells(self):
        grid = self.get_map().map
        data = np.array(grid.data)
        return int((data == 100).sum()), int((data == 0).sum())

    def assert_still_mapping(self, where=(0.0, 0.0, 0.0)):
        """The node answers and still locates a good scan taken at `where`."""
        stamp = rospy.Time.now()
        self.drive([where] * 3)
        x, y, yaw = self.latest_pose(after=stamp)
        self.assertLess(math.hypot(x - where[0], y - where[1]), 0.03, (x, y, yaw))
        self.assertLess(abs(yaw - where[2]), 0.02)

    # --- interface ------------------------------------------------------------------------------

    def test_1_map_pose_and_tf_as_hector_mapping_offers_them(self):
        self.drive([(0.0, 0.0, 0.0)] * 5)
        grid = rospy.wait_for_message('/map', OccupancyGrid, timeout=5)
        meta = rospy.wait_for_message('/map_metadata', MapMetaData, timeout=5)
        self.assertEqual((grid.info.width, grid.info.height), (256, 256))
        self.assertAlmostEqual(grid.info.resolution, 0.05, places=6)
        self.assertEqual(meta.width, 256)
        self.assertEqual(grid.header.frame_id, 'map')
        # map_start 0.5: the map frame's origin is the middle of the map.
        self.assertAlmostEqual(grid.info.origin.position.x, -6.4, places=6)
        occupied, free = self.known_cells()
        self.assertGreater(occupied, 300)
        self.assertGreater(free, 3000)
        x, y, yaw = self.latest_pose()
        self.assertLess(math.hypot(x, y), 0.02)
        with self.lock:
            self.assertTrue(self.pose_updates, 'nothing on /poseupdate')
            update = self.pose_updates[-1]
        self.assertEqual(update.header.frame_id, 'map')
        c = np.array(update.pose.covariance).reshape(6, 6)[np.ix_([0, 1, 5], [0, 1, 5])]
        self.assertTrue(np.allclose(c, c.T))
        self.assertTrue(np.all(np.linalg.eigvalsh(c) > 0), c)
        for child in ('base_link', 'scanmatcher_frame', 'laser'):
            self.assertTrue(self.tf.can_transform('map', child, rospy.Time(0), rospy.Duration(5)), child)

    def test_2_follows_the_laser_as_the_robot_moves(self):
        path = [(0.02 * i, 0.01 * i, 0.004 * i) for i in range(41)]  # to (0.8, 0.4, 0.16 rad)
        try:
            self.drive(path)
            x, y, yaw = self.latest_pose(after=type(self).last_stamp)
            print('mapper after a 0.9 m drive: (%.4f, %.4f, %.4f), truth (0.8, 0.4, 0.16)' % (x, y, yaw))
            self.assertLess(math.hypot(x - 0.8, y - 0.4), 0.02)
            self.assertLess(abs(yaw - 0.16), 0.01)
            with self.lock:  # the tf of the same scan (the newest may still be one scan behind)
                stamp = self.poses[-1].header.stamp
            t = self.tf.lookup_transform('map', 'base_link', stamp, rospy.Duration(2))
            self.assertAlmostEqual(t.transform.translation.x, x, delta=0.01)
        finally:
            self.drive(reversed(path))  # back to the origin for the tests that follow

    # --- bad input ------------------------------------------------------------------------------

    def test_3_nan_and_inf_ranges(self):
        since = rospy.Time.now()
        ranges = ranges_from(0, 0, 0, 360)
        for i in range(0, 360, 7):
            ranges[i] = float('nan')
        for i in range(3, 360, 11):
            ranges[i] = float('inf')
        for _ in range(10):
            self.scan(list(ranges))
        self.assert_still_mapping()
        nan_warnings = self.warnings_containing('NaN', since)
        self.assertGreaterEqual(len(nan_warnings), 1)
        self.assertLessEqual(len(nan_warnings), 1, 'not throttled: %s' % nan_warnings)
        self.assertIn('ignored', nan_warnings[0])

    def test_4_fewer_or_changing_beam_counts(self):
        since = rospy.Time.now()
        full = ranges_from(0, 0, 0, 360)
        self.scan(full[:300], declared_beams=360)  # the angles say 360
        for beams in (720, 180, 359, 1080):
            self.scan(ranges_from(0, 0, 0, beams))
        self.assert_still_mapping()
        warnings = self.warnings_containing('300 ranges where its angles make 360', since)
        self.assertEqual(len(warnings), 1, warnings)

    def test_5_scans_that_cannot_be_used(self):
        since = rospy.Time.now()
        self.scan(ranges_from(0, 0, 0, 360), increment=0.0)       # no angles
        self.scan([float('inf')] * 360)                           # nothing seen
        self.scan([])                                             # nothing at all
        self.scan(ranges_from(0, 0, 0, 360), frame='nowhere')     # no tf for its frame
        self.assert_still_mapping()
        self.assertTrue(self.warnings_containing('angle_increment', since))
        self.assertTrue(self.warnings_containing('no usable beam', since))
        no_tf = self.warnings_containing("'nowhere'", since)
        self.assertTrue(no_tf)
        self.assertIn('Scan dropped', no_tf[0])

    def test_6_stamps_going_back(self):
        since = rospy.Time.now()
        self.drive([(0.0, 0.0, 0.0)] * 2)
        older = type(self).last_stamp - rospy.Duration(0.3)
        with self.lock:
            count = len(self.poses)
        for _ in range(20):  # a burst: one warning, not twenty
            self.scan(ranges_from(0.5, 0.5, 0.5, 360), stamp=older)
        time.sleep(0.5)
        with self.lock:
            self.assertEqual(len(self.poses), count, 'an out-of-order scan was used')
        warnings = self.warnings_containing('is not newer than the last one', since)
        self.assertEqual(len(warnings), 1, warnings)
        self.assert_still_mapping()
        # A clock restarted (10 s back): taken as a new time line, said once, and mapping goes on
        # (the static laser tf survives the tf buffer being cleared).
        restart = type(self).last_stamp - rospy.Duration(10.0)
        self.scan(ranges_from(0, 0, 0, 360), stamp=restart)
        self.assert_still_mapping()
        self.assertEqual(len(self.warnings_containing('time went back', since)), 1)
        with self.lock:  # map -> base_link went out on the new time line too
            self.assertIn(restart, self.map_tf_stamps)

    # --- reset ----------------------------------------------------------------------------------

    def test_7_reset_map_service_and_syscommand_mid_run(self):
        for reset in (lambda: self.assertTrue(self.reset_map().success),
                      lambda: self.sys_pub.publish(String('reset'))):
            out = [(0.02 * i, 0.0, 0.0) for i in range(10)]
            self.drive(out + out[::-1])  # out and back: the reset comes with the robot at the origin
            self.assertGreater(self.known_cells()[0], 100)
            deadline = time.time() + 5
            while self.sys_pub.get_num_connections() == 0 and time.time() < deadline:
                time.sleep(0.05)
            reset()
            deadline = time.time() + 5
            while self.known_cells() != (0, 0) and time.time() < deadline:
                time.sleep(0.05)
            self.assertEqual(self.known_cells(), (0, 0), 'the map is not empty after the reset')
            latched = rospy.wait_for_message('/map', OccupancyGrid, timeout=5)
            self.assertTrue(all(v == -1 for v in latched.data))
            # Mapping starts over where the robot now is: that pose becomes the origin.
            self.assert_still_mapping((0.0, 0.0, 0.0))
            self.assertGreater(self.known_cells()[0], 100)

    # --- saving ---------------------------------------------------------------------------------

    def test_7b_save_map_writes_map_server_files_and_a_png(self):
        self.drive([(0.0, 0.0, 0.0)] * 3)
        time.sleep(0.5)  # a map publication (map_pub_period 0.2 s)
        base = os.path.join(tempfile.mkdtemp(), 'new_folder', 'room')
        run = subprocess.run(['rosrun', 'hector_style_mapping', 'save_map', '-f', base], stdout=subprocess.PIPE,
                             stderr=subprocess.STDOUT, text=True, timeout=60)
        self.assertEqual(run.returncode, 0, run.stdout)
        with open(base + '.yaml') as f:
            meta = f.read()
        self.assertIn('image: room.pgm', meta)
        self.assertIn('resolution: 0.050000', meta)
        with open(base + '.pgm', 'rb') as f:
            self.assertTrue(f.read(2) == b'P5')
        self.assertGreater(os.path.getsize(base + '.png'), 0)

    def test_7c_save_map_says_why_it_cannot_write(self):
        run = subprocess.run(['rosrun', 'hector_style_mapping', 'save_map', '-f', '/proc/no_such_place/room'],
                             stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, timeout=60)
        self.assertEqual(run.returncode, 1, run.stdout)
        self.assertIn('save_map: cannot write /proc/no_such_place/room.pgm', run.stdout)
        self.assertNotIn('Traceback', run.stdout)

    # --- configuration --------------------------------------------------------------------------

    def test_8_bad_parameters_stop_the_node_with_a_message_naming_them(self):
        run = subprocess.run(['rosrun', 'hector_style_mapping', 'hector_mapping', '__name:=bad_mapper',
                              '_map_resolution:=-0.05', '_map_size:=abc', '_laser_min_dist:=5.0',
                              '_laser_max_dist:=1.0'],
                             stdout=subprocess.PIPE, stderr=subprocess.STDOUT, timeout=60, text=True,
                             env=dict(os.environ))
        self.assertEqual(run.returncode, 1, run.stdout)
        for text in ('map_resolution', "/bad_mapper/map_size: expected an integer, got the string 'abc'", 'laser_min_dist'):
            self.assertIn(text, run.stdout)

    def test_9_unknown_parameters_are_named(self):
        # A second mapper in a namespace of its own (no scans reach it), with a misspelt parameter.
        process = subprocess.Popen(['rosrun', 'hector_style_mapping', 'hector_mapping', '__ns:=/other',
                                    '__name:=typo_mapper', '_map_resolutoin:=0.1'],
                                   stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, env=dict(os.environ))
        try:
            rospy.wait_for_service('/other/dynamic_map', timeout=30)
        finally:
            process.terminate()
            output = process.communicate(timeout=30)[0]
        self.assertIn('ignored /other/typo_mapper/map_resolutoin (did you mean map_resolution?): not a parameter of '
                      'hector_mapping', output)


if __name__ == '__main__':
    rostest.rosrun('hector_style_mapping', 'test_mapping_node', MappingNodeTest)
