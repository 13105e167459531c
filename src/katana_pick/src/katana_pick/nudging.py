"""Nudging (issue 38, item 2): a can standing nearer the base than any grasp takes it (reach.py:
nearer than about 0.32 m the elbow's limit stops the forearm folding back) is slid outward along
the line from the base until it stands where the arm takes it.

The pusher is the closed fingers pointing steeply down: open, pointing down, they span about
0.1 m, wider than a can, which would pass between them; closed they are one narrow pusher. Only
pointing down does the arm reach behind a can that near (down to about 0.22 m from the base).
The push is low on the can, the fingertips `tip_height` above the table, so the can slides
rather than tips (pushed at height h it tips only when mu * h > its radius: above 0.066 m for the
simulation's mu 0.5), and along the line through its axis, so that it does not slide off sideways.

The moves: the fingers closed, over the point behind the can (a joint-space move, checked for
clearance), straight down to it, the push outward (a straight line), back from the can a little
and up. The can is looked for again afterwards: where a push leaves it is not certain.
"""
import math
from dataclasses import dataclass
from typing import List, Sequence, Tuple

from katana_pick.arm_geometry import KatanaGeometry
from katana_pick.clearance import Held, Obstacle, path_conflict
from katana_pick.stacking import Grip, Move, StackingOptions, Step, ToolPose
from katana_pick.trajectories import JointPath, PlanError, TimingOptions, plan_moves


@dataclass(frozen=True)
class NudgeOptions:
    tip_height: float = 0.025     # m above the table: the fingertips while pushing
    tip_length: float = 0.023     # m from the tool frame to the fingertips, along the gripper's axis
    finger_half_width: float = 0.007  # m: the closed fingers' face ahead of their axis
    start_gap: float = 0.02       # m between the fingers and the can before the push
    beyond: float = 0.02          # m past the nearest range a grasp takes a can at: well inside
    clear_of_others: float = 0.01  # m between the pushed can and every other, all along the push
    back: float = 0.03            # m back from the can after the push, before going up
    up: float = 0.12              # m up from there: above every can standing
    steepest: float = -math.pi / 2  # rad: straight down
    shallowest: float = -0.9      # rad: shallower, the gripper's body reaches the table before its tips
    pitch_step: float = 0.05


def nudge_target(can: Tuple[float, float], near: float, nudge: NudgeOptions = NudgeOptions()) -> Tuple[float, float]:
    """Where the can at (x, y) is pushed to: on its line from the base, `beyond` past `near`, the
    nearest range at which a grasp takes a can."""
    r = math.hypot(*can)
    scale = (near + nudge.beyond) / r
    return can[0] * scale, can[1] * scale


def _blocked_by(can, target, others, radius, margin):
    """The first can in `others` that the can sliding from `can` to `target` would touch, or None."""
    (x0, y0), (x1, y1) = can, target
    length2 = (x1 - x0) ** 2 + (y1 - y0) ** 2
    for o in others:
        s = 0.0 if length2 == 0 else max(0.0, min(1.0, ((o[0] - x0) * (x1 - x0) + (o[1] - y0) * (y1 - y0)) / length2))
        if math.dist(o, (x0 + s * (x1 - x0), y0 + s * (y1 - y0))) < 2 * radius + margin:
            return o
    return None


def nudge_steps(can: Tuple[float, float], target: Tuple[float, float], pitch: float,
                options: StackingOptions = StackingOptions(), nudge: NudgeOptions = NudgeOptions()) -> List[Step]:
    """The steps that push the can at `can` to `target` (on its line from the base) with the
    closed fingers at `pitch` (pointing down: near -pi/2)."""
    r, r_target = math.hypot(*can), math.hypot(*target)
    ux, uy = can[0] / r, can[1] / r
    # The tool frame is tip_length behind the fingertips along the gripper's axis.
    dr, dz = -nudge.tip_length * math.cos(pitch), -nudge.tip_length * math.sin(pitch)
    z = nudge.tip_height + dz

    def at(tip_range, height):
        return ToolPose(ux * (tip_range + dr), uy * (tip_range + dr), height, pitch)
    face = r - options.can_radius - nudge.finger_half_width  # the fingertips touching the can
    start, end = face - nudge.start_gap, face + (r_target - r)
    return [
        Grip('close to push', options.close_position, hold=False),
        Move('over the point behind the can', (at(start, z + nudge.up),), line=False),
        Move('down behind the can', (at(start, z),)),
        Move('push the can outward along the line from the base', (at(end, z),)),
        Move('back from the can', (at(end - nudge.back, z),)),
        Move('up, clear of the can', (at(end - nudge.back, z + nudge.up),), as_far_as_reachable=True),
    ]


def plan_nudge(geometry: KatanaGeometry, q_start: Sequence[float], can: Tuple[float, float], near: float,
               others: Sequence[Tuple[float, float]] = (), options: StackingOptions = StackingOptions(),
               timing: TimingOptions = TimingOptions(),
               nudge: NudgeOptions = NudgeOptions()) -> Tuple[Tuple[float, float], List[Step], List[JointPath]]:
    """Where the can goes, the steps and their joint paths, at the middle of the pitches that
    make every move (the most room to the joint limits); PlanError, saying why, if the can would
    slide into another, or no pitch reaches."""
    target = nudge_target(can, near, nudge)
    blocker = _blocked_by(can, target, others, options.can_radius, nudge.clear_of_others)
    if blocker is not None:
        raise PlanError('pushed to (%.3f, %.3f) it would touch the can at (%.3f, %.3f)' % (target + blocker))
    obstacles = [Obstacle(x, y, options.can_height, options.can_radius) for x, y in others]
    fingers = Held(nudge.tip_length + nudge.finger_half_width, nudge.finger_half_width)
    n = int(math.floor((nudge.shallowest - nudge.steepest) / nudge.pitch_step + 1e-9))
    feasible, why = [], None
    for k in range(n + 1):
        pitch = nudge.steepest + k * nudge.pitch_step
        steps = nudge_steps(can, target, pitch, options, nudge)
        moves = [s for s in steps if isinstance(s, Move)]
        try:
            paths = plan_moves(geometry, q_start, moves, timing=timing)
        except PlanError as e:
            why = why or e
            continue
        conflict = path_conflict(geometry, (tuple(q_start),) + paths[0].positions, fingers, obstacles)
        if conflict is not None:
            why = why or PlanError('%s: %s' % (moves[0].what, conflict))
            continue
        feasible.append((steps, paths))
    if not feasible:
        raise PlanError('no pitch from %.2f to %.2f rad pushes it (%s)' % (nudge.steepest, nudge.shallowest, why))
    steps, paths = feasible[len(feasible) // 2]
    return target, steps, paths
