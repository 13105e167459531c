"""The triangle IK against KDL's forward kinematics of katana_description's URDF: thousands of
random configurations within the limits, every branch, seeds, and the reasons for failure."""
import math
import os
import re
import sys

import numpy as np
import PyKDL
import pytest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..', 'src'))
from katana_pick import katana_ik  # noqa: E402
from katana_pick.arm_geometry import (BASE_LINK, TOOL_FRAME, KatanaGeometry, geometry_from_urdf,  # noqa: E402
                                      within_limits)
from katana_pick.katana_ik import IkError, forward, gripper_pitch, solutions, solve  # noqa: E402
from katana_pick.kdl_chain import kdl_chain  # noqa: E402

from katana_urdf import katana_urdf  # noqa: E402

G = KatanaGeometry()


@pytest.fixture(scope='module')
def urdf():
    return katana_urdf()


@pytest.fixture(scope='module')
def kdl_fk(urdf):
    chain, joints = kdl_chain(urdf, BASE_LINK, TOOL_FRAME)
    assert [j.name for j in joints] == list(G.joint_names)
    solver = PyKDL.ChainFkSolverPos_recursive(chain)

    def fk(q):
        """(position (3,), gripper axis (3,)) of the tool frame in katana_base_link."""
        array = PyKDL.JntArray(len(q))
        for i, v in enumerate(q):
            array[i] = v
        frame = PyKDL.Frame()
        assert solver.JntToCart(array, frame) >= 0
        return np.array([frame.p[i] for i in range(3)]), np.array([frame.M.UnitX()[i] for i in range(3)])
    fk.chain = chain  # PyKDL's solvers only point at their chain: keep it alive
    return fk


def random_configuration(rng):
    return [rng.uniform(lim.lower, lim.upper) for lim in G.limits]


def target_of(kdl_fk, q):
    position, axis = kdl_fk(q)
    return position, gripper_pitch(position[0], position[1], axis)


def angle_difference(a, b):
    return abs(math.remainder(a - b, 2 * math.pi))


# --- the geometry is the URDF's ---

def test_geometry_read_from_the_urdf_equals_the_defaults(urdf):
    assert geometry_from_urdf(urdf) == G
    assert (G.shoulder_height, G.upper_arm, G.forearm, G.wrist_to_tool) == (0.2015, 0.19, 0.139, 0.1473)


@pytest.mark.parametrize('change, message', [
    ('<axis xyz="0 -1 0"/>', 'katana_motor2_lift_joint: expected a revolute joint about'),
    ('<origin rpy="0 0 0" xyz="0.19 0 0"/>', 'katana_motor3_lift_joint'),
])
def test_a_urdf_of_another_shape_is_refused_with_the_joint_named(urdf, change, message):
    if 'axis' in change:
        broken = urdf.replace(change, '<axis xyz="0 1 0"/>', 1)
    else:
        broken = urdf.replace(change, '<origin rpy="0 0 0" xyz="0.19 0.01 0"/>', 1)
    assert broken != urdf
    with pytest.raises(ValueError, match=message):
        geometry_from_urdf(broken)


def test_zero_pose_and_stretched_up_in_kdl(kdl_fk):
    position, axis = kdl_fk([0.0] * 5)
    np.testing.assert_allclose(position, [0.19 + 0.139 + 0.1473, 0, 0.2015], atol=1e-12)
    np.testing.assert_allclose(axis, [1, 0, 0], atol=1e-12)
    position, axis = kdl_fk([0.0, math.pi / 2, 0.0, 0.0, 0.0])
    np.testing.assert_allclose(position, [0, 0, 0.2015 + 0.19 + 0.139 + 0.1473], atol=1e-12)
    np.testing.assert_allclose(axis, [0, 0, 1], atol=1e-12)


