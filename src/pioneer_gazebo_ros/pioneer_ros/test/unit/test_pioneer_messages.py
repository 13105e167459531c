"""pioneer_ros.messages: tf and odometry from a model state (ROS message types only; no ROS
master needed)."""
import math
import os
import sys

import pytest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..', 'src'))

genpy = pytest.importorskip('genpy')
from geometry_msgs.msg import Pose, Twist  # noqa: E402

from pioneer_ros.messages import odometry_from_model_state, transform_from_pose  # noqa: E402
from pioneer_ros.pose_math import quaternion_from_yaw  # noqa: E402


def pose(x, y, z, yaw, scale=1.0):
    p = Pose()
    p.position.x, p.position.y, p.position.z = x, y, z
    qx, qy, qz, qw = (scale * c for c in quaternion_from_yaw(yaw))
    p.orientation.x, p.orientation.y, p.orientation.z, p.orientation.w = qx, qy, qz, qw
    return p


def world_twist(vx, vy, wz):
    t = Twist()
    t.linear.x, t.linear.y, t.angular.z = vx, vy, wz
    return t


STAMP = genpy.Time(12, 500)


def test_transform_places_the_child_at_the_pose():
    t = transform_from_pose(pose(1.0, -2.0, 0.01, 0.5), STAMP, 'world', 'base_link_truth')
    assert (t.header.frame_id, t.child_frame_id, t.header.stamp) == ('world', 'base_link_truth', STAMP)
    assert (t.transform.translation.x, t.transform.translation.y, t.transform.translation.z) == (1.0, -2.0, 0.01)
    assert t.transform.rotation.z == pytest.approx(math.sin(0.25))
    assert t.transform.rotation.w == pytest.approx(math.cos(0.25))


def test_quaternions_are_normalized():
    t = transform_from_pose(pose(0, 0, 0, 1.0, scale=1.001), STAMP, 'world', 'robot')
    q = t.transform.rotation
    assert q.x ** 2 + q.y ** 2 + q.z ** 2 + q.w ** 2 == pytest.approx(1.0)


def test_odometry_twist_is_in_the_robot_frame():
    # Facing +y (yaw 90 deg) and driving forward at 0.5 m/s: the world twist is +y.
    odom = odometry_from_model_state(pose(3.0, 4.0, 0.0, math.pi / 2), world_twist(0.0, 0.5, 0.2), STAMP,
                                     'world', 'base_link_truth')
    assert (odom.header.frame_id, odom.child_frame_id, odom.header.stamp) == ('world', 'base_link_truth', STAMP)
    assert (odom.pose.pose.position.x, odom.pose.pose.position.y) == (3.0, 4.0)
    assert odom.twist.twist.linear.x == pytest.approx(0.5)
    assert odom.twist.twist.linear.y == pytest.approx(0.0, abs=1e-12)
    assert odom.twist.twist.angular.z == pytest.approx(0.2)


def test_odometry_reports_sideways_slip():
    odom = odometry_from_model_state(pose(0, 0, 0, 0.0), world_twist(0.0, 0.1, 0.0), STAMP, 'world', 'r')
    assert odom.twist.twist.linear.y == pytest.approx(0.1)


def test_ground_truth_has_zero_covariance():
    odom = odometry_from_model_state(pose(0, 0, 0, 0.0), world_twist(0, 0, 0), STAMP, 'world', 'r')
    assert list(odom.pose.covariance) == [0.0] * 36 and list(odom.twist.covariance) == [0.0] * 36
