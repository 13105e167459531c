"""Can layouts: the launch file's x,y pairs, and seeded random layouts that keep the rules."""
import math
import os
import sys

import pytest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..', 'src'))
from katana_arm_gazebo.can_layouts import LayoutRules, parse_positions, random_layout  # noqa: E402


def test_parse_positions():
    assert parse_positions('0.3,-0.1  0.33,0.1') == [(0.3, -0.1), (0.33, 0.1)]
    assert parse_positions('') == []
    for bad in ('0.3', '0.3,x', '0.3,0.1,0.2', 'nan,0.1'):
        with pytest.raises(ValueError, match=r'can position .*expected x,y'):
            parse_positions('0.2,0.2 ' + bad)


def test_random_layouts_keep_the_rules_and_repeat_by_seed():
    rules = LayoutRules()
    for seed in range(100):
        cans = random_layout(3, seed)
        assert cans == random_layout(3, seed)
        assert len(cans) == 3
        for i, (x, y) in enumerate(cans):
            assert rules.min_range <= math.hypot(x, y) <= rules.max_range
            assert abs(math.atan2(y, x)) <= rules.max_bearing
            for (u, v) in cans[i + 1:]:
                assert math.hypot(x - u, y - v) >= rules.min_spacing
                gap = abs(math.remainder(math.atan2(y, x) - math.atan2(v, u), 2 * math.pi))
                assert gap >= rules.min_bearing_gap
    # Different seeds, different layouts.
    assert len({tuple(random_layout(3, s)) for s in range(20)}) == 20


def test_impossible_rules_say_so():
    with pytest.raises(ValueError, match='cannot place 12 cans'):
        random_layout(12, 1)
