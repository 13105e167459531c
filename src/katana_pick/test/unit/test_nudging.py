"""Nudging (issue 38, item 2): a can nearer the base than any grasp takes it is pushed outward
along its line from the base, low, by the closed fingers pointing down, to where the arm takes it;
one the arm cannot reach behind, or that would slide into another can, is refused with the reason."""
import math
import os
import sys

import pytest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..', 'src'))
from katana_pick import katana_ik  # noqa: E402
from katana_pick.arm_geometry import KatanaGeometry, within_limits  # noqa: E402
from katana_pick.nudging import NudgeOptions, nudge_target, plan_nudge  # noqa: E402
from katana_pick.reach import can_take, grasps, taking_range  # noqa: E402
from katana_pick.stacking import Grip, Move, StackingOptions  # noqa: E402
from katana_pick.trajectories import PlanError  # noqa: E402

G = KatanaGeometry()
O = StackingOptions()
N = NudgeOptions()
START = (0.0, 0.0, 0.0, 0.0, 0.0)
NEAR = taking_range(G)[0]


def fingertips(q):
    """The fingertips' range from the base's axis and height, by forward kinematics."""
    x, y, z, pitch = katana_ik.forward(G, q)
    r = math.hypot(x, y)
    return r + N.tip_length * math.cos(pitch), z + N.tip_length * math.sin(pitch), math.atan2(y, x)


def test_the_nearest_range_a_grasp_takes_a_can_at_is_the_reach_maps():
    assert 0.31 <= NEAR <= 0.33
    assert any(can_take(G, NEAR, g) for g in grasps())
    assert not any(can_take(G, NEAR - 0.01, g) for g in grasps())


@pytest.mark.parametrize('r', [0.23, 0.27, 0.30])
def test_a_near_can_is_pushed_low_along_its_line_to_where_a_grasp_takes_it(r):
    bearing = 0.4
    can = (r * math.cos(bearing), r * math.sin(bearing))
    target, steps, paths = plan_nudge(G, START, can, NEAR)
    assert math.hypot(*target) == pytest.approx(NEAR + N.beyond)
    assert math.atan2(target[1], target[0]) == pytest.approx(bearing)
    assert any(can_take(G, round(math.hypot(*target), 3), g) for g in grasps())  # now in reach
    assert isinstance(steps[0], Grip) and steps[0].position == O.close_position and not steps[0].hold
    moves = [s for s in steps if isinstance(s, Move)]
    assert [m.what for m in moves][2] == 'push the can outward along the line from the base'
    for path in paths:
        assert all(within_limits(G, q) for q in path.positions)
    # The push, every via point: the fingertips tip_height above the table, on the can's line, from
    # start_gap behind its near face to where that face stands at the target.
    push = paths[2]
    tips = [fingertips(q) for q in paths[1].positions[-1:] + push.positions]
    face = r - O.can_radius - N.finger_half_width
    assert tips[0][0] == pytest.approx(face - N.start_gap, abs=1e-6)
    assert tips[-1][0] == pytest.approx(face + math.hypot(*target) - r, abs=1e-6)
    for tip_r, tip_z, tip_bearing in tips:
        assert tip_z == pytest.approx(N.tip_height, abs=1e-6)
        assert tip_bearing == pytest.approx(bearing, abs=1e-6)
    # Pointing down (no shallower than the options allow) and, after the push, up above the cans.
    pitch = moves[2].poses[-1].pitch
    assert N.steepest - 1e-9 <= pitch <= N.shallowest + 1e-9
    assert fingertips(paths[-1].positions[-1])[1] > O.can_height


def test_a_can_the_arm_cannot_reach_behind_is_refused_with_the_reason():
    with pytest.raises(PlanError, match=r'no pitch from -1\.57 to -0\.90 rad pushes it .*joint limits'):
        plan_nudge(G, START, (0.15, 0.0), NEAR)


def test_a_can_that_would_slide_into_another_is_refused():
    can = (0.25, 0.0)
    target = nudge_target(can, NEAR)
    other = (target[0] + 0.05, 0.0)  # just beyond where it would stop
    with pytest.raises(PlanError, match=r'would touch the can at \(%.3f, 0.000\)' % other[0]):
        plan_nudge(G, START, can, NEAR, others=[other])
    # One clear of its path does not stop it.
    plan_nudge(G, START, can, NEAR, others=[(target[0], 0.2)])
