"""The tutorial's pick-and-stack as a plan: which can is the tower, the order of the others, and
for each can the gripper's moves through the tutorial's via points.

The tutorial's recipe, made concrete: approach a can along the line from the arm's base to it,
from a point approach_distance short of it; close the gripper; lift it off, carry it above the
tower's top, lower it onto the tower; open; back away along the line to the base and rise (ours,
where the arm reaches). The
moves near the cans are straight lines (cylindrical interpolation about the base's axis: radial
and vertical moves stay on their line); the moves through the air interpolate the joints, which
keeps them within the joint limits where a straight line near the base would not. The IK
(trajectories.py) turns them into joint trajectories and picks the grasp height and the pitch.

All positions are in katana_base_link, whose z = 0 is the surface the arm and the cans stand on.
"""
import math
from dataclasses import dataclass
from typing import List, Optional, Sequence, Tuple, Union


@dataclass(frozen=True)
class StackingOptions:
    can_height: float = 0.12          # m, the tutorial's cans
    can_radius: float = 0.033
    # Tool frame heights above a can's bottom to grasp it at, in order of preference: halfway up
    # first; higher up brings cans nearer the base within reach.
    grasp_heights: Tuple[float, ...] = (0.06, 0.08, 0.10)
    approach_distance: float = 0.07   # m: the open fingertips (0.023 m past the tool frame) clear the can
    # m back from the tower after letting go: far enough that no part of the open gripper is over
    # the tower when the arm turns to the next can (0.033 + 0.023 m, and room for the joint-space
    # move's bulge).
    retreat_distance: float = 0.10
    lift: float = 0.03                # m straight up after the grasp, and down onto the tower
    clearance: float = 0.04           # m between a carried can and what it passes over
    place_gap: float = 0.005          # m above the tower's top where the can is let go
    # m from the end of a move that sets the can down (Move.lands) within which the tool counts
    # as there when the controller reports the goal missed: the tower's top, met by a can held a
    # few degrees askew, holds the arm up or twists the weak wrist roll (upstream's P of 0.1).
    landing_tolerance: float = 0.01
    open_position: float = 0.30       # finger angles (rad), katana_driver's open and closed
    close_position: float = -0.44
    # The gripper's pitch is searched between these (rad), one for the whole of a can's move: the
    # can hangs in the gripper as it was grasped, so it must be let go at the pitch it was taken.
    min_pitch: float = -0.84          # steeper, the finger hinges (0.057 m behind the tool frame,
    max_pitch: float = 0.3            # 0.03 m off its axis) would come down onto the can's rim
    pitch_step: float = 0.05
    # When no grasp above makes today's moves, every grasp height from min_grasp_height up and
    # lower carries (clearance.py checks what they pass over) are tried: the arm's whole reach.
    min_grasp_height: float = 0.04    # the fingertips stay above the table at min_pitch
    grasp_height_step: float = 0.01
    carry_step: float = 0.02          # m between the carry heights tried
    # m between a free spot's can and any other can (free_spots.py): the open fingers round the
    # can they grasp reach 0.058 m from its axis (clearance.OpenFingers).
    spot_gap: float = 0.08


@dataclass(frozen=True)
class ToolPose:
    """The tool frame at (x, y, z) with the gripper's pitch (katana_ik's convention)."""
    x: float
    y: float
    z: float
    pitch: float

    @property
    def radius(self):
        return math.hypot(self.x, self.y)

    @property
    def bearing(self):
        return math.atan2(self.y, self.x)


@dataclass(frozen=True)
class Move:
    """To these tool poses, in order, from wherever the tool is: along straight lines (line) or
    with the joints interpolated (free moves through the air, which keep clear of the joint
    limits where a straight line may not). holding: a can is in the gripper, so the arm keeps the
    side of its base it took the can on (katana_ik.is_flipped): leaning over to the other side
    turns the gripper half a turn about its axis, and a can held at a pitch with it."""
    what: str
    poses: Tuple[ToolPose, ...]
    line: bool = True
    holding: bool = False
    # A straight move that goes as far along its line as the arm reaches, and not at all if it
    # reaches nothing of it (the rise after backing away: near the base the elbow's limit may stop it).
    as_far_as_reachable: bool = False
    # The held can comes down onto something at the end (the tower): touching it there is the can
    # set down, not a failure, when the tool ends within StackingOptions.landing_tolerance.
    lands: bool = False


@dataclass(frozen=True)
class Grip:
    """The fingers to position; hold: whether a can should end up between them."""
    what: str
    position: float
    hold: bool


Step = Union[Move, Grip]


def _on_line(x, y, shorter_by, z, pitch):
    """The point shorter_by nearer the base than (x, y) on the line from the base, at height z."""
    r = math.hypot(x, y)
    scale = (r - shorter_by) / r
    return ToolPose(x * scale, y * scale, z, pitch)


