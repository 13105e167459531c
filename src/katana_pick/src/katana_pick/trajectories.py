"""A Move of the stacking plan as joint-space via points with times, for a
control_msgs/FollowJointTrajectory goal.

The tool path is cut into points about `step` apart (stacking.interpolate) and each is solved by
the triangle IK seeded with the one before, so the arm stays on one branch and the joints move
little between points; a point's time is set by whichever is slower, the tool at tool_speed or
the fastest joint at joint_speed. The last point is repeated `settle` seconds later: upstream's
controller only has P and D terms and must be within 0.02 rad of the goal 0.6 s after the end.
"""
import math
from dataclasses import dataclass, replace
from typing import List, Optional, Sequence, Tuple

from katana_pick import katana_ik
from katana_pick.arm_geometry import KatanaGeometry
from katana_pick.clearance import Held, OpenFingers, path_conflict, tower_and_cans
from katana_pick.stacking import (Move, StackingOptions, Step, ToolPose, can_steps, carry_height, grasp_heights_all,
                                  heights_down, interpolate, pitches)


@dataclass(frozen=True)
class TimingOptions:
    step: float = 0.01          # m between via points
    tool_speed: float = 0.08    # m/s
    joint_speed: float = 0.6    # rad/s, for the joint that moves most
    min_interval: float = 0.02  # s between points
    settle: float = 1.5         # s the last point is held at the end


class PlanError(ValueError):
    """A move the arm cannot make; the message names the move and why. approach_blocked: whether
    some grasp was refused only because the open fingers' way from the arm's joints to its
    approach point passed too close to a can or the tower, the one refusal that a first move
    elsewhere can lift (plan_can_from_here)."""

    def __init__(self, message, approach_blocked=False):
        super().__init__(message)
        self.approach_blocked = approach_blocked


@dataclass(frozen=True)
class JointPath:
    times: Tuple[float, ...]                 # s from the start of the move
    positions: Tuple[Tuple[float, ...], ...]  # the five arm joints at each time
    end: ToolPose                            # where the tool is at the end


def tool_pose(geometry: KatanaGeometry, q: Sequence[float]) -> ToolPose:
    x, y, z, pitch = katana_ik.forward(geometry, q)
    return ToolPose(x, y, z, pitch)


def landed(geometry: KatanaGeometry, q_now: Sequence[float], path: JointPath, tolerance: float) -> bool:
    """Whether the tool at joints q_now is within tolerance (m) of where path ends: a move onto
    the tower the controller called failed may still have set the can down."""
    now = tool_pose(geometry, q_now)
    return math.dist((now.x, now.y, now.z), (path.end.x, path.end.y, path.end.z)) <= tolerance


def joint_path(geometry: KatanaGeometry, q_start: Sequence[float], move: Move, roll: float = 0.0,
               timing: TimingOptions = TimingOptions()) -> JointPath:
    """The move from the arm's joints q_start, as timed via points; PlanError if a point is out
    of reach or out of the joint limits (a move as_far_as_reachable stops at the last point before it)."""
    pose = tool_pose(geometry, q_start)
    q_prev = tuple(q_start)
    side = katana_ik.is_flipped(geometry, q_start) if move.holding else None
    times, positions, t = [], [], 0.0
    stopped = False
    for target in move.poses:
        # A free move goes to each pose in one joint-space segment: the controller interpolates.
        for p in interpolate(pose, target, timing.step) if move.line else (target,):
            try:
                q = katana_ik.solve(geometry, p.x, p.y, p.z, p.pitch, seed=q_prev, roll=roll, flipped=side)
            except katana_ik.IkError as e:
                if not (move.as_far_as_reachable and move.line):
                    raise PlanError('%s: %s' % (move.what, e)) from None
                stopped = True
                break
            travel = math.sqrt((p.x - pose.x) ** 2 + (p.y - pose.y) ** 2 + (p.z - pose.z) ** 2)
            turn = max(abs(a - b) for a, b in zip(q, q_prev))
            t += max(travel / timing.tool_speed, turn / timing.joint_speed, timing.min_interval)
            times.append(t)
            positions.append(q)
            pose, q_prev = p, q
        if stopped:
            break
    if not positions:  # nothing to move (a move as_far_as_reachable that reaches none of its line)
        positions.append(tuple(q_start))
        times.append(timing.min_interval)
        t = timing.min_interval
    times.append(t + timing.settle)
    positions.append(positions[-1])
    return JointPath(tuple(times), tuple(positions), pose)


