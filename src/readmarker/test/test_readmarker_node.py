#!/usr/bin/env python3
"""readmarker_node as the lecture runs it, fed views of the board on camera/image: both pictures
come back on cropped_img (JPEG, header and format set) and on cropped_img1/2, from bgr8, rgb8 and
mono8 frames; a hidden marker makes its picture unavailable; a truncated frame and an unsupported
encoding are warned about and skipped, and the node goes on."""
import os
import sys
import unittest

import cv2
import numpy as np
import rospy
import rostest
from cv_bridge import CvBridge
from rosgraph_msgs.msg import Log
from sensor_msgs.msg import Image

from readmarker.crop import ncc
from readmarker.msg import markermsg

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), 'unit'))
import board_views as views  # noqa: E402


class ReadMarkerNodeTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node('readmarker_node_checks')
        cls.bridge = CvBridge()
        cls.results, cls.crops1, cls.logs = [], [], []
        rospy.Subscriber('cropped_img', markermsg, cls.results.append, queue_size=10)
        rospy.Subscriber('cropped_img1', Image, cls.crops1.append, queue_size=10)
        rospy.Subscriber('/rosout', Log, lambda m: cls.logs.append(m.msg), queue_size=100)
        cls.pub = rospy.Publisher('camera/image', Image, queue_size=1)
        deadline = rospy.get_time() + 30
        while cls.pub.get_num_connections() == 0 and rospy.get_time() < deadline:
            rospy.sleep(0.1)
        cls.view = views.camera_view(views.BOARD, views.looking_at(views.BOARD, 0.15))
        cls.seq = 0

    def send(self, msg):
        """Publishes a frame; the node's answer (or None within 5 s)."""
        self.__class__.seq += 1
        msg.header.seq, msg.header.stamp, msg.header.frame_id = self.seq, rospy.Time.now(), 'camera'
        before = len(self.results)
        self.pub.publish(msg)
        deadline = rospy.get_time() + 5.0
        while len(self.results) == before and rospy.get_time() < deadline:
            rospy.sleep(0.02)
        return self.results[-1] if len(self.results) > before else None

    def decoded(self, compressed):
        return cv2.imdecode(np.frombuffer(compressed.data, np.uint8), cv2.IMREAD_UNCHANGED)

    def test_1_both_pictures_from_bgr8_rgb8_and_mono8(self):
        for encoding in ('bgr8', 'rgb8', 'mono8'):
            image = {'bgr8': self.view, 'rgb8': cv2.cvtColor(self.view, cv2.COLOR_BGR2RGB),
                     'mono8': cv2.cvtColor(self.view, cv2.COLOR_BGR2GRAY)}[encoding]
            msg = self.bridge.cv2_to_imgmsg(image, encoding=encoding)
            out = self.send(msg)
            self.assertIsNotNone(out, encoding)
            self.assertEqual((out.image1_available, out.image2_available), (1, 1), encoding)
            for k, c in enumerate((out.cimage1, out.cimage2)):
                self.assertEqual((c.format, c.header.frame_id, c.header.stamp), ('jpeg', 'camera', msg.header.stamp))
                crop = self.decoded(c)
                self.assertEqual(crop.shape[:2], (255, 255))
                expected = views.expected(k)
                if encoding == 'mono8':
                    expected = cv2.cvtColor(expected, cv2.COLOR_BGR2GRAY)
                self.assertGreaterEqual(ncc(crop, expected), 0.9, (encoding, k))
        rospy.sleep(0.2)
        # The raw crops (no JPEG) of the three frames on cropped_img1: as close as the unit tests'.
        self.assertEqual(len(self.crops1), 3)
        for image_msg, encoding in zip(self.crops1, ('bgr8', 'bgr8', 'mono8')):
            self.assertEqual((image_msg.width, image_msg.height, image_msg.encoding), (255, 255, encoding))
            crop = self.bridge.imgmsg_to_cv2(image_msg, 'passthrough')
            expected = views.expected(0) if encoding == 'bgr8' else cv2.cvtColor(views.expected(0), cv2.COLOR_BGR2GRAY)
            self.assertGreaterEqual(ncc(crop, expected), 0.95, encoding)

    def test_2_a_hidden_marker_makes_its_picture_unavailable(self):
        board = views.BOARD.copy()
        x0, y0, x1, y1 = views.FRAMED[1]
        board[y1:y1 + views.MARKER, x1:x1 + views.MARKER] = 255
        out = self.send(self.bridge.cv2_to_imgmsg(views.camera_view(board, views.looking_at(board, 0.1)), 'bgr8'))
        self.assertEqual((out.image1_available, out.image2_available), (1, 0))
        self.assertEqual(len(out.cimage2.data), 0)
        rospy.sleep(0.3)
        self.assertTrue(any('picture 2 unavailable: marker 7 not seen' in m for m in self.logs), self.logs[-5:])

    def test_3_bad_frames_are_skipped_with_a_warning_and_the_node_goes_on(self):
        truncated = self.bridge.cv2_to_imgmsg(self.view, 'bgr8')
        truncated.data = truncated.data[:len(truncated.data) // 2]
        self.assertIsNone(self.send(truncated))
        odd = Image(height=4, width=4, encoding='16UC1', step=8, data=bytes(32))
        self.assertIsNone(self.send(odd))
        rospy.sleep(0.3)
        self.assertTrue(any('frame skipped' in m and 'needs' in m for m in self.logs), self.logs[-5:])
        self.assertTrue(any("encoding '16UC1'" in m for m in self.logs), self.logs[-5:])
        out = self.send(self.bridge.cv2_to_imgmsg(self.view, 'bgr8'))
        self.assertEqual((out.image1_available, out.image2_available), (1, 1))


if __name__ == '__main__':
    rostest.rosrun('readmarker', 'test_readmarker_node', ReadMarkerNodeTest)
