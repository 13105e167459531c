"""Message building for the Pioneer nodes: ROS message types, but no node, master or clock.

Gazebo's /gazebo/get_model_state answers the model's pose and twist in the reference frame
(the world); nav_msgs/Odometry wants the twist in its child frame (the robot), so
odometry_from_model_state rotates it there. (The report's odometry publisher copied the world
twist, so its forward speed was only right while the robot faced along the world's x.)
"""
from geometry_msgs.msg import Quaternion, TransformStamped, Vector3
from nav_msgs.msg import Odometry

from pioneer_ros.pose_math import normalize_quaternion, rotate_inverse


def quaternion_tuple(q):
    return (q.x, q.y, q.z, q.w)


def _unit_quaternion_msg(q):
    x, y, z, w = normalize_quaternion(quaternion_tuple(q))
    return Quaternion(x=x, y=y, z=z, w=w)


def transform_from_pose(pose, stamp, frame_id, child_frame_id):
    """The transform frame_id -> child_frame_id that places the child at pose."""
    t = TransformStamped()
    t.header.stamp = stamp
    t.header.frame_id = frame_id
    t.child_frame_id = child_frame_id
    t.transform.translation = Vector3(x=pose.position.x, y=pose.position.y, z=pose.position.z)
    t.transform.rotation = _unit_quaternion_msg(pose.orientation)
    return t


def odometry_from_model_state(pose, twist, stamp, frame_id, child_frame_id):
    """nav_msgs/Odometry of a model at pose with twist (both in frame_id); the twist is
    expressed in child_frame_id, as REP 105 and nav_msgs/Odometry ask. Covariances stay 0:
    this is ground truth."""
    odom = Odometry()
    odom.header.stamp = stamp
    odom.header.frame_id = frame_id
    odom.child_frame_id = child_frame_id
    odom.pose.pose.position.x = pose.position.x
    odom.pose.pose.position.y = pose.position.y
    odom.pose.pose.position.z = pose.position.z
    odom.pose.pose.orientation = _unit_quaternion_msg(pose.orientation)
    q = quaternion_tuple(odom.pose.pose.orientation)
    linear = rotate_inverse(q, (twist.linear.x, twist.linear.y, twist.linear.z))
    angular = rotate_inverse(q, (twist.angular.x, twist.angular.y, twist.angular.z))
    odom.twist.twist.linear = Vector3(*linear)
    odom.twist.twist.angular = Vector3(*angular)
    return odom
