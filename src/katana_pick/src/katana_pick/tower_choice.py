"""Which can the others are stacked on, and in which order, so that the most cans end in the tower.

The tower's level rises as cans go on it, and the arm's reach shrinks with it (docs/KATANA.md,
"The arm's reach"): which can goes to which level matters as much as where the tower stands. Every
can's spot is tried as the tower and every order of the others, each scored by how many cans go
on: can i goes to level L (the cans already on the tower, plus one) if fits(i, tower, L), and a
can that does not fit is skipped, the tower growing only by those that do (as stack_cans runs a
plan). Any can may be the tower, even one the arm cannot take. Ties keep the tutorial's choice:
the middle can by bearing of those the arm can take as the tower (stacking.choose_tower), the
nearest cans first (stacking.pick_order). Where no can's spot takes them all, a free spot
(free_spots.py) may: the first can is carried there and set on the table, the others on it.
"""
import functools
import itertools
from typing import Callable, List, Sequence, Tuple

from katana_pick.arm_geometry import KatanaGeometry
from katana_pick.stacking import StackingOptions, choose_tower, pick_order
from katana_pick.trajectories import PlanError, TimingOptions, plan_can_from_here

# Above this many cans only the tutorial's order is scored for each tower: 8 cans would be 40320
# orders a tower.
MAX_CANS_FOR_EVERY_ORDER = 7


def placed(order: Sequence[int], tower: int, fits: Callable[[int, int, int], bool], first_level: int = 1) -> int:
    """How many of the cans in `order` go onto the tower, each to the level above the last that
    did, the first to first_level (0 on a free spot: onto the table)."""
    level = first_level
    for i in order:
        if fits(i, tower, level):
            level += 1
    return level - first_level


def in_tower(n: int, tower: int, order: Sequence[int], fits: Callable[[int, int, int], bool]) -> int:
    """How many of the n cans end in the tower: those the order puts on it, and the tower's own
    can when it stands on a can's spot (tower < n)."""
    own = tower < n
    return placed(order, tower, fits, 1 if own else 0) + (1 if own else 0)


def choose_stack(cans: Sequence[Tuple[float, float]], fits: Callable[[int, int, int], bool],
                 free: Sequence[Tuple[float, float]] = ()) -> Tuple[int, List[int]]:
    """The tower and the order the cans go to it in. The tower is an index into cans + free: a
    can's own spot (that can stays; the order holds the others) or a free spot (the order's first
    can is set there on the table, level 0; free_spots.py), tried after the cans' spots and taken
    only when it holds more cans. fits(i, tower, level): whether can i can be set `level` cans
    high on the tower at that spot."""
    n = len(cans)
    # The tutorial's tower is the middle one of the cans the arm can take: one it cannot move (too
    # far or too near) is a tower only when that puts more cans on.
    movable = [i for i in range(n) if any(fits(i, t, 1) for t in range(n) if t != i)]
    preferred = movable[choose_tower([cans[i] for i in movable])] if movable else choose_tower(cans)
    best = None
    towers = [preferred] + [t for t in range(n) if t != preferred] + list(range(n, n + len(free)))
    for tower in towers:
        own = tower < n
        spot = cans[tower] if own else free[tower - n]
        nearest_first = pick_order(list(cans) + [spot], n) if not own else pick_order(cans, tower)
        orders = itertools.permutations(nearest_first) if n <= MAX_CANS_FOR_EVERY_ORDER else [nearest_first]
        for order in orders:
            count = in_tower(n, tower, order, fits)
            if best is None or count > best[0]:
                best = (count, tower, list(order))
            if count == n:
                return tower, list(order)
    return best[1], best[2]


def fits_by_plan(geometry: KatanaGeometry, q_start: Sequence[float], cans: Sequence[Tuple[float, float]],
                 also_standing: Sequence[Tuple[float, float]] = (), options: StackingOptions = StackingOptions(),
                 timing: TimingOptions = TimingOptions(),
                 free: Sequence[Tuple[float, float]] = ()) -> Callable[[int, int, int], bool]:
    """choose_stack's fits, remembered: whether plan_can_from_here finds a plan from q_start for
    cans[i] onto a tower `level` high at (cans + free)[tower], past every other can counted as
    standing (those of cans and also_standing, cans the arm does not reach). From here, as
    stack_cans plans each can, not plan_can: a tower two cans high may stand where the arm is at
    q_start (stretched out, its wrist 0.2 m up), and only a first move away from it leaves it."""
    towers = list(cans) + list(free)

    @functools.lru_cache(maxsize=None)
    def fits(i, tower, level):
        standing = [c for k, c in enumerate(cans) if k not in (i, tower)] + list(also_standing)
        try:
            plan_can_from_here(geometry, q_start, cans[i], towers[tower], level, options, timing, standing)
            return True
        except PlanError:
            return False
    return fits
