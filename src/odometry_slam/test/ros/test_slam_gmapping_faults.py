#!/usr/bin/env python3
"""slam_gmapping's faults, seen as a user sees them (its /rosout messages, its topics and service):
scans without odometry tf get the clear message and no map; once odometry comes the room is mapped
(walls 2 m away where they are); bad scans (NaN and inf ranges, a changed beam count, a stamp from
the past) are survived with the map kept; a misspelt parameter is named, a particle filter parameter
is said to be unused."""
import math
import signal
import subprocess
import threading
import unittest

import rospy
import rostest
import tf2_ros
from geometry_msgs.msg import TransformStamped
from nav_msgs.msg import OccupancyGrid
from nav_msgs.srv import GetMap
from rosgraph_msgs.msg import Log
from sensor_msgs.msg import LaserScan
from std_msgs.msg import Float64

HALF_ROOM = 2.0  # m: the square room's walls are at x, y = +-2 round the robot


def room_ranges(count):
    """Ranges of `count` beams over the full circle from the centre of the room."""
    ranges = []
    for i in range(count):
        a = -math.pi + 2 * math.pi * i / count
        c, s = abs(math.cos(a)), abs(math.sin(a))
        ranges.append(min(HALF_ROOM / c if c > 1e-9 else 1e9, HALF_ROOM / s if s > 1e-9 else 1e9))
    return ranges


def transform(parent, child, stamp):
    t = TransformStamped()
    t.header.stamp, t.header.frame_id, t.child_frame_id = stamp, parent, child
    t.transform.rotation.w = 1.0
    return t


