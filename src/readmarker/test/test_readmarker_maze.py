#!/usr/bin/env python3
"""readmarker_maze.launch: m_robot starts 1.1 m in front of the board on the Capstone maze's west
wall; readmarker gives both pictures, each matching what its markers frame on the shipped board
(boards/board.png; normalised cross-correlation >= 0.9). Turned 90 degrees away, the robot sees
no marker, and both pictures are reported unavailable with empty images."""
import math
import os
import sys
import unittest

import cv2
import numpy as np
import rospkg
import rospy
import rostest
from geometry_msgs.msg import Twist
from nav_msgs.msg import Odometry

from readmarker.crop import ncc
from readmarker.msg import markermsg
from readmarker.pictures import pets_board

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), 'unit'))
from board_views import framed_crop  # noqa: E402

_, FRAMED = pets_board()  # the regions the markers frame on boards/board.png


def angle_between(a, b):
    return abs(math.atan2(math.sin(b - a), math.cos(b - a)))


def decoded(compressed):
    return cv2.imdecode(np.frombuffer(compressed.data, np.uint8), cv2.IMREAD_COLOR)


class ReadMarkerMazeTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node('readmarker_maze_checks')
        cls.board = cv2.imread(os.path.join(rospkg.RosPack().get_path('readmarker'), 'boards', 'board.png'))
        cls.results = []
        rospy.Subscriber('cropped_img', markermsg, lambda m: cls.results.append((rospy.get_time(), m)), queue_size=5)
        cls.cmd_vel = rospy.Publisher('cmd_vel', Twist, queue_size=1)

    def yaw(self):
        q = rospy.wait_for_message('odom', Odometry, timeout=10).pose.pose.orientation
        return 2 * math.atan2(q.z, q.w)

    def crops_after(self, since, timeout=40.0):
        deadline = rospy.get_time() + timeout
        while rospy.get_time() < deadline and sum(t > since for t, _ in self.results) < 3:
            rospy.sleep(0.1)
        later = [m for t, m in self.results if t > since]
        self.assertGreaterEqual(len(later), 3, 'fewer than 3 cropped_img messages within %.0f s' % timeout)
        return later[-1]

    def test_both_pictures_then_none_when_turned_away(self):
        rospy.sleep(1.0)  # sim time: the robot settled, the board spawned
        out = self.crops_after(rospy.get_time())
        self.assertEqual((out.image1_available, out.image2_available), (1, 1))
        for k, compressed in enumerate((out.cimage1, out.cimage2)):
            self.assertEqual(compressed.format, 'jpeg')
            crop = decoded(compressed)
            self.assertGreaterEqual(ncc(crop, framed_crop(self.board, FRAMED[k])), 0.9, 'picture %d' % (k + 1))
            self.assertLess(ncc(crop, framed_crop(self.board, FRAMED[1 - k])), 0.5, 'picture %d' % (k + 1))

        # 90 degrees to the left (by the skid steer's odometry, the model's pose): the board, 1 m
        # wide at 1.1 m (+-24 degrees), leaves the camera's 80 degree view.
        start = self.yaw()
        turn = Twist()
        turn.angular.z = 1.0
        deadline = rospy.get_time() + 10.0
        while rospy.get_time() < deadline and angle_between(start, self.yaw()) < math.pi / 2:
            self.cmd_vel.publish(turn)
            rospy.sleep(0.05)
        self.cmd_vel.publish(Twist())
        self.assertGreaterEqual(angle_between(start, self.yaw()), math.pi / 2, 'the robot did not turn')
        rospy.sleep(0.5)
        out = self.crops_after(rospy.get_time())
        self.assertEqual((out.image1_available, out.image2_available), (0, 0))
        self.assertEqual((len(out.cimage1.data), len(out.cimage2.data)), (0, 0))


if __name__ == '__main__':
    rostest.rosrun('readmarker', 'test_readmarker_maze', ReadMarkerMazeTest)
