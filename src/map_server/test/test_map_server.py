#!/usr/bin/env python3
"""rostest (map_server.test): the served map, its metadata and static_map; map_saver writes what
map_server loads; a broken yaml stops map_server with the tag named."""
import os
import subprocess
import sys
import tempfile
import unittest

import rospy
import rostest
from nav_msgs.msg import MapMetaData, OccupancyGrid
from nav_msgs.srv import GetMap

# small.pgm, bottom row first: the unknown corner and free cells, free, one occupied, free, the wall.
EXPECTED = [-1, 0, 0, 0, 0,
            0, 0, 0, 0, 0,
            0, 0, 100, 0, 0,
            100, 100, 100, 100, 100]


class MapServerTest(unittest.TestCase):
    def test_the_map_is_latched_with_its_geometry_and_frame(self):
        grid = rospy.wait_for_message('/map', OccupancyGrid, timeout=20)
        self.assertEqual(grid.header.frame_id, 'world_map')
        self.assertEqual((grid.info.width, grid.info.height), (5, 4))
        self.assertAlmostEqual(grid.info.resolution, 0.25)
        self.assertAlmostEqual(grid.info.origin.position.x, -1.0)
        self.assertAlmostEqual(grid.info.origin.position.y, 0.5)
        self.assertAlmostEqual(grid.info.origin.orientation.w, 1.0)
        self.assertEqual(list(grid.data), EXPECTED)
        meta = rospy.wait_for_message('/map_metadata', MapMetaData, timeout=10)
        self.assertEqual((meta.width, meta.height), (5, 4))

    def test_static_map_answers_the_same_map(self):
        rospy.wait_for_service('/static_map', 20)
        grid = rospy.ServiceProxy('/static_map', GetMap)().map
        self.assertEqual(list(grid.data), EXPECTED)

    def test_map_saver_writes_files_map_server_loads_back(self):
        rospy.wait_for_message('/map', OccupancyGrid, timeout=20)
        folder = tempfile.mkdtemp()
        base = os.path.join(folder, 'saved')
        done = subprocess.run(['rosrun', 'map_server', 'map_saver', '-f', base], timeout=30,
                              stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
        self.assertEqual(done.returncode, 0, done.stdout)
        with open(base + '.yaml') as f:
            text = f.read()
        self.assertIn('image: saved.pgm\nresolution: 0.250000\norigin: [-1.000000, 0.500000, 0.000000]', text)
        sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', 'src'))
        from map_files import load
        self.assertEqual(load.load_map(base + '.yaml').data, EXPECTED)

    def test_a_broken_yaml_stops_map_server_naming_the_tag(self):
        folder = tempfile.mkdtemp()
        path = os.path.join(folder, 'broken.yaml')
        with open(path, 'w') as f:
            f.write('image: small.pgm\nresolution: 0.25\norigin: [0, 0, 0]\noccupied_thresh: 0.65\nfree_thresh: 0.2\n')
        done = subprocess.run(['rosrun', 'map_server', 'map_server', path, '__name:=broken_map_server'], timeout=30,
                              stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
        self.assertEqual(done.returncode, 255, done.stdout)
        self.assertIn('The map does not contain a negate tag or it is invalid.', done.stdout)
        self.assertIn('broken.yaml', done.stdout)


if __name__ == '__main__':
    rospy.init_node('test_map_server')
    rostest.rosrun('map_server', 'map_server', MapServerTest)
