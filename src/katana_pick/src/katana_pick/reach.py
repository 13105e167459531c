"""Where the arm can take a can and where it can set one on a tower, computed from the arm's
dimensions and joint limits (arm_geometry: read from the URDF), over every grasp the gripper can
hold a can by: the tool frame's height up the can, the gripper's pitch (the planner's pitches),
and whichever IK branch (elbow up or down, shoulder flipped or not) reaches each pose.

The tutorial's method fixes what taking and placing need (stacking.can_steps): to take a can
standing at range r, the tool comes in along the line from the base from r - approach_distance
to r at the grasp height, then lifts straight up by `lift`; to place one on a tower at range r,
`level` cans high, it comes down from `lift` above the place height to it, then backs away
towards the base by retreat_distance. Each of those straight moves must be reachable all along
(checked every `step`, as the planner cuts them), at one pitch: the can hangs in the gripper as
it was grasped. A can at r_can goes onto a tower at r_tower at `level` when one grasp does both.

Ranges only: the pan joint turns the arm to any bearing the laser sees (its limits span more
than a full turn less 0.4 rad, centred ahead), so reach does not depend on bearing there.
"""
import math
from dataclasses import dataclass
from typing import Dict, List, Sequence, Tuple

from katana_pick import arm_geometry, katana_ik
from katana_pick.arm_geometry import KatanaGeometry
from katana_pick.stacking import StackingOptions, pitches


@dataclass(frozen=True)
class Grasp:
    height: float  # m, the tool frame above the can's bottom
    pitch: float   # rad, katana_ik's convention


@dataclass(frozen=True)
class ReachOptions:
    # Grasp heights: from low enough that the fingertips (0.023 m past the tool frame, pitched
    # down at most min_pitch) stay above the table, to the can's top less the fingers' half width.
    min_height: float = 0.04
    max_height: float = 0.10
    height_step: float = 0.01
    step: float = 0.01      # m between checked points of a straight move (the planner's)


def grasps(stacking: StackingOptions = StackingOptions(), options: ReachOptions = ReachOptions()) -> List[Grasp]:
    """Every grasp considered: the heights and pitches of the gripper's whole range."""
    n_h = int(round((options.max_height - options.min_height) / options.height_step))
    # The planner's pitches (stacking.pitches), so that what the map allows the planner tries.
    return [Grasp(round(options.min_height + i * options.height_step, 6), round(p, 6))
            for i in range(n_h + 1) for p in sorted(pitches(stacking))]


def pose_reachable(geometry: KatanaGeometry, r: float, z: float, pitch: float) -> bool:
    """Whether some IK branch within the joint limits puts the tool at range r, height z, pitch."""
    return bool(katana_ik.solutions(geometry, r, 0.0, z, pitch))


def _line_reachable(geometry, start, end, pitch, step):
    """Every point of the straight move from (r, z) `start` to `end`, `step` apart, reachable."""
    n = max(1, int(math.ceil(math.hypot(end[0] - start[0], end[1] - start[1]) / step)))
    return all(pose_reachable(geometry, start[0] + (end[0] - start[0]) * k / n, start[1] + (end[1] - start[1]) * k / n,
                              pitch) for k in range(n + 1))


def can_take(geometry: KatanaGeometry, r: float, grasp: Grasp, stacking: StackingOptions = StackingOptions(),
             options: ReachOptions = ReachOptions()) -> bool:
    """In along the line from the base to the can at range r, then straight up off the table."""
    h, p = grasp.height, grasp.pitch
    return (r - stacking.approach_distance > 0
            and _line_reachable(geometry, (r - stacking.approach_distance, h), (r, h), p, options.step)
            and _line_reachable(geometry, (r, h), (r, h + stacking.lift), p, options.step))


def can_place(geometry: KatanaGeometry, r: float, level: int, grasp: Grasp,
              stacking: StackingOptions = StackingOptions(), options: ReachOptions = ReachOptions()) -> bool:
    """Down onto a tower `level` cans high at range r (0: onto the table), then back towards the
    base."""
    h, p = grasp.height, grasp.pitch
    z = level * stacking.can_height + stacking.place_gap + h
    return (r - stacking.retreat_distance > 0
            and _line_reachable(geometry, (r, z + stacking.lift), (r, z), p, options.step)
            and _line_reachable(geometry, (r, z), (r - stacking.retreat_distance, z), p, options.step))


@dataclass(frozen=True)
class ReachMap:
    """For each range of a grid: the grasps that take a can there, and for each level the grasps
    that place a can there (level 0: on the table, where a tower's first can is moved to)."""
    radii: Tuple[float, ...]
    take: Dict[float, Tuple[Grasp, ...]]
    place: Dict[Tuple[float, int], Tuple[Grasp, ...]]
    max_level: int

    def stackable(self, r_can: float, r_tower: float, level: int) -> List[Grasp]:
        """The grasps that take a can at r_can (a grid range) and set it `level` high at r_tower."""
        placing = set(self.place.get((round(r_tower, 6), level), ()))
        return [g for g in self.take.get(round(r_can, 6), ()) if g in placing]

    def take_range(self) -> Tuple[float, float]:
        """The nearest and farthest grid ranges at which some grasp takes a can."""
        taken = [r for r in self.radii if self.take[r]]
        return (min(taken), max(taken)) if taken else (math.nan, math.nan)

    def highest_own_spot_level(self, r: float) -> int:
        """The highest level a tower standing at r can be built to with cans taken at r: the
        level a can taken from the same range is placed at (0: it cannot be taken)."""
        return max([level for level in range(1, self.max_level + 1) if self.stackable(r, r, level)], default=0)


def reach_map(geometry: KatanaGeometry, radii: Sequence[float], max_level: int = 5,
              stacking: StackingOptions = StackingOptions(), options: ReachOptions = ReachOptions()) -> ReachMap:
    """The reach over a grid of ranges and levels 0..max_level, for every grasp."""
    all_grasps = grasps(stacking, options)
    radii = tuple(round(r, 6) for r in radii)
    take = {r: tuple(g for g in all_grasps if can_take(geometry, r, g, stacking, options)) for r in radii}
    place = {(r, level): tuple(g for g in all_grasps if can_place(geometry, r, level, g, stacking, options))
             for r in radii for level in range(0, max_level + 1)}
    return ReachMap(radii, take, place, max_level)


def taking_range(geometry: KatanaGeometry, stacking: StackingOptions = StackingOptions(),
                 step: float = 0.005) -> Tuple[float, float]:
    """The nearest and farthest ranges, on a `step` grid, at which some grasp takes a can: from
    the base's axis out past the arm stretched out (arm_geometry.reach)."""
    radii = [round(k * step, 6) for k in range(1, int(arm_geometry.reach(geometry) / step) + 2)]
    return reach_map(geometry, radii, max_level=0, stacking=stacking).take_range()