def choose_tower(cans: Sequence[Tuple[float, float]]) -> int:
    """The can the others are stacked on: the middle one by bearing, so that the others are
    carried in from either side and no approach passes the tower."""
    by_bearing = sorted(range(len(cans)), key=lambda i: math.atan2(cans[i][1], cans[i][0]))
    return by_bearing[(len(cans) - 1) // 2]


def pick_order(cans: Sequence[Tuple[float, float]], tower: int) -> List[int]:
    """The other cans, nearest the tower first (the shortest carries)."""
    tx, ty = cans[tower]
    others = [i for i in range(len(cans)) if i != tower]
    return sorted(others, key=lambda i: math.hypot(cans[i][0] - tx, cans[i][1] - ty))


def carry_height(level: int, grasp_height: float, options: StackingOptions) -> float:
    """The tool's height when carrying the can that goes to `level`: its bottom clears the
    tower's top (level cans) and every can on the table (one can high)."""
    return max(level, 1) * options.can_height + grasp_height + options.clearance


def can_steps(can: Tuple[float, float], tower: Tuple[float, float], level: int, grasp_height: float,
              pitch: float, options: StackingOptions = StackingOptions(),
              approach_height: Optional[float] = None,
              carry_heights: Optional[Tuple[float, float]] = None) -> List[Step]:
    """The steps that take the can standing at `can` to the top of the tower (`level` cans high;
    0: onto the table) standing at `tower`, grasped grasp_height above its bottom with the
    gripper at `pitch`.

    The moves through the air go high enough to clear every can and the tower (carry_height)
    unless given lower: approach_height, the tool's height above the approach point before it
    comes down to it; carry_heights, the tool's height over the can after lifting it and over the
    tower before coming down onto it (at least the lift's and the place's; one straight joint-space
    move between them). Lower ones reach farther; clearance.py says whether they clear."""
    o = options
    x, y = can
    tx, ty = tower
    high = carry_height(level, grasp_height, o)
    grasp = ToolPose(x, y, grasp_height, pitch)
    before = _on_line(x, y, o.approach_distance, grasp_height, pitch)
    place_z = level * o.can_height + o.place_gap + grasp_height
    place = ToolPose(tx, ty, place_z, pitch)
    away = _on_line(tx, ty, o.retreat_distance, place_z, pitch)
    above_can, above_tower = carry_heights if carry_heights is not None else (high, high)
    lifted_z = grasp_height + o.lift
    carry = (ToolPose(x, y, max(above_can, lifted_z), pitch), ToolPose(tx, ty, max(above_tower, place_z + o.lift), pitch))
    if carry[1].z > place_z + o.lift:
        carry += (ToolPose(tx, ty, place_z + o.lift, pitch),)
    return [
        Grip('open before the approach', o.open_position, hold=False),
        Move('over to the approach point', (ToolPose(before.x, before.y, high if approach_height is None
                                                     else max(approach_height, grasp_height), pitch),
                                             before), line=False),
        Move('in along the line from the base', (grasp,)),
        Grip('close on the can', o.close_position, hold=True),
        Move('lift off', (ToolPose(x, y, lifted_z, pitch),), holding=True),
        Move('carry over the tower', carry, line=False, holding=True),
        Move('lower onto the tower', (place,), holding=True, lands=True),
        Grip('let go', o.open_position, hold=False),
        Move('back away towards the base', (away,)),
        # Not the tutorial's (it backs away, then goes on to the next can): the open fingers higher
        # above the tower before the move through the air, where the arm reaches.
        Move('rise', (ToolPose(away.x, away.y, place_z + 2 * o.lift, pitch),), as_far_as_reachable=True),
    ]


def grasp_heights_all(options: StackingOptions) -> List[float]:
    """Every grasp height from options.min_grasp_height to the highest of options.grasp_heights."""
    top = max(options.grasp_heights)
    n = int(round((top - options.min_grasp_height) / options.grasp_height_step))
    return [round(options.min_grasp_height + k * options.grasp_height_step, 6) for k in range(n + 1)]


def heights_down(high: float, low: float, step: float) -> List[float]:
    """high, then every `step` lower down to low (included)."""
    n = max(0, int(math.ceil((high - low) / step - 1e-9)))
    return [max(high - k * step, low) for k in range(n + 1)]


def pitches(options: StackingOptions) -> List[float]:
    """The pitches to try, level first, then alternately steeper and shallower, pitch_step apart
    and never past min_pitch or max_pitch (the last step to a limit may be shorter)."""
    n_down = int(math.ceil(-options.min_pitch / options.pitch_step - 1e-9))
    n_up = int(math.ceil(options.max_pitch / options.pitch_step - 1e-9))
    found = [0.0]
    for k in range(1, max(n_down, n_up) + 1):
        if k <= n_down:
            found.append(max(-k * options.pitch_step, options.min_pitch))
        if k <= n_up:
            found.append(min(k * options.pitch_step, options.max_pitch))
    return found


def interpolate(start: ToolPose, end: ToolPose, step: float) -> List[ToolPose]:
    """Poses from start (excluded) to end (included) no more than about `step` metres apart,
    interpolated in cylindrical coordinates about the base's axis: a move along a line from the
    base or straight up stays on it, a carry at one height is an arc at that height."""
    r0, r1 = start.radius, end.radius
    b0 = start.bearing
    db = math.remainder(end.bearing - b0, 2 * math.pi)
    # The length of the path, the arc counted at the larger radius.
    length = math.sqrt((r1 - r0) ** 2 + (end.z - start.z) ** 2 + (max(r0, r1) * db) ** 2)
    n = max(1, int(math.ceil(length / step)))
    poses = []
    for k in range(1, n + 1):
        s = k / n
        r = r0 + s * (r1 - r0)
        b = b0 + s * db
        poses.append(ToolPose(r * math.cos(b), r * math.sin(b), start.z + s * (end.z - start.z),
                              start.pitch + s * (end.pitch - start.pitch)))
    return poses
