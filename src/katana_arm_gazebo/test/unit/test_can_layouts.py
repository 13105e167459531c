"""Can layouts: the launch file's x,y pairs, and seeded random layouts that keep the rules."""
import math
import os
import sys

import pytest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..', 'src'))
from katana_arm_gazebo.can_layouts import LayoutRules, parse_positions, parse_range, random_layout  # noqa: E402


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


def test_a_range_given_draws_four_cans_over_it():
    rules = parse_range('0.32,0.46', LayoutRules())
    assert (rules.min_range, rules.max_range) == (0.32, 0.46)
    assert parse_range(' ', LayoutRules()) == LayoutRules()
    ranges = [math.hypot(x, y) for seed in range(200) for x, y in random_layout(4, seed, rules)]
    assert 0.32 <= min(ranges) < 0.33 and 0.45 < max(ranges) <= 0.46  # the whole band is drawn from
    for bad, why in (('0.46,0.32', 'expected 0 < min < max'), ('0.3', 'expected min,max'), ('a,b', 'expected min,max'),
                     ('0,0.4', 'expected 0 < min < max'), ('0.3,inf', 'expected 0 < min < max')):
        with pytest.raises(ValueError, match=r"can range '%s': %s" % (bad, why)):
            parse_range(bad, LayoutRules())


def test_impossible_rules_say_so():
    with pytest.raises(ValueError, match='cannot place 12 cans'):
        random_layout(12, 1)