def plan_moves(geometry: KatanaGeometry, q_start: Sequence[float], moves: Sequence[Move],
               roll: float = 0.0, timing: TimingOptions = TimingOptions()) -> List[JointPath]:
    """joint_path for each move in turn, each starting where the one before ends: solving all of
    a can's moves before the first is sent tells an unreachable can before it is touched."""
    paths, q = [], tuple(q_start)
    for move in moves:
        path = joint_path(geometry, q, move, roll, timing)
        paths.append(path)
        q = path.positions[-1]
    return paths


def plan_can(geometry: KatanaGeometry, q_start: Sequence[float], can, tower, level: int,
             options: StackingOptions = StackingOptions(), roll: float = 0.0,
             timing: TimingOptions = TimingOptions(),
             standing: Sequence[Tuple[float, float]] = ()) -> Tuple[List[Step], List[JointPath]]:
    """The steps for one can (stacking.can_steps) and the joint paths of their moves; PlanError if
    no grasp makes them.

    First as the tutorial's moves go, high over everything: at the first of options.grasp_heights
    for which some pitch makes every move reachable, at the middle one of those pitches (the most
    room to the joint limits). Where that finds nothing (far or high places, near cans), over the
    arm's whole reach: every grasp height from options.min_grasp_height, the approach and the
    carry as high as the arm reaches. In both, the moves through the air are checked (clearance.py)
    against the tower and the cans in `standing`, those on the table besides this one and the
    tower's."""
    obstacles = tower_and_cans(tower, level, standing, options.can_height, options.can_radius)
    why_not, blocked = None, False
    for whole_reach in (False, True):
        for height in grasp_heights_all(options) if whole_reach else options.grasp_heights:
            feasible = []
            for pitch in sorted(pitches(options)):
                try:
                    if whole_reach:
                        feasible.append(_plan_lower(geometry, q_start, can, tower, level, height, pitch, obstacles,
                                                    options, roll, timing))
                    else:
                        steps = can_steps(can, tower, level, height, pitch, options)
                        paths = plan_moves(geometry, q_start, [s for s in steps if isinstance(s, Move)], roll, timing)
                        _check_clear(geometry, q_start, steps, paths, height, obstacles, options)
                        feasible.append((steps, paths))
                except PlanError as e:
                    blocked = blocked or e.approach_blocked
                    if why_not is None or pitch == 0.0 and height == options.grasp_heights[0] and not whole_reach:
                        why_not = 'grasped %.2f m up with the gripper level: %s' % (height, e)
            if feasible:
                return feasible[len(feasible) // 2]
    raise PlanError('no grasp %.2f-%.2f m up with a pitch in [%.2f, %.2f] rad reaches it (%s)' % (
        options.min_grasp_height, max(options.grasp_heights), options.min_pitch, options.max_pitch, why_not),
        approach_blocked=blocked)


def plan_can_from_here(geometry: KatanaGeometry, q_now: Sequence[float], can, tower, level: int,
                       options: StackingOptions = StackingOptions(), timing: TimingOptions = TimingOptions(),
                       standing: Sequence[Tuple[float, float]] = (),
                       home: Optional[Sequence[float]] = None) -> Tuple[List[Step], List[JointPath]]:
    """plan_can from the arm's joints q_now or, where that finds nothing, after a first move that
    takes the tool farther from what it last let go of: up by retreat_distance, back along the
    line to the base by approach_distance, or both; the empty gripper turned to a pitch at which
    it rises, and up; last, back to the joints `home` (where the arm started, by way_home),
    from here or from that rise. After a can the open fingers are just behind the tower and little
    above its top, and the way from there to the next can may pass too close to it, while from
    higher or farther back it does not. Near the base the straight moves may be out of reach (a
    can set on the table: the elbow's limit), and tower_choice scored every plan from where the
    arm started. The turn and the way home keep the open fingers clear of the tower and the cans.
    PlanError with plan_can's reason from q_now otherwise."""
    try:
        return plan_can(geometry, q_now, can, tower, level, options, timing=timing, standing=standing)
    except PlanError as from_here:
        failure = from_here
    if not failure.approach_blocked:  # no first move makes a can reachable that is not
        raise failure
    here = tool_pose(geometry, q_now)
    back = max(0.0, here.radius - options.approach_distance) / max(here.radius, 1e-9)
    up = here.z + options.retreat_distance
    obstacles = tower_and_cans(tower, level, standing, options.can_height, options.can_radius)
    fingers = OpenFingers(options.open_position)
    straight = [Move('up, clear of the tower', (ToolPose(here.x, here.y, up, here.pitch),)),
                Move('back, clear of the tower', (ToolPose(here.x * back, here.y * back, here.z, here.pitch),)),
                Move('back and up, clear of the tower', (ToolPose(here.x * back, here.y * back, up, here.pitch),))]

    def after(move):
        """plan_can after `move` from q_now, with it; None if either cannot be made."""
        try:
            first = joint_path(geometry, q_now, move, timing=timing)
            steps, paths = plan_can(geometry, first.positions[-1], can, tower, level, options, timing=timing,
                                    standing=standing)
        except PlanError:
            return None
        return [move] + steps, [first] + paths
    for move in straight:
        planned = after(move)
        if planned is not None:
            return planned
    # The turn is searched for only where no straight move did.
    turned = _turned_and_up(geometry, q_now, up, fingers, obstacles, options, timing)
    planned = after(turned) if turned is not None else None
    if planned is not None:
        return planned
    if home is None:
        raise failure
    # Back to where the arm started, from here or from the top of the turned rise.
    way = way_home(geometry, q_now, home, obstacles, options, timing)
    if way is None:
        raise failure
    try:
        steps, paths = plan_can(geometry, home, can, tower, level, options, timing=timing, standing=standing)
    except PlanError:
        raise failure from None
    return [m for m, _ in way] + steps, [p for _, p in way] + paths


def way_home(geometry: KatanaGeometry, q_now: Sequence[float], home: Sequence[float], obstacles,
             options: StackingOptions = StackingOptions(),
             timing: TimingOptions = TimingOptions()) -> Optional[List[Tuple[Move, JointPath]]]:
    """The open gripper's way from q_now back to the joints `home`, as (move, path) pairs: back_off's
    (straight up where the arm can, then the joints home) if the fingers clear the obstacles along
    it, else the gripper first turned to a pitch at which it rises, and up; None if neither clears
    them. The straight rise is not checked: it lifts the fingers off whatever they are at. Near the
    base the elbow's limit stops that rise, and a joint move home from beside a can can sweep the
    fingers through it."""
    fingers = OpenFingers(options.open_position)
    for first in (False, True):
        before = []
        if first:
            here = tool_pose(geometry, q_now)
            turned = _turned_and_up(geometry, q_now, here.z + options.retreat_distance, fingers, obstacles, options,
                                    timing)
            if turned is None:
                return None
            before = [(turned, joint_path(geometry, q_now, turned, timing=timing))]
        q = before[-1][1].positions[-1] if before else tuple(q_now)
        path = back_off(geometry, q, home, options, timing=timing)
        risen = path.positions[-3] if len(path.positions) > 2 else q  # the top of the straight rise
        if path_conflict(geometry, (risen,) + path.positions[-2:], fingers, obstacles) is None:
            return before + [(Move('back to where the arm started', (path.end,), line=False), path)]
    return None


def _turned_and_up(geometry, q_now, up, fingers, obstacles, options, timing):
    """The empty gripper turned in place to the nearest pitch at which the tool rises to height
    `up`, then up (one joint-space segment each), its fingers clear of the obstacles; None if no
    pitch does. Holding nothing, the pitch is free (min_pitch is for a held can's rim), down to
    pointing straight down: near the base the elbow's limit keeps the tool from rising at the
    pitch the can was let go at."""
    here = tool_pose(geometry, q_now)
    empty = pitches(replace(options, min_pitch=-math.pi / 2))
    for pitch in sorted(empty, key=lambda p: abs(p - here.pitch))[1:]:
        move = Move('the gripper turned to %.2f rad and up, clear of the tower' % pitch,
                    (ToolPose(here.x, here.y, here.z, pitch), ToolPose(here.x, here.y, up, pitch)), line=False)
        try:
            path = joint_path(geometry, q_now, move, timing=timing)
        except PlanError:
            continue
        if path_conflict(geometry, (tuple(q_now),) + path.positions, fingers, obstacles) is None:
            return move
    return None


def _check_clear(geometry, q_start, steps, paths, height, obstacles, options):
    """PlanError unless the moves through the air of can_steps' plan clear the obstacles: the
    approach with the fingers open, the carry with the can held (clearance.py). High over
    everything as they go, the joint-space path may still bulge: from just behind the tower, the
    fingers may sweep over it before they rise. The carry first: a blocked approach is
    approach_blocked only when the rest would do."""
    moves = [s for s in steps if isinstance(s, Move)]
    for index, held in ((3, Held(height, options.can_radius)), (0, OpenFingers(options.open_position))):
        start = tuple(q_start) if index == 0 else paths[index - 1].positions[-1]
        conflict = path_conflict(geometry, (start,) + paths[index].positions, held, obstacles)
        if conflict is not None:
            raise PlanError('%s: %s' % (moves[index].what, conflict), approach_blocked=index == 0)


def _plan_lower(geometry, q_start, can, tower, level, height, pitch, obstacles, options, roll, timing):
    """plan_can's second search for one grasp: the approach and the carry at the highest heights
    (carry_step apart) that the arm reaches and that clear the obstacles."""
    o = options
    high = carry_height(level, height, o)

    def moves(steps):
        return [s for s in steps if isinstance(s, Move)]

    def first_clear(variants, q, held, index):
        """The first (heights, steps) whose move `index` is reachable from q and clears the
        obstacles (held None: reachable), with that move's path."""
        why = None
        for heights, steps in variants:
            move = moves(steps)[index]
            try:
                path = joint_path(geometry, q, move, roll, timing)
            except PlanError as e:
                why = why or e
                continue
            conflict = None if held is None else path_conflict(geometry, (tuple(q),) + path.positions, held, obstacles)
            if conflict is None:
                return heights, steps, path
            why = PlanError('%s: %s' % (move.what, conflict), approach_blocked=index == 0)
        raise why

    def after_approach(approach_height, steps, approach):
        taken = plan_moves(geometry, approach.positions[-1], moves(steps)[1:3], roll, timing)
        over_tower = level * o.can_height + o.place_gap + height + o.lift
        _, steps, carry = first_clear(
            ((None, can_steps(can, tower, level, height, pitch, o, approach_height, (above_can, above_tower)))
             for above_tower in heights_down(high, over_tower, o.carry_step)
             for above_can in heights_down(high, height + o.lift, o.carry_step)),
            taken[-1].positions[-1], Held(height, o.can_radius), 3)
        rest = plan_moves(geometry, carry.positions[-1], moves(steps)[4:], roll, timing)
        return steps, [approach] + taken + [carry] + rest

    approaches = [(h, can_steps(can, tower, level, height, pitch, o, approach_height=h))
                  for h in heights_down(high, height, o.carry_step)]
    try:
        return after_approach(*first_clear(approaches, q_start, OpenFingers(o.open_position), 0))
    except PlanError as blocked:
        if not blocked.approach_blocked:
            raise
        # Only the way to the approach point is blocked: a first move elsewhere lifts that only if
        # the rest would do (a PlanError from here if not).
        after_approach(*first_clear(approaches, q_start, None, 0))
        raise


def back_off(geometry: KatanaGeometry, q_now: Sequence[float], q_home: Sequence[float],
             options: StackingOptions = StackingOptions(), roll: float = 0.0,
             timing: TimingOptions = TimingOptions()) -> JointPath:
    """After a failed step: the tool straight up by options.retreat_distance (clear of the can it
    was at; skipped where the arm cannot go straight up), then the joints back to q_home, where
    the arm started and left the laser's view of the table clear."""
    here = tool_pose(geometry, q_now)
    up = Move('straight up', (ToolPose(here.x, here.y, here.z + options.retreat_distance, here.pitch),))
    try:
        path = joint_path(geometry, q_now, up, roll, timing)
        times, positions = list(path.times[:-1]), list(path.positions[:-1])
    except PlanError:
        times, positions = [], []
    last = positions[-1] if positions else tuple(q_now)
    t = times[-1] if times else 0.0
    turn = max(abs(a - b) for a, b in zip(q_home, last))
    t += max(turn / timing.joint_speed, timing.min_interval)
    times += [t, t + timing.settle]
    positions += [tuple(q_home), tuple(q_home)]
    return JointPath(tuple(times), tuple(positions), tool_pose(geometry, q_home))