def test_planar_forward_kinematics_agrees_with_kdl(kdl_fk):
    rng = np.random.default_rng(1)
    for _ in range(1000):
        q = random_configuration(rng)
        position, pitch = target_of(kdl_fk, q)
        x, y, z, p = forward(G, q)
        np.testing.assert_allclose([x, y, z], position, atol=1e-12)
        assert angle_difference(p, pitch) < 1e-9


# --- IK against KDL ---

def test_ik_reaches_every_target_made_from_a_configuration_within_the_limits(kdl_fk):
    """4000 random configurations within the limits: each one's tool position and pitch is a
    reachable target, so the IK must solve every one, from a random seed, within the limits."""
    rng = np.random.default_rng(7)
    errors, pitch_errors, solved = [], [], 0
    for _ in range(4000):
        position, pitch = target_of(kdl_fk, random_configuration(rng))
        q = solve(G, *position, pitch, seed=random_configuration(rng))
        assert within_limits(G, q)
        reached, reached_pitch = target_of(kdl_fk, q)
        errors.append(np.linalg.norm(reached - position))
        pitch_errors.append(angle_difference(reached_pitch, pitch))
        solved += 1
    assert solved == 4000
    assert max(errors) < 1e-3        # the requirement: 1 mm
    assert max(errors) < 1e-9        # what an exact solver gives
    assert max(pitch_errors) < 1e-9


def test_seeded_with_the_configuration_the_ik_gives_it_back(kdl_fk):
    rng = np.random.default_rng(8)
    for _ in range(500):
        q = random_configuration(rng)
        position, pitch = target_of(kdl_fk, q)
        np.testing.assert_allclose(solve(G, *position, pitch, seed=q), q, atol=1e-7)


def test_all_four_branches_are_found_and_each_reaches_the_target(kdl_fk):
    # High and to the left, the arm reaches with either elbow, turned to the target or turned
    # away and leaning back over its base (pan pi/2 - pi: inside the pan limits).
    x, y, z, pitch = 0.0, 0.2, 0.5, 0.0
    found = solutions(G, x, y, z, pitch)
    names = sorted(name for name, _ in found)
    assert names == ['elbow down', 'elbow down, shoulder flipped', 'elbow up', 'elbow up, shoulder flipped']
    for name, q in found:
        reached, reached_pitch = target_of(kdl_fk, q)
        np.testing.assert_allclose(reached, [x, y, z], atol=1e-9)
        assert angle_difference(reached_pitch, pitch) < 1e-9, name
        assert within_limits(G, q)
    flipped = dict(found)['elbow up, shoulder flipped']
    assert flipped[0] == pytest.approx(-math.pi / 2) and flipped[1] > math.pi / 2
    assert dict(found)['elbow up'][0] == pytest.approx(math.pi / 2)


def test_the_branch_closest_to_the_seed_wins():
    found = dict(solutions(G, 0.3, 0.1, 0.1, -math.pi / 2))
    up, down = found['elbow up'], found['elbow down']
    assert up[2] < 0 < down[2]                       # elbow up bends the forearm down
    assert solve(G, 0.3, 0.1, 0.1, -math.pi / 2, seed=up) == pytest.approx(up)
    assert solve(G, 0.3, 0.1, 0.1, -math.pi / 2, seed=down) == pytest.approx(down)


def test_a_target_behind_the_pan_limit_is_reached_leaning_back_over_the_base(kdl_fk):
    bearing = 3.0  # the pan joint stops at 2.891
    x, y, z, pitch = 0.1 * math.cos(bearing), 0.1 * math.sin(bearing), 0.5, 0.3
    q = solve(G, x, y, z, pitch)
    assert q[0] == pytest.approx(bearing - math.pi)  # turned away: the target is behind the arm
    np.testing.assert_allclose(target_of(kdl_fk, q)[0], [x, y, z], atol=1e-9)


