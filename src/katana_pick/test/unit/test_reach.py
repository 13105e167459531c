"""The arm's reach for pick-and-stack (katana_pick.reach) sampled against KDL's forward kinematics
of katana_description's URDF: every pose the arm's joints put the tool in, within their limits,
is called reachable, and every move called reachable is made by joint angles within the limits
that KDL puts on it; the far edge of the taking range is where the stretched arm ends."""
import math
import os
import random
import sys

import numpy as np
import PyKDL
import pytest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..', 'src'))
from katana_pick import katana_ik, reach  # noqa: E402
from katana_pick.arm_geometry import BASE_LINK, TOOL_FRAME, geometry_from_urdf, within_limits  # noqa: E402
from katana_pick.kdl_chain import kdl_chain  # noqa: E402
from katana_pick.stacking import StackingOptions  # noqa: E402

from katana_urdf import katana_urdf  # noqa: E402

STACKING = StackingOptions()


@pytest.fixture(scope='module')
def urdf():
    return katana_urdf()


@pytest.fixture(scope='module')
def geometry(urdf):
    return geometry_from_urdf(urdf)


@pytest.fixture(scope='module')
def kdl_fk(urdf):
    chain, _ = kdl_chain(urdf, BASE_LINK, TOOL_FRAME)
    solver = PyKDL.ChainFkSolverPos_recursive(chain)

    def fk(q):
        """(range, height, pitch) of the tool frame, with the arm panned to 0."""
        array = PyKDL.JntArray(len(q))
        for i, v in enumerate(q):
            array[i] = v
        frame = PyKDL.Frame()
        assert solver.JntToCart(array, frame) >= 0
        axis = frame.M.UnitX()
        return frame.p[0], frame.p[2], katana_ik.gripper_pitch(frame.p[0], frame.p[1], [axis[0], axis[1], axis[2]])
    fk.chain = chain  # PyKDL's solvers only point at their chain: keep it alive
    return fk


@pytest.fixture(scope='module')
def reach_map(geometry):
    return reach.reach_map(geometry, [0.20 + 0.02 * k for k in range(16)], max_level=4)


def test_every_pose_the_joints_make_is_called_reachable(geometry, kdl_fk):
    rng = random.Random(7)
    tried = 0
    while tried < 3000:
        q = [0.0] + [rng.uniform(lim.lower, lim.upper) for lim in geometry.limits[1:4]] + [0.0]
        r, z, pitch = kdl_fk(q)
        if r <= 0.01:  # the far side of the base, or on its axis: not a range in front of the arm
            continue
        tried += 1
        assert reach.pose_reachable(geometry, r, z, pitch), (q, r, z, pitch)


def test_every_move_called_reachable_is_made_by_joints_within_the_limits(geometry, kdl_fk, reach_map):
    rng = random.Random(3)
    claims = [(r, g, 'take') for r in reach_map.radii for g in reach_map.take[r]]
    claims += [(r, g, level) for (r, level), gs in reach_map.place.items() for g in gs]
    assert len(claims) > 1000
    for r, grasp, what in rng.sample(claims, 300):
        if what == 'take':
            points = [(r - STACKING.approach_distance, grasp.height), (r, grasp.height),
                      (r, grasp.height + STACKING.lift)]
        else:
            z = what * STACKING.can_height + STACKING.place_gap + grasp.height
            points = [(r, z + STACKING.lift), (r, z), (r - STACKING.retreat_distance, z)]
        for pr, pz in points:
            found = katana_ik.solutions(geometry, pr, 0.0, pz, grasp.pitch)
            assert found, (r, grasp, what, pr, pz)
            for _, q in found:
                assert within_limits(geometry, q)
                fr, fz, fpitch = kdl_fk(q)
                assert abs(fr - pr) < 1e-9 and abs(fz - pz) < 1e-9
                assert abs(math.remainder(fpitch - grasp.pitch, 2 * math.pi)) < 1e-9


def test_a_move_with_a_point_out_of_reach_is_not_called_reachable(geometry):
    # Taking a can 0.47 m out grasped 0.04 m up: the stretched arm (0.4763 m from the shoulder,
    # 0.2015 m up) ends 0.4480 m out at that height, so the grasp point is out of reach.
    grasp = reach.Grasp(0.04, 0.0)
    assert not reach.can_take(geometry, 0.47, grasp)
    assert not reach.pose_reachable(geometry, 0.47, 0.04, -0.3)


def test_the_far_edge_of_taking_is_the_stretched_arm(geometry, reach_map):
    # The farthest grasp point is at the highest grasp (0.10 m up): the stretched arm reaches
    # sqrt(0.4763^2 - 0.1015^2) = 0.4654 m out there, at a pitch (-0.21 rad) the gripper allows.
    stretched = geometry.upper_arm + geometry.forearm + geometry.wrist_to_tool
    farthest = math.sqrt(stretched ** 2 - (geometry.shoulder_height - 0.10) ** 2)
    near, far = reach_map.take_range()
    assert farthest - 0.02 <= far <= farthest
    fine = reach.reach_map(geometry, np.arange(0.440, 0.470, 0.002), max_level=0)
    assert farthest - 0.004 <= fine.take_range()[1] <= farthest
    # Near the base a can is out of reach for every grasp: the elbow's limit (-2.22 rad) stops the
    # forearm folding back far enough (the 0.25 and 0.29 m cans of issue 38); the old band's
    # 0.34 m is taken.
    assert 0.29 < near <= 0.34


def test_higher_levels_are_placed_nearer_the_base(reach_map):
    # A tower's top rises towards the shoulder and beyond: the ranges that can be placed on move in.
    def placed(level):
        return [r for r in reach_map.radii if reach_map.place[(r, level)]]
    for level in range(1, 4):
        assert placed(level + 1) and placed(level)
        assert max(placed(level + 1)) <= max(placed(level))
        assert min(placed(level + 1)) <= min(placed(level))
    # Level 4's place points (0.53-0.59 m up) lie far above the shoulder (0.2015 m up), where the
    # stretched arm reaches much less far out than at level 1's (0.17-0.23 m up).
    assert max(placed(4)) < max(placed(1)) - 0.1


def test_stackable_takes_and_places_with_one_grasp(geometry, reach_map):
    for r_can in reach_map.radii:
        for r_tower in reach_map.radii:
            for level in range(0, 4):
                for grasp in reach_map.stackable(r_can, r_tower, level):
                    assert grasp in reach_map.take[r_can] and grasp in reach_map.place[(r_tower, level)]
    # A fourth can (level 3) taken in the old band goes onto a tower standing nearer the base,
    # never onto one at the band's far side (issue 38's "out of reach by 0.032 m").
    assert reach_map.stackable(0.36, 0.30, 3)
    assert not reach_map.stackable(0.36, 0.42, 3)
