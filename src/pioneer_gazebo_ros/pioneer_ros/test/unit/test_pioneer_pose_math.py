"""pioneer_ros.pose_math: quaternions, yaw and frame rotations (no ROS master needed)."""
import math
import os
import sys

import pytest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..', 'src'))

from pioneer_ros.pose_math import (normalize_quaternion, quaternion_from_yaw, roll_pitch_yaw,  # noqa: E402
                                   rotate, rotate_inverse, wrap_angle, yaw_from_quaternion)


def quaternion_from_rpy(roll, pitch, yaw):
    cr, sr = math.cos(roll / 2), math.sin(roll / 2)
    cp, sp = math.cos(pitch / 2), math.sin(pitch / 2)
    cy, sy = math.cos(yaw / 2), math.sin(yaw / 2)
    return (sr * cp * cy - cr * sp * sy, cr * sp * cy + sr * cp * sy, cr * cp * sy - sr * sp * cy,
            cr * cp * cy + sr * sp * sy)


@pytest.mark.parametrize('yaw', [0.0, 0.3, -1.2, math.pi / 2, 3.0, -3.0])
def test_yaw_round_trips_through_a_quaternion(yaw):
    assert yaw_from_quaternion(quaternion_from_yaw(yaw)) == pytest.approx(yaw, abs=1e-12)


def test_yaw_of_a_scaled_quaternion_is_the_same():
    q = quaternion_from_yaw(0.7)
    assert yaw_from_quaternion(tuple(3.0 * c for c in q)) == pytest.approx(0.7)


@pytest.mark.parametrize('rpy', [(0.1, -0.2, 2.5), (0.0, 0.0, -1.0), (-0.4, 0.3, 0.0)])
def test_roll_pitch_yaw_inverts_the_zyx_construction(rpy):
    assert roll_pitch_yaw(quaternion_from_rpy(*rpy)) == pytest.approx(rpy, abs=1e-12)


def test_yaw_ignores_small_tilts():
    assert yaw_from_quaternion(quaternion_from_rpy(0.01, -0.02, 1.0)) == pytest.approx(1.0, abs=1e-12)


def test_zero_and_nan_quaternions_are_refused():
    with pytest.raises(ValueError):
        normalize_quaternion((0.0, 0.0, 0.0, 0.0))
    with pytest.raises(ValueError):
        normalize_quaternion((float('nan'), 0.0, 0.0, 1.0))


@pytest.mark.parametrize('angle,wrapped', [(0.0, 0.0), (math.pi / 2, math.pi / 2), (3 * math.pi / 2, -math.pi / 2),
                                           (-3 * math.pi / 2, math.pi / 2), (7.0, 7.0 - 2 * math.pi)])
def test_wrap_angle(angle, wrapped):
    assert wrap_angle(angle) == pytest.approx(wrapped)


def test_rotate_by_a_quarter_turn_about_z():
    q = quaternion_from_yaw(math.pi / 2)
    assert rotate(q, (1.0, 0.0, 0.0)) == pytest.approx((0.0, 1.0, 0.0), abs=1e-12)
    assert rotate_inverse(q, (0.0, 1.0, 0.0)) == pytest.approx((1.0, 0.0, 0.0), abs=1e-12)


def test_rotate_matches_the_rotation_matrix():
    q = quaternion_from_rpy(0.3, -0.5, 1.1)
    x, y, z, w = q
    m = [[1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
         [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
         [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)]]
    v = (0.4, -1.3, 2.2)
    expected = tuple(sum(m[i][j] * v[j] for j in range(3)) for i in range(3))
    assert rotate(q, v) == pytest.approx(expected, abs=1e-12)
    assert rotate_inverse(q, rotate(q, v)) == pytest.approx(v, abs=1e-12)
