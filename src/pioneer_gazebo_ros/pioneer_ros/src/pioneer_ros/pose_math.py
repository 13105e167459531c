"""Quaternion and planar-angle maths for the Pioneer nodes, on plain tuples (no ROS).

Quaternions are (x, y, z, w), as in geometry_msgs/Quaternion; vectors are (x, y, z).
"""
import math


def wrap_angle(angle):
    """The same angle in [-pi, pi)."""
    return (angle + math.pi) % (2.0 * math.pi) - math.pi


def normalize_quaternion(q):
    """q scaled to unit length; ValueError for a zero or non-finite quaternion."""
    norm = math.sqrt(sum(c * c for c in q))
    if not (norm > 1e-12 and math.isfinite(norm)):
        raise ValueError('expected a non-zero, finite quaternion, got %r' % (tuple(q),))
    return tuple(c / norm for c in q)


def quaternion_from_yaw(yaw):
    """The rotation by yaw about z."""
    return (0.0, 0.0, math.sin(yaw / 2.0), math.cos(yaw / 2.0))


def yaw_from_quaternion(q):
    """The heading (rotation about z, ZYX convention) of q, in [-pi, pi]."""
    x, y, z, w = normalize_quaternion(q)
    return math.atan2(2.0 * (w * z + x * y), 1.0 - 2.0 * (y * y + z * z))


def roll_pitch_yaw(q):
    """(roll, pitch, yaw) of q, ZYX convention (tf's getRPY)."""
    x, y, z, w = normalize_quaternion(q)
    roll = math.atan2(2.0 * (w * x + y * z), 1.0 - 2.0 * (x * x + y * y))
    pitch = math.asin(max(-1.0, min(1.0, 2.0 * (w * y - z * x))))
    yaw = math.atan2(2.0 * (w * z + x * y), 1.0 - 2.0 * (y * y + z * z))
    return roll, pitch, yaw


def rotate(q, v):
    """v rotated by q (a vector of the rotated frame, expressed in the reference frame)."""
    x, y, z, w = normalize_quaternion(q)
    vx, vy, vz = v
    # v + 2 w (u x v) + 2 u x (u x v), with u the quaternion's vector part.
    tx = 2.0 * (y * vz - z * vy)
    ty = 2.0 * (z * vx - x * vz)
    tz = 2.0 * (x * vy - y * vx)
    return (vx + w * tx + (y * tz - z * ty),
            vy + w * ty + (z * tx - x * tz),
            vz + w * tz + (x * ty - y * tx))


def rotate_inverse(q, v):
    """v, given in the reference frame, expressed in the frame that q rotates to."""
    x, y, z, w = normalize_quaternion(q)
    return rotate((-x, -y, -z, w), v)
