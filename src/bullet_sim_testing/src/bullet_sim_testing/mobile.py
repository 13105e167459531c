"""What every mobile robot's rostest checks, as a unittest mixin (needs a ROS master).

A test class sets the class attributes below and inherits MobileRobotChecks and
unittest.TestCase; the robot must already be spawned by the test's launch file. Drive tests
teleport the robot to open ground outside the maze (OPEN_GROUND), where nothing is in its way.
"""
import math
import time

import numpy as np
import rospy
import tf2_ros
from gazebo_msgs.msg import ModelState
from gazebo_msgs.srv import GetModelState, SetModelState
from geometry_msgs.msg import Pose, Twist
from nav_msgs.msg import Odometry
from sensor_msgs.msg import CameraInfo, Image, LaserScan

from bullet_sim_testing.walls import compare_scan, load_walls


def yaw_of(q):
    return math.atan2(2 * (q.w * q.z + q.x * q.y), 1 - 2 * (q.y * q.y + q.z * q.z))


def pose_msg(x, y, z, yaw):
    p = Pose()
    p.position.x, p.position.y, p.position.z = x, y, z
    p.orientation.z, p.orientation.w = math.sin(yaw / 2), math.cos(yaw / 2)
    return p


def angle_diff(a, b):
    return math.atan2(math.sin(a - b), math.cos(a - b))


