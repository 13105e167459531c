"""clearance.OpenFingers against KDL's forward kinematics of katana_description's URDF, and what
the open fingers' true shape changes: a can beside the tool is in their way, one as far straight
ahead is not (no one radius round the tool frame says both)."""
import math
import os
import random
import sys

import PyKDL
import pytest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..', 'src'))
from katana_pick import katana_ik  # noqa: E402
from katana_pick.arm_geometry import BASE_LINK, KatanaGeometry  # noqa: E402
from katana_pick.clearance import Held, Obstacle, OpenFingers, path_conflict  # noqa: E402
from katana_pick.kdl_chain import kdl_chain  # noqa: E402
from katana_pick.stacking import StackingOptions  # noqa: E402

from katana_urdf import katana_urdf  # noqa: E402

G = KatanaGeometry()
O = StackingOptions()
FINGER_LINKS = ('katana_r_finger_link', 'katana_l_finger_link')


@pytest.fixture(scope='module')
def finger_frames():
    """q (5 arm joints), finger angle -> [PyKDL.Frame of each finger link], right then left."""
    urdf = katana_urdf()
    chains = [kdl_chain(urdf, BASE_LINK, link)[0] for link in FINGER_LINKS]
    solvers = [PyKDL.ChainFkSolverPos_recursive(c) for c in chains]

    def frames(q, angle):
        found = []
        for solver in solvers:
            array = PyKDL.JntArray(6)
            for i, v in enumerate(list(q) + [angle]):
                array[i] = v
            frame = PyKDL.Frame()
            assert solver.JntToCart(array, frame) >= 0
            found.append(frame)
        return found
    frames.chains = chains  # PyKDL's solvers only point at their chains: keep them alive
    return frames


def _vector(v):
    return tuple(v[i] for i in range(3))


def test_the_finger_frames_are_where_kdl_puts_the_urdfs_finger_links(finger_frames):
    rng = random.Random(7)
    for _ in range(500):
        q = [rng.uniform(lim.lower, lim.upper) for lim in G.limits]
        angle = rng.uniform(O.close_position, O.open_position)
        for ours, kdl in zip(OpenFingers(angle).fingers(G, q), finger_frames(q, angle)):
            expected = (_vector(kdl.p), _vector(kdl.M.UnitX()), _vector(kdl.M.UnitY()), _vector(kdl.M.UnitZ()))
            for a, b in zip(ours, expected):
                assert math.dist(a, b) < 1e-9, (q, angle)


def test_each_part_covers_the_finger_boxs_cross_section_as_kdl_places_it(finger_frames):
    """The finger box (0.008 x 0.02 m across): each part's bottom is its cross-section's lowest
    corner, and its radius reaches every corner, at most the half sizes' sum; all within the
    fingers' reach of the tool frame."""
    fingers = OpenFingers(O.open_position)
    rng = random.Random(8)
    for _ in range(200):
        q = [rng.uniform(lim.lower, lim.upper) for lim in G.limits]
        parts = fingers.parts(G, q)
        for f, frame in enumerate(finger_frames(q, fingers.angle)):
            for k in range(fingers.points):
                part = parts[f * fingers.points + k]
                s = fingers.length * k / (fingers.points - 1)
                corners = [frame * PyKDL.Vector(s, a * fingers.half_thickness, b * fingers.half_height)
                           for a in (-1, 1) for b in (-1, 1)]
                assert abs(min(c[2] for c in corners) - part.bottom) < 1e-9
                assert max(math.hypot(c[0] - part.x, c[1] - part.y) for c in corners) <= part.radius + 1e-9
                assert part.radius <= fingers.half_thickness + fingers.half_height + 1e-9
        # path_conflict places the parts only where the tool frame is within their reach of an obstacle.
        tool = katana_ik.forward(G, q)
        for part in parts:
            assert math.hypot(part.x - tool[0], part.y - tool[1]) + part.radius <= fingers.reach + 1e-9
            assert tool[2] - part.bottom <= fingers.reach + 1e-9


def test_open_fingers_reach_far_to_the_side_and_little_ahead():
    """The gripper level, its tool frame at (0.30, 0, 0.08): the open fingers' outer faces 0.058 m
    to either side (0.03 + 0.08 sin 0.30 + 0.004), their tips 0.019 m ahead of the tool frame
    (0.08 cos 0.30 - 0.0573), their bottoms 0.01 m below it."""
    q = katana_ik.solve(G, 0.30, 0.0, 0.08, 0.0)
    parts = OpenFingers(O.open_position).parts(G, q)
    side = max(abs(p.y) + p.radius for p in parts)
    ahead = max(p.x - 0.30 for p in parts)
    assert 0.0575 < side < 0.0578
    assert 0.0190 < ahead < 0.0192
    assert all(abs(p.bottom - 0.07) < 1e-9 for p in parts)


def test_a_can_beside_the_tool_is_in_the_fingers_way_and_one_as_far_ahead_is_not():
    """0.09 m from the tool frame, below the cans' tops: beside it (as when the arm pans past a
    can) the open fingertip is 0.041 m from the can's axis, inside its radius and the margin;
    straight ahead the fingers clear it. The old 0.04 m radius passed both, and 0.06 m (what the
    side needs) refuses both."""
    q = katana_ik.solve(G, 0.30, 0.0, 0.08, 0.0)
    beside = (Obstacle(0.30, -0.09, O.can_height, O.can_radius),)
    ahead = (Obstacle(0.39, 0.0, O.can_height, O.can_radius),)
    fingers = OpenFingers(O.open_position)
    assert path_conflict(G, (q, q), fingers, beside) is not None
    assert path_conflict(G, (q, q), fingers, ahead) is None
    old, wide = Held(0.03, 0.04), Held(0.03, 0.06)
    assert path_conflict(G, (q, q), old, beside) is None and path_conflict(G, (q, q), old, ahead) is None
    assert path_conflict(G, (q, q), wide, beside) is not None and path_conflict(G, (q, q), wide, ahead) is not None


def test_a_can_the_fingers_pass_above_is_clear():
    """The same can beside the tool, the tool 0.15 m up: the fingers' bottoms (0.14 m) are above
    its top (0.12 m) by more than the 0.01 m margin."""
    q = katana_ik.solve(G, 0.30, 0.0, 0.15, 0.0)
    beside = (Obstacle(0.30, -0.09, O.can_height, O.can_radius),)
    assert path_conflict(G, (q, q), OpenFingers(O.open_position), beside) is None
