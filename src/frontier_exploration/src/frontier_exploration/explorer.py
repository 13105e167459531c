"""The choice of exploration goal, without ROS: find_frontier and explore call plan() with each map
(or at their planner frequency) and finished() with each goal's outcome, and act on the Decision.

- A goal is a reachable cell with no unknown cell within the robot's radius: the robot fits there
  even if a wall the map has not seen yet stands just beyond the frontier.
- A goal is sent once and kept while its frontier is still there (a frontier cell within
  `blacklist_radius` of its middle), its goal cell still reachable, and the robot makes progress:
  a new map alone never re-sends it (re-sending preempts move_base over and over).
- Goals that abort, are refused, or see no progress along their path for `progress_timeout` are
  blacklisted, and so are goals reached while their frontier is still there (going back would not
  reveal it either). A goal we preempt ourselves, or that someone else preempts, is not.
- "Still there" is judged on a map made after the arrival: mappers publish every few seconds
  (slam_gmapping every 5 s, and only once the robot has moved), and the map the robot arrives
  with may not yet show what it saw on the way. Until a newer map comes (at most
  `progress_timeout`), other frontiers are chosen, or the explorer waits. (A shorter wait, twice
  the mapper's interval between maps, was tried: one of ten Pioneer explorations then ended at
  61 %, and m_robot finished no sooner.)
- A mapper may send no new map until the robot moves (slam_gmapping maps a scan only after
  `linearUpdate` or `angularUpdate`): when nothing else is left to do and the map is overdue (no
  map for twice its usual interval, or a single map so far), the robot turns a quarter turn on
  the spot at the reached goal, once per arrival, towards the frontier's side; the wait for a
  newer map restarts when the turn ends.
- A frontier given up on once is tried again when nothing else is left (a robot that was stuck
  may not be any more); twice, never.
- "complete" when no frontier is left, or none that is reachable and not given up on twice.
"""
import math
from dataclasses import dataclass, field

import numpy as np

from frontier_exploration.frontiers import FrontierOptions, find_frontiers
from frontier_exploration.goals import Blacklist, goal_cell, middle_cell
from frontier_exploration.reachability import reachable_cells, seen_round

SEND, KEEP, COMPLETE, WAIT = 'send', 'keep', 'complete', 'wait'
SUCCEEDED, ABORTED, REJECTED, PREEMPTED, LOST = 'succeeded', 'aborted', 'rejected', 'preempted', 'lost'


@dataclass
class ExplorerOptions:
    frontiers: FrontierOptions = field(default_factory=FrontierOptions)
    min_frontier_size: float = 0.5    # m of frontier (cells x resolution); smaller ones are left out
    clearance: float = 0.2            # m from occupied cells the robot needs (its inscribed radius or more)
    approach_radius: float = 1.0      # m: how far from its frontier a goal may be
    ranking: str = 'size'             # 'size': largest first (the lecture); 'cost': explore_lite's cost
    potential_scale: float = 1e-3     # explore_lite's weights (ranking 'cost')
    gain_scale: float = 1.0
    progress_timeout: float = 30.0    # s without getting 5 cm nearer the goal: give it up
    blacklist_radius: float = 0.5     # m


@dataclass
class Candidate:
    """A frontier as the last plan saw it, for the node's markers."""
    frontier: object
    middle: tuple           # world (x, y) of its middle cell
    goal: tuple = None      # world (x, y) of its goal cell, None when out of reach (or not looked for)
    checked: bool = False   # whether its goal was looked for (not while a goal is kept)
    path_length: float = math.inf
    blacklisted: bool = False   # given up on as often as allowed
    strikes: int = 0            # times given up on


@dataclass
class Target:
    number: int             # counts goals sent: finished() names the goal it is about
    middle: tuple
    goal: tuple             # (x, y, yaw)
    best_distance: float    # the shortest path length to the goal seen so far (m)
    last_progress: float
    turn: bool = False      # a turn on the spot at the last reached goal, for a newer map