class SlamGmappingFaults(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node('slam_gmapping_faults')
        cls.logs, cls.maps, cls.entropies, cls.lock = [], [], [], threading.Lock()
        rospy.Subscriber('/rosout', Log, cls._on_log, queue_size=100)
        rospy.Subscriber('/map', OccupancyGrid, cls._on_map, queue_size=5)
        rospy.Subscriber('/slam_gmapping/entropy', Float64, lambda m: cls.entropies.append(m.data))
        cls.scans = rospy.Publisher('/scan', LaserScan, queue_size=5)
        cls.static = tf2_ros.StaticTransformBroadcaster()
        cls.static.sendTransform(transform('base_link', 'laser', rospy.Time.now()))
        cls.tf = tf2_ros.TransformBroadcaster()
        cls.odometry_on = False
        cls.stop = False
        threading.Thread(target=cls._odometry_loop, daemon=True).start()

    @classmethod
    def _on_log(cls, msg):
        if msg.name == '/slam_gmapping':
            with cls.lock:
                cls.logs.append(msg.msg)

    @classmethod
    def _on_map(cls, msg):
        with cls.lock:
            cls.maps.append(msg)

    @classmethod
    def _odometry_loop(cls):
        rate = rospy.Rate(50)
        while not rospy.is_shutdown() and not cls.stop:
            if cls.odometry_on:
                cls.tf.sendTransform(transform('odom', 'base_link', rospy.Time.now()))
            rate.sleep()

    def scan(self, ranges=None, stamp=None):
        count = 360
        msg = LaserScan()
        msg.header.stamp = stamp or rospy.Time.now()
        msg.header.frame_id = 'laser'
        msg.angle_min, msg.angle_increment = -math.pi, 2 * math.pi / count
        msg.angle_max = msg.angle_min + (count - 1) * msg.angle_increment
        msg.range_min, msg.range_max = 0.05, 10.0
        msg.ranges = room_ranges(count) if ranges is None else ranges
        self.scans.publish(msg)

    def said(self, text):
        with self.lock:
            return any(text in m for m in self.logs)

    def wait_for(self, condition, timeout):
        end = rospy.get_time() + timeout
        while rospy.get_time() < end and not condition():
            rospy.sleep(0.1)
        return condition()

    def test_faults_in_order(self):
        while self.scans.get_num_connections() == 0:
            rospy.sleep(0.1)
        # 1. No odometry tf: the clear message, and no map.
        for _ in range(20):
            self.scan()
            rospy.sleep(0.1)
        self.assertTrue(self.wait_for(lambda: self.said("needs the robot's odometry as tf odom -> base_link"), 5),
                        'no message about the missing odometry; got %s' % self.logs)
        self.assertEqual(self.maps, [])

        # 2. Odometry comes: the room is mapped, its walls 2 m away on each side.
        type(self).odometry_on = True
        rospy.sleep(0.5)
        self.assertTrue(self.wait_for(lambda: (self.scan(), bool(self.maps))[1], 10), 'no map once odometry came')
        grid = self.maps[-1]
        res, ox, oy, w = grid.info.resolution, grid.info.origin.position.x, grid.info.origin.position.y, grid.info.width
        occupied = [(ox + (i % w + 0.5) * res, oy + (i // w + 0.5) * res) for i, v in enumerate(grid.data) if v == 100]
        self.assertGreater(len(occupied), 4 * 60)  # four 4 m walls of 5 cm cells: 320 cells
        for x, y in occupied:
            self.assertAlmostEqual(max(abs(x), abs(y)), HALF_ROOM, delta=0.1)
        self.assertAlmostEqual(grid.info.resolution, 0.05, places=6)
        self.assertTrue(self.wait_for(lambda: bool(self.entropies), 5))
        served = rospy.ServiceProxy('/dynamic_map', GetMap)().map
        self.assertEqual((served.info.width, served.info.height), (grid.info.width, grid.info.height))

        # 3. Bad scans: survived, said, the map kept.
        self.scan(ranges=[float('nan')] * 180 + [float('inf')] * 180)
        self.scan(ranges=room_ranges(360)[:200])
        self.scan(stamp=rospy.Time.now() - rospy.Duration(5.0))
        self.assertTrue(self.wait_for(lambda: self.said('has 200 ranges where its angles make 360'), 5), self.logs)
        self.assertTrue(self.wait_for(lambda: self.said('time went back'), 5), self.logs)
        self.scan()
        served = rospy.ServiceProxy('/dynamic_map', GetMap)().map
        self.assertEqual(sum(1 for v in served.data if v == 100), len(occupied))
        type(self).stop = True


    def run_with(self, *params, seconds=3.0):
        """(exit code or None if still running after `seconds`, output) of another slam_gmapping."""
        process = subprocess.Popen(['rosrun', 'odometry_slam', 'slam_gmapping', '__name:=gmapping_params'] +
                                   list(params), stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
        try:
            output, _ = process.communicate(timeout=seconds)
            return process.returncode, output
        except subprocess.TimeoutExpired:
            process.send_signal(signal.SIGINT)  # a clean stop flushes its stdout
            output, _ = process.communicate(timeout=10)
            return None, output

    def test_misspelt_and_particle_filter_parameters_are_named(self):
        code, output = self.run_with('_linearUpdte:=0.5', '_particles:=80', '_xmin:=-5.0', '_ymin:=-5.0',
                                     '_xmax:=5.0', '_ymax:=5.0')
        self.assertIsNone(code, 'slam_gmapping stopped:\n' + output)
        self.assertIn('ignored /gmapping_params/linearUpdte (did you mean linearUpdate?): not a parameter of '
                      'slam_gmapping', output)
        self.assertIn("particles: parameters of gmapping's particle filter", output)
        self.assertIn('200 x 200 cells of 0.050 m', output)

    def test_unusable_parameters_stop_it_with_every_problem_named(self):
        code, output = self.run_with('_delta:=-0.05', '_throttle_scans:=0', '_odom_frame:=base_link', seconds=15)
        self.assertEqual(code, 1, output)
        for text in ('delta must be > 0 (got -0.05)', 'throttle_scans: expected an integer >= 1, got 0',
                     'expected three different frames'):
            self.assertIn(text, output)


if __name__ == '__main__':
    rostest.rosrun('odometry_slam', 'test_slam_gmapping_faults', SlamGmappingFaults)
