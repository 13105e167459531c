"""map_scoring: pose algebra, interpolation in time, and a map's occupied cells against walls."""
import math
import os
import sys

import pytest

sys.path.insert(0, os.path.join(os.path.dirname(__file__), '..', '..', 'src'))
from bullet_sim_testing.map_scoring import compose, interpolate, map_alignment, relative  # noqa: E402


class Box:
    """An axis-aligned wall seen from above, as map_alignment expects one."""

    def __init__(self, x, y, sx, sy):
        self.x, self.y, self.sx, self.sy, self.yaw = x, y, sx, sy, 0.0

    def distance(self, px, py):
        du, dv = abs(px - self.x) - self.sx / 2, abs(py - self.y) - self.sy / 2
        return math.hypot(max(du, 0.0), max(dv, 0.0)) if du > 0 or dv > 0 else -max(du, dv)

    def ray_distance(self, ox, oy, dx, dy):
        t_near, t_far = -math.inf, math.inf
        for p, v, half in ((ox - self.x, dx, self.sx / 2), (oy - self.y, dy, self.sy / 2)):
            if abs(v) < 1e-12:
                if abs(p) > half:
                    return None
                continue
            t1, t2 = (-half - p) / v, (half - p) / v
            t_near, t_far = max(t_near, min(t1, t2)), min(t_far, max(t1, t2))
        return None if t_near > t_far or t_far < 0 else max(t_near, 0.0)


def test_relative_undoes_compose():
    a, b = (1.0, -2.0, 0.7), (0.3, 0.4, -1.2)
    assert relative(a, compose(a, b)) == pytest.approx(b)
    # A quarter turn takes the child's x axis onto the parent's y axis.
    assert compose((0, 0, math.pi / 2), (1, 0, 0)) == pytest.approx((0, 1, math.pi / 2))


def test_interpolation_is_linear_in_time_and_refuses_gaps_and_the_outside():
    samples = [(0.0, 0.0, 0.0, 0.0), (0.1, 1.0, 2.0, 0.2), (1.0, 5.0, 5.0, 0.0)]
    assert interpolate(samples, 0.05) == pytest.approx((0.5, 1.0, 0.1))
    assert interpolate(samples, 0.5) is None       # 0.9 s between the samples: a gap
    assert interpolate(samples, -0.1) is None
    assert interpolate(samples, 2.0) is None


def test_cells_on_the_visible_face_score_full_precision_and_coverage():
    wall = Box(0.0, 0.0, 2.0, 0.2)                       # its top face is y = 0.1, x in [-1, 1]
    on_face = [(x / 20.0, 0.1) for x in range(-20, 21)]
    precision, mean, coverage = map_alignment([wall], on_face, seen_from=[(0.0, 1.0)], max_range=5.0)
    assert precision == pytest.approx(1.0)
    assert mean == pytest.approx(0.0, abs=1e-9)
    assert coverage == pytest.approx(1.0)                # only the top face can be seen from (0, 1)


def test_cells_off_the_wall_or_half_the_face_score_accordingly():
    wall = Box(0.0, 0.0, 2.0, 0.2)
    half_face = [(x / 20.0, 0.1) for x in range(0, 21)]  # x in [0, 1]
    _, _, coverage = map_alignment([wall], half_face, seen_from=[(0.0, 1.0)], max_range=5.0)
    assert 0.45 < coverage < 0.6
    astray = [(0.0, 0.5), (0.5, 0.6)]
    precision, mean, _ = map_alignment([wall], astray, seen_from=[(0.0, 1.0)], max_range=5.0)
    assert precision == 0.0
    assert mean == pytest.approx((0.4 + 0.5) / 2)
    # Out of range, nothing is visible, so nothing can be covered.
    assert map_alignment([wall], half_face, seen_from=[(0.0, 1.0)], max_range=0.5)[2] == 0.0
