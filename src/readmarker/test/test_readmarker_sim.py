#!/usr/bin/env python3
"""readmarker end to end in the simulator: the marker board (the package's model: boards/board.png,
our dog and cat, as the texture of a 1 m wide panel) stands in front of m_robot at several distances and angles, and readmarker_node on the
robot's camera (800 x 800, rgb8) gives both pictures, each matching what its markers frame on the
board (normalised cross-correlation >= 0.9).

With READMARKER_PICTURE=FILE.png it also writes the camera's view at the second pose beside the two
crops (docs/images/readmarker_sim.png)."""
import math
import os
import subprocess
import sys
import unittest

import cv2
import numpy as np
import rospkg
import rospy
import rostest
from gazebo_msgs.srv import DeleteModel, SpawnModel
from geometry_msgs.msg import Pose

from readmarker.crop import ncc
from readmarker.msg import markermsg
from readmarker.pictures import pets_board

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), 'unit'))
import board_views as views  # noqa: E402

WIDTH = 1.0  # m, the panel
PACKAGE = rospkg.RosPack().get_path('readmarker')
_, FRAMED = pets_board()  # the regions the markers frame on boards/board.png
# (x, y, yaw) of the panel in the world; m_robot sits at the origin looking along +x. The panel's
# printed face looks along its -x, so yaw pi faces the robot.
POSES = [(1.0, 0.0, math.pi), (0.8, 0.15, math.pi - 0.35), (1.3, -0.2, math.pi + 0.5)]


def board_urdf():
    xacro_file = os.path.join(PACKAGE, 'urdf', 'marker_board.urdf.xacro')
    return subprocess.run(['xacro', xacro_file, 'width:=%g' % WIDTH], check=True, stdout=subprocess.PIPE,
                          text=True).stdout


class ReadMarkerSimTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node('readmarker_sim_checks')
        board = cv2.imread(os.path.join(PACKAGE, 'boards', 'board.png'))
        cls.expected = [views.framed_crop(board, region) for region in FRAMED]
        cls.urdf = board_urdf()
        cls.results = []
        rospy.Subscriber('cropped_img', markermsg, lambda m: cls.results.append((rospy.get_time(), m)), queue_size=5)
        rospy.wait_for_service('/gazebo/spawn_urdf_model', timeout=60)
        cls.spawn = rospy.ServiceProxy('/gazebo/spawn_urdf_model', SpawnModel)
        cls.delete = rospy.ServiceProxy('/gazebo/delete_model', DeleteModel)
        cls.picture = os.environ.get('READMARKER_PICTURE', '')
        cls.frames = []
        if cls.picture:
            from sensor_msgs.msg import Image
            rospy.Subscriber('/m_robot/camera1/image_raw', Image, cls.frames.append, queue_size=1)

    def save_picture(self, out):
        from cv_bridge import CvBridge
        view = cv2.resize(CvBridge().imgmsg_to_cv2(self.last_frame, 'bgr8'), (400, 400))
        columns = [view]
        for compressed in (out.cimage1, out.cimage2):
            column = np.full((400, 255, 3), 255, np.uint8)
            column[:255] = cv2.imdecode(np.frombuffer(compressed.data, np.uint8), cv2.IMREAD_COLOR)
            columns += [np.full((400, 20, 3), 255, np.uint8), column]
        cv2.imwrite(self.picture, np.hstack(columns))

    def crops_at(self, x, y, yaw):
        pose = Pose()
        pose.position.x, pose.position.y = x, y
        pose.orientation.z, pose.orientation.w = math.sin(yaw / 2), math.cos(yaw / 2)
        self.assertTrue(self.spawn(model_name='marker_board', model_xml=self.urdf, robot_namespace='',
                                   initial_pose=pose, reference_frame='world').success)
        try:
            since = rospy.get_time() + 0.5  # frames rendered with the board standing
            deadline = rospy.get_time() + 30.0
            while rospy.get_time() < deadline and sum(t > since for t, _ in self.results) < 3:
                rospy.sleep(0.1)
            later = [m for t, m in self.results if t > since]
            self.assertGreaterEqual(len(later), 3, 'no crops from the camera within 30 s')
            self.last_frame = self.frames[-1] if self.frames else None  # the board still standing
            return later[-1]
        finally:
            self.delete(model_name='marker_board')
            rospy.sleep(0.5)

    def test_both_pictures_from_several_poses(self):
        for x, y, yaw in POSES:
            out = self.crops_at(x, y, yaw)
            if self.picture and (x, y, yaw) == POSES[1] and self.last_frame is not None:
                self.save_picture(out)
            self.assertEqual((out.image1_available, out.image2_available), (1, 1), (x, y, yaw))
            for k, compressed in enumerate((out.cimage1, out.cimage2)):
                crop = cv2.imdecode(np.frombuffer(compressed.data, np.uint8), cv2.IMREAD_COLOR)
                self.assertGreaterEqual(ncc(crop, self.expected[k]), 0.9, (x, y, yaw, k))
                self.assertLess(ncc(crop, self.expected[1 - k]), 0.5)


if __name__ == '__main__':
    rostest.rosrun('readmarker', 'test_readmarker_sim', ReadMarkerSimTest)