class MobileRobotChecks:
    MODEL = None            # model name in the simulator
    CMD_VEL = None          # geometry_msgs/Twist topic of the drive plugin
    ODOM = None             # nav_msgs/Odometry topic of the drive plugin
    SCAN = None             # sensor_msgs/LaserScan topic
    CAMERA = None           # camera namespace: CAMERA + '/image_raw', '/camera_info'
    IMAGE_SIZE = None       # (width, height)
    WALLS = None            # walls yaml (ground truth of the maze)
    LASER_SIGMA = None      # the laser's noise stddev
    ODOM_FRAME = 'odom'
    SENSOR_FRAMES = ()      # frames that must be in tf under ODOM_FRAME
    SPAWN_Z = 0.05          # height to teleport the robot to (it settles on its wheels)
    MAZE_POSE = None        # (x, y, yaw) inside the maze for the laser and camera checks
    OPEN_GROUND = (20.0, 20.0)
    SPEED = 1.0             # m/s for the straight drive
    # rad that 1 rad/s for 1.5 s turns the robot, +-10 %: the commanded 1.5 rad for a diff drive;
    # a skid steer turns less, by the rate scripts/bench_skid_steer.py measures (and PyBullet agrees).
    TURN = 1.5

    @classmethod
    def setUpClass(cls):
        rospy.init_node('test_' + cls.MODEL, anonymous=True)
        rospy.wait_for_service('/gazebo/get_model_state', timeout=60)
        cls.get_state = rospy.ServiceProxy('/gazebo/get_model_state', GetModelState)
        cls.set_state = rospy.ServiceProxy('/gazebo/set_model_state', SetModelState)
        deadline = time.monotonic() + 60
        while time.monotonic() < deadline and not cls.get_state(model_name=cls.MODEL).success:
            time.sleep(0.2)
        cls.cmd = rospy.Publisher(cls.CMD_VEL, Twist, queue_size=1)
        cls.tf_buffer = tf2_ros.Buffer()
        cls.tf_listener = tf2_ros.TransformListener(cls.tf_buffer)

    # --- helpers --------------------------------------------------------------------------------

    def ground_truth(self):
        s = self.get_state(model_name=self.MODEL, relative_entity_name='world')
        self.assertTrue(s.success, s.status_message)
        return s.pose.position.x, s.pose.position.y, yaw_of(s.pose.orientation)

    def teleport(self, x, y, yaw):
        state = ModelState(model_name=self.MODEL, pose=pose_msg(x, y, self.SPAWN_Z, yaw), reference_frame='world')
        self.assertTrue(self.set_state(model_state=state).success)
        self.drive(0.0, 0.0, 1.0)  # settle on the wheels, at rest

    def drive(self, v, w, seconds):
        twist = Twist()
        twist.linear.x, twist.angular.z = v, w
        end = rospy.get_time() + seconds
        while rospy.get_time() < end and not rospy.is_shutdown():
            self.cmd.publish(twist)
            rospy.sleep(0.05)
        self.cmd.publish(Twist())

    def odom_pose(self):
        o = rospy.wait_for_message(self.ODOM, Odometry, timeout=10)
        return o.pose.pose.position.x, o.pose.pose.position.y, yaw_of(o.pose.pose.orientation)

    # --- the checks -------------------------------------------------------------------------

    def test_straight_drive_covers_the_commanded_distance_and_odometry_agrees(self):
        self.teleport(self.OPEN_GROUND[0], self.OPEN_GROUND[1], 0.3)
        x0, y0, _ = self.ground_truth()
        ox0, oy0, _ = self.odom_pose()
        self.drive(self.SPEED, 0.0, 2.0)
        rospy.sleep(1.0)  # coast to a stop
        x1, y1, _ = self.ground_truth()
        ox1, oy1, _ = self.odom_pose()
        moved = math.hypot(x1 - x0, y1 - y0)
        odom_moved = math.hypot(ox1 - ox0, oy1 - oy0)
        expected = 2.0 * self.SPEED
        print('%s: %.2f m/s for 2 s moved %.3f m (ground truth), odometry says %.3f m'
              % (self.MODEL, self.SPEED, moved, odom_moved))
        self.assertAlmostEqual(moved, expected, delta=0.05 * expected)
        self.assertAlmostEqual(odom_moved, moved, delta=0.05 * expected)

    def test_turning_in_place_turns(self):
        self.teleport(self.OPEN_GROUND[0] + 5, self.OPEN_GROUND[1], 0.0)
        x0, y0, yaw0 = self.ground_truth()
        self.drive(0.0, 1.0, 1.5)
        rospy.sleep(0.5)
        x1, y1, yaw1 = self.ground_truth()
        turned = angle_diff(yaw1, yaw0)
        print('%s: 1 rad/s for 1.5 s turned %.3f rad, drifting %.3f m' % (self.MODEL, turned, math.hypot(x1 - x0, y1 - y0)))
        self.assertAlmostEqual(turned, self.TURN, delta=0.1 * self.TURN)
        self.assertLess(math.hypot(x1 - x0, y1 - y0), 0.05)  # on the spot: a symmetric robot does not drift

    def test_driving_into_a_wall_does_not_go_through_it(self):
        # A static wall 1 m ahead, as its own model.
        from gazebo_msgs.srv import SpawnModel
        wx, wy = self.OPEN_GROUND[0] - 5, self.OPEN_GROUND[1]
        spawn = rospy.ServiceProxy('/gazebo/spawn_sdf_model', SpawnModel)
        sdf = ('<sdf version="1.6"><model name="test_wall"><static>true</static><link name="l"><collision name="c">'
               '<geometry><box><size>0.1 4 1</size></box></geometry></collision></link></model></sdf>')
        spawn(model_name='test_wall_%s' % self.MODEL, model_xml=sdf, robot_namespace='', reference_frame='',
              initial_pose=pose_msg(wx + 1.0, wy, 0.5, 0.0))
        self.teleport(wx, wy, 0.0)
        self.drive(self.SPEED, 0.0, 3.0)
        x, _, _ = self.ground_truth()
        print('%s: pushed into a wall at x=%.2f, stopped with its centre at x=%.3f' % (self.MODEL, wx + 0.95, x))
        self.assertLess(x, wx + 0.95)

    def test_laser_ranges_match_the_maze_geometry(self):
        walls = load_walls(self.WALLS)
        self.teleport(*self.MAZE_POSE)
        scan = rospy.wait_for_message(self.SCAN, LaserScan, timeout=20)
        t = self.tf_buffer.lookup_transform('world', scan.header.frame_id, rospy.Time(0), rospy.Duration(5))
        q, p = t.transform.rotation, t.transform.translation
        scan = rospy.wait_for_message(self.SCAN, LaserScan, timeout=20)  # one taken at this pose
        errors, beyond, failures = compare_scan(walls, p.x, p.y, yaw_of(q), scan, 5 * self.LASER_SIGMA)
        errors = np.array(errors)
        print('%s laser: %d beams compared with the maze, mean error %.4f m, std %.4f m (sigma %.3f); %d out of range'
              % (self.MODEL, len(errors), errors.mean(), errors.std(), self.LASER_SIGMA, beyond))
        self.assertGreater(len(errors), len(scan.ranges) // 3)
        self.assertLessEqual(len(failures), len(scan.ranges) // 100, failures[:10])
        self.assertLess(abs(errors.mean()), self.LASER_SIGMA)
        self.assertLess(errors.std(), 2 * self.LASER_SIGMA)

    def test_camera_publishes_images_of_its_size_that_change_when_the_robot_turns(self):
        self.teleport(*self.MAZE_POSE)
        info = rospy.wait_for_message(self.CAMERA + '/camera_info', CameraInfo, timeout=20)
        self.assertEqual((info.width, info.height), self.IMAGE_SIZE)
        first = rospy.wait_for_message(self.CAMERA + '/image_raw', Image, timeout=20)
        self.assertEqual((first.width, first.height), self.IMAGE_SIZE)
        self.assertIn(first.encoding, ('rgb8', 'bgr8'))
        x, y, yaw = self.ground_truth()
        self.teleport(x, y, yaw + math.pi / 2)
        second = rospy.wait_for_message(self.CAMERA + '/image_raw', Image, timeout=20)
        a = np.frombuffer(first.data, np.uint8).astype(float)
        b = np.frombuffer(second.data, np.uint8).astype(float)
        change = np.abs(a - b).mean()
        print('%s camera: %dx%d %s, mean pixel change after a quarter turn %.1f' %
              (self.MODEL, first.width, first.height, first.encoding, change))
        self.assertGreater(change, 5.0)

    def test_tf_reaches_every_sensor_frame_from_odom(self):
        for frame in self.SENSOR_FRAMES:
            self.assertTrue(self.tf_buffer.can_transform(self.ODOM_FRAME, frame, rospy.Time(0), rospy.Duration(10)),
                            'no tf from %s to %s' % (self.ODOM_FRAME, frame))
