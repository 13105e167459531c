#!/usr/bin/env python3
"""hector_mapping without odometry and scans far apart (0.4 m and 0.5 rad between scans, half a second
apart): with the correlative search on (search_window_linear / _angular, ours, off by default as in
upstream) the node keeps the pose, and its map has the room's walls; as upstream matches, from the last
pose, the same run is lost.
"""
import os
import sys
import time
import unittest

import rospy
import rostest
from nav_msgs.msg import OccupancyGrid

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from test_mapping_node_odometry import START, TwoMappers, jumps  # noqa: E402  (the same room and jumps)

# Between scans: the search's window is the motion plausible over the scan interval (1.5 m/s, pi rad/s),
# so jumps of 0.4 m and 0.5 rad need the scans this far apart in time.
SCAN_INTERVAL = 0.5  # s


class SearchTest(TwoMappers, unittest.TestCase):
    def setUp(self):
        self.map = None
        self.start('test_mapping_node_search', ['with_search', 'without_search'])
        rospy.Subscriber('/with_search/map', OccupancyGrid, self.keep_map)

    def keep_map(self, msg):
        with self.lock:
            self.map = msg

    def play(self, x, y, yaw):
        """A scan taken at (x, y, yaw), time for both mappers to match it, and the rest of SCAN_INTERVAL."""
        stamp = rospy.Time.now()
        self.publish_scan(stamp, x, y, yaw)
        self.wait_for_answers(stamp)
        time.sleep(max(0.0, SCAN_INTERVAL - (rospy.Time.now() - stamp).to_sec()))

    def test_jumps_are_tracked_with_the_search_and_lost_without(self):
        for pose in START + jumps():
            self.play(*pose)
        truth = jumps()[-1]
        distance, angle = self.error('with_search', truth)
        # The search lands within a 5 cm cell of the map; Gauss-Newton on the map then settles it.
        self.assertLess(distance, 0.05)
        self.assertLess(angle, 0.03)
        distance, angle = self.error('without_search', truth)
        # From the last pose alone, 0.4 m and 0.5 rad is beyond the matcher's reach.
        self.assertTrue(distance > 0.2 or angle > 0.1, (distance, angle))

        # With loop closure on too, the map comes (every map_pub_period, 2 s) with the room's walls: 22 m of
        # them at 0.05 m cells, some hundreds of occupied cells; a lost pose would have smeared them.
        deadline = time.time() + 10
        occupied = 0
        while time.time() < deadline and not 300 <= occupied:
            with self.lock:
                occupied = sum(1 for v in self.map.data if v == 100) if self.map is not None else 0
            time.sleep(0.1)
        self.assertGreater(occupied, 300)
        self.assertLess(occupied, 1500)


if __name__ == '__main__':
    rostest.rosrun('hector_style_mapping', 'mapping_node_search', SearchTest)