@dataclass
class Arrival:
    """A reached goal whose frontier is judged on the first map made after `at`."""
    number: int
    middle: tuple
    at: float               # s; None: unknown, the next map judges
    goal: tuple = None      # (x, y, yaw) reached
    waited_from: float = None   # s: the newer map is waited for since then (None: since `at`)
    turned: bool = False    # whether the robot has turned on the spot for it


@dataclass
class Decision:
    kind: str               # SEND, KEEP, COMPLETE or WAIT
    message: str
    goal: tuple = None      # (x, y, yaw) for SEND and KEEP
    number: int = 0         # the goal's number, for SEND and KEEP
    candidates: list = field(default_factory=list)
    note: str = ''          # why the last goal was dropped, when it was
    grid: object = None     # the grid the candidates' cells index (the map cropped to its known part)


class Explorer:
    PROGRESS_STEP = 0.05  # m nearer the goal along the path that counts as progress (more than the mapper's jitter)
    MAX_STRIKES = 2       # times a frontier may be given up on before it is left for good
    MAP_INTERVALS = 5     # recent intervals between maps that give the mapper's usual interval

    def __init__(self, options=None):
        self.options = options or ExplorerOptions()
        self.blacklist = Blacklist(self.options.blacklist_radius)
        self.target = None
        self.arrival = None      # the last reached goal, until a newer map shows whether its frontier is gone
        self.goals_sent = 0
        self.goals_reached = 0
        self.goals_failed = 0
        self.map_times = []      # the last few distinct map times (s), oldest first

    # --- what the node calls ------------------------------------------------------------------------

    def plan(self, grid, robot_xy, now, map_time=None):
        """The decision for this map and robot position at time `now` (s); `map_time` is when the map
        was made (None: it is current)."""
        grid = grid.cropped_to_known()
        self._note_map_time(map_time)
        o = self.options
        reach = reachable_cells(grid, robot_xy, o.clearance, o.frontiers.free_threshold, o.frontiers.occupied_threshold)
        if reach is None:
            return Decision(WAIT, 'the robot at (%.2f, %.2f) has no known free cell with %.2f m clearance within '
                                  'reach (off the map, boxed in, or the map has not seen round it yet)'
                            % (robot_xy[0], robot_xy[1], o.clearance), grid=grid)
        frontier_options = FrontierOptions(**{**o.frontiers.__dict__,
                                              'min_size': max(1, math.ceil(o.min_frontier_size / grid.resolution))})
        candidates = [Candidate(f, tuple(float(v) for v in grid.cell_to_world(*middle_cell(f))))
                      for f in find_frontiers(grid, robot_xy, frontier_options)]
        note = self._judge_arrival(grid, candidates, now, map_time)
        if self.target is not None:
            kept, dropped = self._follow_target(grid, reach, candidates, robot_xy, now)
            if kept:
                return Decision(KEEP, '%s (%.2f, %.2f)' % ('turning on the spot at' if self.target.turn else
                                                           'heading for', *self.target.goal[:2]),
                                self.target.goal, self.target.number, candidates, note, grid)
            note = '; '.join(n for n in (note, dropped) if n)
        goal_cells = reach.mask & seen_round(grid, o.clearance)
        for c in candidates:
            c.strikes = self.blacklist.strikes(c.middle)
            c.blacklisted = c.strikes >= self.MAX_STRIKES
            if c.blacklisted:
                continue
            cell = goal_cell(c.frontier, grid, goal_cells, o.approach_radius, o.frontiers.free_threshold)
            c.checked = True
            if cell is not None:
                c.goal = tuple(float(v) for v in grid.cell_to_world(*cell))
                c.path_length = float(reach.distance[cell])
        reachable = [c for c in candidates if c.goal is not None and not c.blacklisted]
        if self.arrival is not None:  # the reached goal's frontier, as a map from before the arrival shows it
            reachable = [c for c in reachable if not self._near(c, self.arrival.middle, grid)]
        fewest = min((c.strikes for c in reachable), default=0)
        usable = [c for c in reachable if c.strikes == fewest]  # frontiers given up on once: when nothing else is left
        if not usable and self.arrival is not None:
            turn = self._turn_for_a_map(now)
            if turn is not None:
                return Decision(SEND, turn, self.target.goal, self.target.number, candidates, note, grid)
            return Decision(WAIT, 'waiting for a map made after goal %d was reached' % self.arrival.number,
                            candidates=candidates, note=note, grid=grid)
        if not usable:
            return Decision(COMPLETE, self._completion_message(candidates), candidates=candidates, note=note,
                            grid=grid)
        best = min(usable, key=lambda c: self._rank(c, grid.resolution))
        gx, gy = best.goal
        yaw = self._heading(robot_xy, best.goal, best.middle)
        self.goals_sent += 1
        self.target = Target(self.goals_sent, best.middle, (gx, gy, yaw), best.path_length, now)
        return Decision(SEND, 'goal %d: (%.2f, %.2f), for a frontier of %d cells %.1f m away'
                        % (self.goals_sent, gx, gy, best.frontier.size, best.path_length),
                        self.target.goal, self.goals_sent, candidates, note, grid)

    def finished(self, number, outcome, now=None):
        """Goal `number` ended with `outcome` (SUCCEEDED, ABORTED, REJECTED, PREEMPTED or LOST) at time
        `now` (s; None: unknown). Returns a message for the log, or None when the goal is no longer ours."""
        target = self.target
        if target is None or number != target.number:
            return None
        self.target = None
        if target.turn:  # whatever its outcome: the wait for a newer map goes on from here
            if self.arrival is not None and now is not None:
                self.arrival.waited_from = now
            return 'goal %d (the turn on the spot) %s' % (number, outcome)
        if outcome == PREEMPTED:
            return 'goal %d was preempted (not by us): choosing again' % number
        if outcome == SUCCEEDED:
            self.goals_reached += 1
            self.arrival = Arrival(number, target.middle, now, target.goal)
            return 'goal %d reached' % number
        self.blacklist.add(target.middle)
        self.goals_failed += 1
        return 'goal %d at (%.2f, %.2f) %s: its frontier is given up on' % (number, target.goal[0], target.goal[1], outcome)

    # --- the parts --------------------------------------------------------------------------------------

    def _judge_arrival(self, grid, candidates, now, map_time):
        """Once a map made after the last arrival is here (or progress_timeout has passed without
        one), a frontier still at the reached goal's is given up on once. A note when it is."""
        a = self.arrival
        if a is None:
            return ''
        fresh = map_time is None or a.at is None or map_time > a.at
        waited_from = a.at if a.waited_from is None else a.waited_from
        if not fresh and now - waited_from <= self.options.progress_timeout:
            return ''
        self.arrival = None
        if not any(self._near(c, a.middle, grid) for c in candidates):
            return ''
        self.blacklist.add(a.middle)
        return 'goal %d was reached but its frontier is still there%s: it is given up on' % (
            a.number, '' if fresh else ' (no newer map in %.0f s)' % self.options.progress_timeout)

    def _note_map_time(self, map_time):
        times = self.map_times
        if map_time is None or (times and map_time == times[-1]):
            return
        if times and map_time < times[-1]:  # time went back (a world reset): a new schedule
            times.clear()
        times.append(map_time)
        del times[:-(self.MAP_INTERVALS + 1)]

    def _map_overdue(self, now):
        """Whether no map has come for twice the mapper's usual interval (the median of the last few);
        with a single map, always (waiting costs more than a needless turn)."""
        if len(self.map_times) < 2:
            return True
        return now - self.map_times[-1] > 2.0 * float(np.median(np.diff(self.map_times)))

    def _turn_for_a_map(self, now):
        """The message of a quarter turn on the spot at the reached goal, made the target, when the
        map is overdue and the robot has not turned for this arrival yet; else None."""
        a = self.arrival
        if a.turned or a.goal is None or not self._map_overdue(now):
            return None
        a.turned, a.waited_from = True, now
        x, y, yaw = a.goal
        left = math.cos(yaw) * (a.middle[1] - y) - math.sin(yaw) * (a.middle[0] - x) >= 0
        turned = yaw + (math.pi / 2 if left else -math.pi / 2)
        turned = math.atan2(math.sin(turned), math.cos(turned))
        self.goals_sent += 1
        self.target = Target(self.goals_sent, a.middle, (x, y, turned), 0.0, now, turn=True)
        silent = ' for %.0f s' % (now - self.map_times[-1]) if self.map_times else ''
        return ('goal %d: a turn on the spot at (%.2f, %.2f): no map has come%s since goal %d was reached (the mapper '
                'may wait for the robot to move)' % (self.goals_sent, x, y, silent, a.number))

    def _near(self, candidate, point, grid):
        """Whether a frontier cell of `candidate` lies within blacklist_radius of `point`."""
        xy = np.asarray(grid.cell_to_world(candidate.frontier.rows, candidate.frontier.cols))
        return bool(np.hypot(*(xy - np.asarray(point).reshape(2, 1))).min() <= self.options.blacklist_radius)

    def _follow_target(self, grid, reach, candidates, robot_xy, now):
        """(keep it?, a note on why not)."""
        t = self.target
        if t.turn:  # kept until it ends, unless a newer map has judged the arrival meanwhile
            if self.arrival is None:
                self.target = None
                return False, ''
            if now - t.last_progress > self.options.progress_timeout:
                self.target = None
                return False, 'the turn on the spot (goal %d) took over %.0f s: left' % (
                    t.number, self.options.progress_timeout)
            return True, ''
        cell = grid.world_to_cell(*t.goal[:2])
        if cell is None or not reach.mask[cell]:
            self.target = None
            return False, 'goal %d is no longer reachable (the map has changed there)' % t.number
        if not any(self._near(c, t.middle, grid) for c in candidates):
            self.target = None
            return False, 'goal %d\'s frontier is explored' % t.number
        # Along the path: on a detour round a wall the straight line grows while the robot gets nearer.
        distance = float(reach.distance[cell])
        if distance < t.best_distance - self.PROGRESS_STEP:
            t.best_distance, t.last_progress = distance, now
        elif now - t.last_progress > self.options.progress_timeout:
            self.blacklist.add(t.middle)
            self.goals_failed += 1
            self.target = None
            return False, ('no progress towards goal %d at (%.2f, %.2f) for %.0f s: its frontier is given up on'
                           % (t.number, t.goal[0], t.goal[1], self.options.progress_timeout))
        return True, ''

    def _rank(self, c, resolution):
        o = self.options
        if o.ranking == 'cost':  # explore_lite's frontier cost, its units as there
            return o.potential_scale * c.path_length * resolution - o.gain_scale * c.frontier.size * resolution
        return (-c.frontier.size, c.path_length)

    @staticmethod
    def _heading(robot_xy, goal, middle):
        """The goal's yaw: the way the robot drives there (no turn on arrival), or towards the
        frontier when the goal is where the robot stands."""
        dx, dy = goal[0] - robot_xy[0], goal[1] - robot_xy[1]
        if math.hypot(dx, dy) < 0.1:
            dx, dy = middle[0] - goal[0], middle[1] - goal[1]
        return math.atan2(dy, dx)

    @staticmethod
    def _completion_message(candidates):
        if not candidates:
            return 'exploration complete: no frontier left'
        blacklisted = sum(1 for c in candidates if c.blacklisted)
        unreachable = sum(1 for c in candidates if not c.blacklisted and c.goal is None)
        return ('exploration complete: no reachable frontier left (%d left: %d given up on twice, %d out of reach of the '
                'robot through known free space)' % (len(candidates), blacklisted, unreachable))