def test_roll_is_kept_from_the_seed_unless_given():
    assert solve(G, 0.3, 0.0, 0.1, -math.pi / 2, seed=(0, 0, 0, 0, 1.25))[4] == 1.25
    assert solve(G, 0.3, 0.0, 0.1, -math.pi / 2, roll=-0.5)[4] == -0.5
    # Whole turns are taken off when that puts the roll inside its limits.
    assert solve(G, 0.3, 0.0, 0.1, -math.pi / 2, roll=2 * math.pi + 0.5)[4] == pytest.approx(0.5)


def test_on_the_pan_axis_the_pan_stays_where_the_seed_has_it(kdl_fk):
    q = solve(G, 0.0, 0.0, 0.55, math.pi / 2, seed=(1.0, 1.2, 0.3, 0.0, 0.0))
    assert q[0] == pytest.approx(1.0)
    np.testing.assert_allclose(target_of(kdl_fk, q)[0], [0, 0, 0.55], atol=1e-9)


# --- why not ---

def excess_in(message):
    return float(re.search(r'out of reach by (\d+\.\d+) m', message).group(1))


def test_a_target_too_far_says_by_how_much():
    with pytest.raises(IkError, match='out of reach by') as error:
        solve(G, 0.9, 0.0, 0.2015, 0.0)
    # Stretched out horizontally the wrist reaches 0.329 m from the shoulder; it would need 0.7527.
    assert excess_in(str(error.value)) == pytest.approx(0.9 - 0.1473 - 0.329, abs=1e-3)


def test_a_target_too_close_to_the_shoulder_says_so():
    # Wrist axis 0.02 m from the shoulder: closer than upper arm minus forearm (0.051 m).
    with pytest.raises(IkError, match='out of reach by') as error:
        solve(G, 0.02 + 0.1473, 0.0, 0.2015, 0.0)
    assert excess_in(str(error.value)) == pytest.approx(0.051 - 0.02, abs=1e-3)
    assert 'from 0.051 to 0.329 m' in str(error.value)


def test_a_target_only_reachable_past_a_limit_names_the_joint():
    # Pointing straight down 0.3 m above the floor right in front: the wrist cannot bend that far.
    with pytest.raises(IkError, match='outside the joint limits') as error:
        solve(G, 0.2, 0.0, 0.3, -math.pi / 2)
    message = str(error.value)
    assert 'katana_motor4_lift_joint' in message
    assert message.count(' needs ') == 4  # every branch, each with its reason


@pytest.mark.parametrize('arguments, name', [
    ((math.nan, 0.0, 0.2, 0.0), 'target x'), ((0.3, math.inf, 0.2, 0.0), 'target y'),
    ((0.3, 0.0, -math.inf, 0.0), 'target z'), ((0.3, 0.0, 0.2, math.nan), 'target pitch'),
])
def test_nan_and_inf_targets_are_refused_by_name(arguments, name):
    with pytest.raises(IkError, match=name + ' is (nan|inf|-inf): expected a finite number'):
        solve(G, *arguments)


def test_bad_seed_and_roll_are_refused():
    with pytest.raises(IkError, match='seed katana_motor3_lift_joint is nan'):
        solve(G, 0.3, 0.0, 0.1, -math.pi / 2, seed=(0, 0, math.nan, 0, 0))
    with pytest.raises(IkError, match='seed has 4 angles'):
        solve(G, 0.3, 0.0, 0.1, -math.pi / 2, seed=(0, 0, 0, 0))
    with pytest.raises(IkError, match='target roll is inf'):
        solve(G, 0.3, 0.0, 0.1, -math.pi / 2, roll=math.inf)
    with pytest.raises(IkError, match='katana_motor5_wrist_roll_joint'):
        solve(G, 0.3, 0.0, 0.1, -math.pi / 2, roll=3.0)  # the roll stops at 2.871 (and -2.993)


def test_ik_errors_are_value_errors():
    assert issubclass(IkError, ValueError)
    assert katana_ik.solve is solve
