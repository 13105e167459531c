"""Where the cans stand: parsed from the launch file's "x,y x,y ..." or drawn at random.

Random layouts are what the stacking benchmark runs on: cans the arm can take with a level
grasp and the laser can see, far enough apart that the open gripper passes between them, each
on its own line of sight from the base so that reaching one never sweeps through another.
"""
import dataclasses
import math
import random
from dataclasses import dataclass
from typing import List, Tuple


@dataclass(frozen=True)
class LayoutRules:
    # m from the base's axis. The Katana grasps a can and sets it on a tower two cans high at the
    # same pitch (the can hangs in the gripper as it was taken) only between about 0.34 and
    # 0.43 m: nearer, the elbow's limit (-2.22 rad) stops it reaching down; farther, up.
    # katana_pick's planner finds a grasp for every layout of 300 seeds within these.
    min_range: float = 0.34
    max_range: float = 0.42
    max_bearing: float = math.radians(70)  # the laser sees +-90 degrees; keep clear of its edges
    min_spacing: float = 0.15   # m between can axes: 2 radii + the open fingers + clearance
    min_bearing_gap: float = math.radians(25)  # between lines of sight from the base


def parse_positions(text: str) -> List[Tuple[float, float]]:
    """'0.3,-0.1 0.33,0.1' -> [(0.3, -0.1), (0.33, 0.1)]; ValueError naming the bad pair."""
    positions = []
    for pair in text.split():
        parts = pair.split(',')
        try:
            if len(parts) != 2:
                raise ValueError
            x, y = float(parts[0]), float(parts[1])
            if not (math.isfinite(x) and math.isfinite(y)):
                raise ValueError
        except ValueError:
            raise ValueError('can position %r: expected x,y in metres, e.g. 0.3,-0.1' % pair) from None
        positions.append((x, y))
    return positions


def parse_range(text: str, rules: LayoutRules) -> LayoutRules:
    """'0.32,0.46' -> rules drawing between those ranges (m); '' keeps rules; ValueError saying why."""
    if not text.strip():
        return rules
    try:
        low, high = (float(v) for v in text.split(','))
    except ValueError:
        raise ValueError('can range %r: expected min,max in metres, e.g. 0.32,0.46' % text) from None
    if not (math.isfinite(low) and math.isfinite(high) and 0.0 < low < high):
        raise ValueError('can range %r: expected 0 < min < max, both finite' % text)
    return dataclasses.replace(rules, min_range=low, max_range=high)


def fits(positions: List[Tuple[float, float]], x: float, y: float, rules: LayoutRules) -> bool:
    """Whether a can at (x, y) keeps the rules' spacing to every can in positions."""
    bearing = math.atan2(y, x)
    for px, py in positions:
        if math.hypot(px - x, py - y) < rules.min_spacing:
            return False
        if abs(math.remainder(math.atan2(py, px) - bearing, 2 * math.pi)) < rules.min_bearing_gap:
            return False
    return True


def random_layout(count: int, seed: int, rules: LayoutRules = LayoutRules()) -> List[Tuple[float, float]]:
    """count can positions drawn uniformly over the allowed area, each kept only if it fits the
    ones before; the same seed gives the same layout."""
    rng = random.Random(seed)
    for _ in range(1000):
        positions = []
        for _ in range(200 * count):
            if len(positions) == count:
                break
            # Uniform over the annulus sector: the radius by the square root of a uniform draw.
            r = math.sqrt(rng.uniform(rules.min_range ** 2, rules.max_range ** 2))
            bearing = rng.uniform(-rules.max_bearing, rules.max_bearing)
            x, y = r * math.cos(bearing), r * math.sin(bearing)
            if fits(positions, x, y, rules):
                positions.append((x, y))
        if len(positions) == count:
            return positions
    raise ValueError('cannot place %d cans by these rules: %s' % (count, rules))
