#!/usr/bin/env python3
"""move_base's costmap layers, found by their costmap_2d type names, do what upstream's do: the
static layer writes /map into the global costmap, the obstacle layer marks a scan's hits within
obstacle_range (searched for up the namespaces) into the local costmap, and the inflation layer
spreads cost around both as costmap_2d's exponential decay says."""
import math
import unittest

import rospy
import rostest
from nav_msgs.msg import OccupancyGrid
from sensor_msgs.msg import LaserScan

RESOLUTION = 0.05
INFLATION_RADIUS, COST_SCALING = 0.5, 5.0   # layers.test
INSCRIBED = 0.1 + 0.01                      # robot_radius + costmap_2d's default footprint_padding


def occupancy_band(distance):
    """The OccupancyGrid values costmap_2d publishes for a cell `distance` m from an obstacle,
    allowing the distance one cell either way."""
    def occupancy(d):
        cost = 253 if d <= INSCRIBED else int(252 * math.exp(-COST_SCALING * (d - INSCRIBED)))
        return 99 if cost == 253 else 1 + (97 * (cost - 1)) // 251
    return occupancy(distance + RESOLUTION), occupancy(distance - RESOLUTION)


def value_at(grid, x, y):
    i = int(math.floor((x - grid.info.origin.position.x) / grid.info.resolution))
    j = int(math.floor((y - grid.info.origin.position.y) / grid.info.resolution))
    return grid.data[j * grid.info.width + i]


def wait_for_grid(topic, condition, timeout=30.0):
    """The first grid on `topic` that satisfies `condition`, else the last one seen."""
    grid = None
    deadline = rospy.Time.now() + rospy.Duration(timeout)
    while rospy.Time.now() < deadline:
        grid = rospy.wait_for_message(topic, OccupancyGrid, timeout=timeout)
        if condition(grid):
            break
    return grid


class LayersTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node('move_base_layers_test')

    def test_the_static_layer_takes_the_map_and_the_inflation_layer_spreads_it(self):
        # A 2 m square map at the origin, free but for one occupied cell at its centre.
        grid = OccupancyGrid()
        grid.header.frame_id = 'map'
        grid.info.resolution = RESOLUTION
        grid.info.width = grid.info.height = 40
        grid.info.origin.position.x = grid.info.origin.position.y = -1.0
        grid.info.origin.orientation.w = 1.0
        grid.data = [0] * 1600
        grid.data[20 * 40 + 20] = 100
        publisher = rospy.Publisher('/map', OccupancyGrid, queue_size=1, latch=True)
        publisher.publish(grid)
        costmap = wait_for_grid('/move_base/global_costmap/costmap', lambda g: g.info.width == 40)
        self.assertEqual((costmap.info.width, costmap.info.height), (40, 40))
        self.assertAlmostEqual(costmap.info.origin.position.x, -1.0, places=6)
        centre = 0.025  # the occupied cell's centre
        self.assertEqual(value_at(costmap, centre, centre), 100)
        self.assertEqual(value_at(costmap, centre + 0.1, centre), 99)  # within the inscribed radius
        low, high = occupancy_band(0.3)
        self.assertTrue(low <= value_at(costmap, centre + 0.3, centre) <= high,
                        (low, value_at(costmap, centre + 0.3, centre), high))
        self.assertEqual(value_at(costmap, centre + 0.7, centre), 0)  # beyond inflation_radius
        self.assertEqual(value_at(costmap, -0.9, -0.9), 0)

    def test_the_obstacle_layer_marks_hits_within_obstacle_range(self):
        # Beams at -0.1, 0 and 0.1 rad: nothing, a wall 1.02 m ahead, something 2.5 m away (beyond
        # obstacle_range 2.0: not marked). The laser is 0.025 m left of the robot (layers.test).
        publisher = rospy.Publisher('/scan', LaserScan, queue_size=1)
        scan = LaserScan()
        scan.header.frame_id = 'laser'
        scan.angle_min, scan.angle_max, scan.angle_increment = -0.1, 0.1, 0.1
        scan.range_min, scan.range_max = 0.05, 10.0
        scan.ranges = [float('inf'), 1.02, 2.5]
        hit, far = (1.02, 0.025), (2.5 * math.cos(0.1), 0.025 + 2.5 * math.sin(0.1))
        costmap = None
        deadline = rospy.Time.now() + rospy.Duration(30)
        while rospy.Time.now() < deadline:
            scan.header.stamp = rospy.Time.now()
            publisher.publish(scan)
            try:
                costmap = rospy.wait_for_message('/move_base/local_costmap/costmap', OccupancyGrid, timeout=1.0)
            except rospy.ROSException:
                continue
            if value_at(costmap, *hit) == 100:
                break
        self.assertIsNotNone(costmap)
        self.assertEqual((costmap.info.width, costmap.info.height), (120, 120))  # 6 m at 0.05 m
        self.assertEqual(value_at(costmap, *hit), 100)
        low, high = occupancy_band(0.3)
        beside = (hit[0], hit[1] + 0.3)
        self.assertTrue(low <= value_at(costmap, *beside) <= high, (low, value_at(costmap, *beside), high))
        self.assertEqual(value_at(costmap, 0.5, 0.025), 0)  # on the ray: free
        self.assertEqual(value_at(costmap, far[0], far[1]), 0)  # beyond obstacle_range


if __name__ == '__main__':
    rostest.rosrun('move_base', 'test_layers', LayersTest)
