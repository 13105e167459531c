"""A Move of the stacking plan as joint-space via points with times, for a
control_msgs/FollowJointTrajectory goal.

The tool path is cut into points about `step` apart (stacking.interpolate) and each is solved by
the triangle IK seeded with the one before, so the arm stays on one branch and the joints move
little between points; a point's time is set by whichever is slower, the tool at tool_speed or
the fastest joint at joint_speed. The last point is repeated `settle` seconds later: upstream's
controller only has P and D terms and must be within 0.02 rad of the goal 0.6 s after the end.
"""
import math
from dataclasses import dataclass
from typing import List, Sequence, Tuple

from katana_pick import katana_ik
from katana_pick.arm_geometry import KatanaGeometry
from katana_pick.stacking import Move, StackingOptions, Step, ToolPose, can_steps, interpolate, pitches


@dataclass(frozen=True)
class TimingOptions:
    step: float = 0.01          # m between via points
    tool_speed: float = 0.08    # m/s
    joint_speed: float = 0.6    # rad/s, for the joint that moves most
    min_interval: float = 0.02  # s between points
    settle: float = 1.5         # s the last point is held at the end


class PlanError(ValueError):
    """A move the arm cannot make; the message names the move and why."""


@dataclass(frozen=True)
class JointPath:
    times: Tuple[float, ...]                 # s from the start of the move
    positions: Tuple[Tuple[float, ...], ...]  # the five arm joints at each time
    end: ToolPose                            # where the tool is at the end


def tool_pose(geometry: KatanaGeometry, q: Sequence[float]) -> ToolPose:
    x, y, z, pitch = katana_ik.forward(geometry, q)
    return ToolPose(x, y, z, pitch)


def joint_path(geometry: KatanaGeometry, q_start: Sequence[float], move: Move, roll: float = 0.0,
               timing: TimingOptions = TimingOptions()) -> JointPath:
    """The move from the arm's joints q_start, as timed via points; PlanError if a point is out
    of reach or out of the joint limits."""
    pose = tool_pose(geometry, q_start)
    q_prev = tuple(q_start)
    times, positions, t = [], [], 0.0
    for target in move.poses:
        # A free move goes to each pose in one joint-space segment: the controller interpolates.
        for p in interpolate(pose, target, timing.step) if move.line else (target,):
            try:
                q = katana_ik.solve(geometry, p.x, p.y, p.z, p.pitch, seed=q_prev, roll=roll)
            except katana_ik.IkError as e:
                raise PlanError('%s: %s' % (move.what, e)) from None
            travel = math.sqrt((p.x - pose.x) ** 2 + (p.y - pose.y) ** 2 + (p.z - pose.z) ** 2)
            turn = max(abs(a - b) for a, b in zip(q, q_prev))
            t += max(travel / timing.tool_speed, turn / timing.joint_speed, timing.min_interval)
            times.append(t)
            positions.append(q)
            pose, q_prev = p, q
    if not positions:
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
             timing: TimingOptions = TimingOptions()) -> Tuple[List[Step], List[JointPath]]:
    """The steps for one can (stacking.can_steps) and the joint paths of their moves, at the first
    of options.grasp_heights for which some pitch makes every move reachable, and at the middle
    one of those pitches (the most room to the joint limits); PlanError if there is none."""
    why_not = None
    for height in options.grasp_heights:
        feasible = []
        for pitch in sorted(pitches(options)):
            steps = can_steps(can, tower, level, height, pitch, options)
            try:
                paths = plan_moves(geometry, q_start, [s for s in steps if isinstance(s, Move)], roll, timing)
            except PlanError as e:
                if why_not is None or pitch == 0.0 and height == options.grasp_heights[0]:
                    why_not = 'grasped %.2f m up with the gripper level: %s' % (height, e)
                continue
            feasible.append((steps, paths))
        if feasible:
            return feasible[len(feasible) // 2]
    raise PlanError('no grasp %s m up with a pitch in [%.2f, %.2f] rad reaches it (%s)' % (
        '/'.join('%.2f' % h for h in options.grasp_heights), options.min_pitch, options.max_pitch, why_not))


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
