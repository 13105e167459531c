"""Where a tower may stand when no can's own spot takes all the cans (issue 38, item 2): a free
spot, to which the first can is carried and set on the table (level 0), the others on it.

The reach (reach.py) depends on a spot's range only: a tower nearer the base takes higher levels,
one farther out takes cans from farther out. So the ranges tried are those of a grid at which the
reach map puts the most cans in one tower (each can taken at its own range and set at its level,
levels 0 to n-1, the best order), and only if that beats every can's own spot by the map. The
bearings tried at each range: halfway between cans next to each other by bearing, and beside the
outermost ones, within the half of the table in front of the arm (where the laser sees it); a
spot must keep min_distance from every can, so that the open fingers about a can clear the
others. The planner (tower_choice.fits_by_plan) then decides, as for the cans' own spots.
"""
import itertools
import math
from typing import List, Sequence, Tuple

from katana_pick import arm_geometry
from katana_pick.arm_geometry import KatanaGeometry
from katana_pick.reach import ReachMap, reach_map
from katana_pick.stacking import StackingOptions
from katana_pick.tower_choice import MAX_CANS_FOR_EVERY_ORDER, placed

GRID_STEP = 0.01   # m between the ranges tried (the best band can be 2 cm wide)
BESIDE = 0.45      # rad past the outermost cans' bearings
NEARER = 0.10      # m: the nearest range tried, nearer the base than the nearest can


def tower_size(reach: ReachMap, can_ranges: Sequence[float], r_tower: float, on_table: bool) -> int:
    """The most cans one tower at range r_tower holds by the reach map, over every order: the cans
    at can_ranges carried to it (from level 0 if on_table, a free spot; else from level 1, the
    spot's own can counted)."""
    first = 0 if on_table else 1

    def fits(i, _tower, level):
        return reach.stackable(can_ranges[i], r_tower, level)
    return first + max(placed(order, 0, fits, first) for order in itertools.permutations(range(len(can_ranges))))


def free_spots(cans: Sequence[Tuple[float, float]], geometry: KatanaGeometry = KatanaGeometry(),
               options: StackingOptions = StackingOptions()) -> List[Tuple[float, float]]:
    """Free spots for a tower of the cans at (x, y), the most promising first; none when a can's
    own spot is as good by the reach map, and for more cans than tower_choice tries every order of."""
    if not 2 <= len(cans) <= MAX_CANS_FOR_EVERY_ORDER:
        return []
    can_ranges = [round(math.hypot(x, y), 6) for x, y in cans]
    # From a little nearer the base than the nearest can (levels reach higher there) to the
    # farthest can (a tower beyond every can takes no more of them) or the arm stretched out.
    near = max(min(can_ranges) - NEARER, options.retreat_distance + GRID_STEP)
    far = min(max(can_ranges), arm_geometry.reach(geometry))
    grid = [round(near + k * GRID_STEP, 6) for k in range(int((far - near) / GRID_STEP) + 1)]
    reach = reach_map(geometry, sorted(set(grid + can_ranges)), max_level=len(cans) - 1, stacking=options)
    own = max(tower_size(reach, [r for j, r in enumerate(can_ranges) if j != t], can_ranges[t], False)
              for t in range(len(cans)))
    sizes = {r: tower_size(reach, can_ranges, r, True) for r in grid}
    most = max(sizes.values(), default=0)
    if most <= own:
        return []
    bearings = sorted(math.atan2(y, x) for x, y in cans)
    tried = [(a + b) / 2 for a, b in zip(bearings, bearings[1:])] + [bearings[0] - BESIDE, bearings[-1] + BESIDE]
    tried = [b for b in tried if abs(b) <= math.pi / 2]
    clear = 2 * options.can_radius + options.spot_gap
    spots = [(r * math.cos(b), r * math.sin(b)) for r in grid if sizes[r] == most for b in tried]
    spots = [s for s in spots if all(math.dist(s, c) >= clear for c in cans)]
    # Nearest the cans first: the shortest carries.
    return sorted(spots, key=lambda s: sum(math.dist(s, c) for c in cans))
