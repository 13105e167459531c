"""frontier_exploration's reachability, goal cells, blacklist and Explorer decisions on small
hand-made grids of 0.05 m cells (no ROS)."""
import math
import os
import sys

import numpy as np
import pytest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..', 'src'))
from frontier_exploration.explorer import (ABORTED, COMPLETE, KEEP, PREEMPTED, SEND, SUCCEEDED, WAIT,  # noqa: E402
                                           Explorer, ExplorerOptions)
from frontier_exploration.frontiers import FrontierOptions, find_frontiers  # noqa: E402
from frontier_exploration.goals import Blacklist, goal_cell, middle_cell  # noqa: E402
from frontier_exploration.grid import Grid  # noqa: E402
from frontier_exploration.reachability import reachable_cells  # noqa: E402

U, F, O = -1, 0, 100
RES = 0.05


def grid_of(rows, origin=(0.0, 0.0)):
    """A grid from text, top line = highest row: '#' occupied, '.' free, '?' unknown."""
    code = {'#': O, '.': F, '?': U}
    values = np.array([[code[ch] for ch in line] for line in reversed(rows)])
    return Grid(values, RES, *origin)


def block(height, width, fill):
    return np.full((height, width), fill)


def square_room_with_pillar():
    """A 1.5 m free square (rows and columns 5-34) in unknown space, a 0.5 m pillar in its middle:
    the frontier is the square's rim, one 8-connected ring whose centroid is inside the pillar."""
    g = block(40, 40, U)
    g[5:35, 5:35] = F
    g[15:25, 15:25] = O
    return Grid(g, RES)


def two_rooms_with_an_opening(opening_rows):
    """Room A (columns 1-18) and room B (columns 21-38) of a 40 x 40 grid, walled round, split by a
    wall at columns 19-20 open at `opening_rows`; unknown beyond a gap in B's east wall (rows
    10-29)."""
    g = block(40, 42, U)
    g[0:40, 0:40] = O
    g[1:39, 1:19] = F
    g[1:39, 21:39] = F
    g[opening_rows, 19:21] = F
    g[10:30, 39] = F  # the gap: free cells with unknown beyond, column 40+
    return Grid(g, RES)


OPTIONS = ExplorerOptions(frontiers=FrontierOptions(min_distance=0.0, clearance=0.0), min_frontier_size=0.1,
                          clearance=0.15, approach_radius=0.5, progress_timeout=30.0, blacklist_radius=0.3)


# --- reachability -------------------------------------------------------------------------------------

def test_an_opening_narrower_than_the_robot_leaves_the_other_room_out_of_reach():
    wide = reachable_cells(two_rooms_with_an_opening(slice(10, 30)), (0.5, 1.0), clearance=0.15)
    narrow = reachable_cells(two_rooms_with_an_opening(slice(18, 22)), (0.5, 1.0), clearance=0.15)
    assert wide.mask[20, 30] and not narrow.mask[20, 30]       # room B's middle
    assert narrow.mask[20, 10] and wide.mask[20, 10]           # room A's
    assert not wide.mask[5, 19]                                # the wall's cells are never reachable


def test_path_lengths_go_round_walls():
    grid = two_rooms_with_an_opening(slice(30, 38))  # the opening high up
    reach = reachable_cells(grid, grid.cell_to_world(10, 10), clearance=0.15)
    straight = math.hypot(0, 20) * RES               # row 10: column 10 to column 30, through the wall
    assert reach.distance[10, 10] == 0.0
    # Up to the opening (rows 33-34 keep 0.15 m from its edges) and back down: at least 2 x 23 cells.
    assert 2 * 22 * RES < reach.distance[10, 30] < 2 * 30 * RES
    assert reach.distance[10, 30] > 2 * straight
    assert math.isinf(reach.distance[20, 19])


def test_a_robot_off_the_map_or_walled_in_has_nowhere_to_go():
    grid = square_room_with_pillar()
    assert reachable_cells(grid, (5.0, 5.0), clearance=0.15) is None   # off the grid
    assert reachable_cells(grid, (1.0, 1.0), clearance=0.15) is None   # in the pillar
    # Beside a wall, nearer than the clearance: paths start from the nearest clear cell.
    beside = reachable_cells(grid, grid.cell_to_world(20, 26), clearance=0.15)
    assert beside is not None and beside.start != (20, 26) and beside.mask[beside.start]


# --- goal cells -------------------------------------------------------------------------------------

def test_the_goal_of_a_frontier_whose_centroid_is_in_a_wall_is_a_reachable_cell_on_it():
    grid = square_room_with_pillar()
    (rim,) = find_frontiers(grid, (0.4, 0.4), FrontierOptions(min_distance=0.0, clearance=0.0))
    assert grid.world_to_cell(*rim.centroid) in [(r, c) for r in range(15, 25) for c in range(15, 25)]
    middle = middle_cell(rim)
    assert middle in set(zip(rim.rows.tolist(), rim.cols.tolist()))  # on the frontier itself
    reach = reachable_cells(grid, (0.4, 0.4), clearance=0.15)
    cell = goal_cell(rim, grid, reach.mask, approach_radius=0.5)
    assert grid.values[cell] == F and reach.mask[cell]
    # The rim hugs unknown space, so its own cells are 0.15 m too near nothing: the goal is among
    # them when clear, else at most approach_radius from them.
    assert min(math.hypot(cell[0] - r, cell[1] - c) for r, c in zip(rim.rows, rim.cols)) * RES <= 0.5


def test_a_frontier_behind_a_wall_gets_no_goal_on_the_near_side():
    grid = two_rooms_with_an_opening(slice(0, 0))                       # no opening: B is sealed off
    robot = grid.cell_to_world(20, 17)                                  # in A, 0.2 m from the wall
    (gap,) = find_frontiers(grid, robot, FrontierOptions(min_distance=0.0, clearance=0.0))
    reach = reachable_cells(grid, robot, clearance=0.15)
    assert goal_cell(gap, grid, reach.mask, approach_radius=2.0) is None


def test_the_blacklist_matches_points_within_its_radius_and_counts_strikes():
    b = Blacklist(0.3)
    b.add((1.0, 1.0))
    assert b.contains((1.2, 1.2)) and not b.contains((1.3, 1.3))
    b.add((1.1, 1.0))                      # the same frontier, shifted a little
    assert b.strikes((1.0, 1.0)) == 2 and len(b) == 1
    b.clear()
    assert not b.contains((1.0, 1.0)) and len(b) == 0


def test_cropping_to_the_known_part_keeps_world_positions():
    g = block(100, 80, U)
    g[40:50, 30:45] = F
    grid = Grid(g, RES, origin_x=-2.0, origin_y=1.0, origin_yaw=0.3)
    small = grid.cropped_to_known(margin=2)
    assert small.values.shape == (14, 19)
    assert small.cell_to_world(2, 2) == pytest.approx(grid.cell_to_world(40, 30))


# --- the Explorer -------------------------------------------------------------------------------------

def east_and_north_openings():
    """A walled 2 x 2 m room (40 x 40 cells) with a 1 m opening east (rows 10-29) and a 0.5 m
    opening north (columns 25-34), unknown beyond both."""
    g = block(46, 46, U)
    g[0:41, 0:41] = O
    g[1:40, 1:40] = F
    g[10:30, 40] = F
    g[40, 25:35] = F
    return Grid(g, RES)


def only_the_east_opening():
    """east_and_north_openings() with the north opening walled: the east frontier is the only one."""
    g = east_and_north_openings().values.copy()
    g[40, 25:35] = O
    return Grid(g, RES)


def test_the_largest_frontier_is_sent_once_then_kept_not_resent():
    explorer = Explorer(OPTIONS)
    grid = east_and_north_openings()
    first = explorer.plan(grid, (0.5, 0.5), now=0.0)
    assert first.kind == SEND
    assert grid.world_to_cell(*first.goal[:2])[1] >= 37     # at the east opening
    again = explorer.plan(grid, (0.6, 0.6), now=1.0)
    assert again.kind == KEEP and again.number == first.number and again.goal == first.goal


@pytest.mark.parametrize('outcome', [ABORTED, 'rejected', 'lost'])
def test_a_failed_goal_is_given_up_for_the_next_frontier_and_retried_once_when_none_is_left(outcome):
    explorer = Explorer(OPTIONS)
    grid = east_and_north_openings()
    first = explorer.plan(grid, (0.5, 0.5), now=0.0)
    assert explorer.finished(first.number, outcome).endswith('its frontier is given up on')
    second = explorer.plan(grid, (0.5, 0.5), now=1.0)
    assert second.kind == SEND and second.number == first.number + 1
    assert grid.world_to_cell(*second.goal[:2])[0] >= 37    # at the north opening
    explorer.finished(second.number, ABORTED)
    # Both given up on once: each is tried once more, the larger first, then never again.
    third = explorer.plan(grid, (0.5, 0.5), now=2.0)
    assert third.kind == SEND and third.goal == first.goal
    explorer.finished(third.number, ABORTED)
    fourth = explorer.plan(grid, (0.5, 0.5), now=3.0)
    assert fourth.kind == SEND and fourth.goal == second.goal
    explorer.finished(fourth.number, ABORTED)
    done = explorer.plan(grid, (0.5, 0.5), now=4.0)
    assert done.kind == COMPLETE
    assert done.message == ('exploration complete: no reachable frontier left (2 left: 2 given up on twice, '
                            '0 out of reach of the robot through known free space)')


def test_a_preempted_goal_is_not_blacklisted_and_an_old_goals_result_is_ignored():
    explorer = Explorer(OPTIONS)
    grid = east_and_north_openings()
    first = explorer.plan(grid, (0.5, 0.5), now=0.0)
    assert explorer.finished(first.number - 1, ABORTED) is None     # not the current goal
    assert explorer.finished(first.number, PREEMPTED) == 'goal 1 was preempted (not by us): choosing again'
    again = explorer.plan(grid, (0.5, 0.5), now=1.0)
    assert again.kind == SEND and again.goal == first.goal and len(explorer.blacklist) == 0


def test_no_progress_along_the_path_for_progress_timeout_gives_the_goal_up():
    explorer = Explorer(OPTIONS)
    grid = east_and_north_openings()
    first = explorer.plan(grid, (0.5, 0.5), now=0.0)
    assert explorer.plan(grid, (0.5, 0.5), now=29.0).kind == KEEP
    # 10 cm nearer at 29.5 s restarts the clock; stuck from there on.
    assert explorer.plan(grid, (0.6, 0.55), now=29.5).kind == KEEP
    assert explorer.plan(grid, (0.6, 0.55), now=59.0).kind == KEEP
    after = explorer.plan(grid, (0.6, 0.55), now=60.0)
    assert after.kind == SEND and after.number == first.number + 1 and after.goal != first.goal
    assert after.note.startswith('no progress towards goal 1 at') and after.message.startswith('goal 2: (')
    assert len(explorer.blacklist) == 1


def test_a_goal_reached_with_its_frontier_still_there_is_not_chosen_again():
    explorer = Explorer(OPTIONS)
    grid = east_and_north_openings()
    first = explorer.plan(grid, (0.5, 0.5), now=0.0)
    assert explorer.finished(first.number, SUCCEEDED) == 'goal 1 reached'
    second = explorer.plan(grid, first.goal[:2], now=5.0)
    assert second.kind == SEND and math.dist(second.goal[:2], first.goal[:2]) > 0.5


def east_alcove_seen(grid):
    """east_and_north_openings() once the robot has looked through the east opening: a closed alcove."""
    g = grid.values.copy()
    g[10:30, 41:45] = F
    g[9, 40:46] = g[30, 40:46] = O
    g[10:30, 45] = O
    return Grid(g, RES)


def test_a_reached_goal_is_judged_on_a_map_made_after_the_arrival():
    explorer = Explorer(OPTIONS)
    grid = east_and_north_openings()
    first = explorer.plan(grid, (0.5, 0.5), now=0.0, map_time=0.0)
    assert explorer.finished(first.number, SUCCEEDED, now=10.0) == 'goal 1 reached'
    # The map from before the arrival still shows the east frontier: not a strike, but not chosen.
    stale = explorer.plan(grid, first.goal[:2], now=10.5, map_time=8.0)
    assert stale.kind == SEND and grid.world_to_cell(*stale.goal[:2])[0] >= 37   # the north opening
    assert len(explorer.blacklist) == 0 and stale.note == ''
    # The next map shows what the robot saw on arrival: the east frontier is gone, nothing given up.
    fresh = explorer.plan(east_alcove_seen(grid), stale.goal[:2], now=12.0, map_time=11.0)
    assert fresh.kind == KEEP and fresh.number == stale.number
    assert len(explorer.blacklist) == 0 and fresh.note == ''


def test_a_frontier_still_there_on_a_map_made_after_the_arrival_is_given_up_once():
    explorer = Explorer(OPTIONS)
    grid = east_and_north_openings()
    first = explorer.plan(grid, (0.5, 0.5), now=0.0, map_time=0.0)
    explorer.finished(first.number, SUCCEEDED, now=10.0)
    second = explorer.plan(grid, first.goal[:2], now=11.0, map_time=10.5)
    assert second.note == 'goal 1 was reached but its frontier is still there: it is given up on'
    assert explorer.blacklist.strikes(first.goal[:2]) == 1 and explorer.blacklist.strikes(second.goal[:2]) == 0
    assert second.kind == SEND and grid.world_to_cell(*second.goal[:2])[0] >= 37


def test_with_a_single_map_so_far_the_robot_turns_at_once_then_waits_progress_timeout():
    explorer = Explorer(OPTIONS)
    grid = only_the_east_opening()
    first = explorer.plan(grid, (0.5, 0.5), now=0.0, map_time=0.0)
    explorer.finished(first.number, SUCCEEDED, now=10.0)
    # No interval between maps to tell when the next is due: the turn comes at once.
    turn = explorer.plan(grid, first.goal[:2], now=10.5, map_time=0.0)
    assert turn.kind == SEND and turn.message.startswith('goal 2: a turn on the spot')
    explorer.finished(turn.number, SUCCEEDED, now=12.0)
    waiting = explorer.plan(grid, first.goal[:2], now=41.5, map_time=0.0)
    assert waiting.kind == WAIT and waiting.message == 'waiting for a map made after goal 1 was reached'
    assert len(explorer.blacklist) == 0
    # No newer map within progress_timeout (30 s) of the turn: judged on this one; tried once more, as the
    # only frontier.
    judged = explorer.plan(grid, first.goal[:2], now=42.5, map_time=0.0)
    assert judged.note == ('goal 1 was reached but its frontier is still there (no newer map in 30 s): it is '
                           'given up on')
    assert judged.kind == SEND and explorer.blacklist.strikes(first.goal[:2]) == 1


def test_when_the_frontier_is_explored_a_new_goal_is_chosen():
    explorer = Explorer(OPTIONS)
    grid = east_and_north_openings()
    explorer.plan(grid, (0.5, 0.5), now=0.0)
    second = explorer.plan(east_alcove_seen(grid), (0.6, 0.6), now=1.0)
    assert second.kind == SEND and second.number == 2
    assert second.note == "goal 1's frontier is explored" and second.message.startswith('goal 2: (')


def test_a_goal_that_ends_up_inside_a_wall_is_replaced():
    explorer = Explorer(OPTIONS)
    grid = east_and_north_openings()
    first = explorer.plan(grid, (0.5, 0.5), now=0.0)
    g = grid.values.copy()
    row, col = grid.world_to_cell(*first.goal[:2])
    g[row - 2:row + 3, col - 2:col + 3] = O
    second = explorer.plan(Grid(g, RES), (0.5, 0.5), now=1.0)
    assert second.kind == SEND and second.note == 'goal 1 is no longer reachable (the map has changed there)'
    assert g[grid.world_to_cell(*second.goal[:2])] == F


def test_a_closed_room_is_complete_and_a_lost_robot_waits():
    g = block(20, 20, O)
    g[1:19, 1:19] = F
    explorer = Explorer(OPTIONS)
    done = explorer.plan(Grid(g, RES), (0.5, 0.5), now=0.0)
    assert (done.kind, done.message) == (COMPLETE, 'exploration complete: no frontier left')
    lost = explorer.plan(Grid(g, RES), (3.0, 3.0), now=0.0)
    assert lost.kind == WAIT and 'no known free cell' in lost.message


def test_the_cost_ranking_prefers_the_near_frontier_when_distance_weighs_more():
    grid = east_and_north_openings()
    robot = grid.cell_to_world(36, 30)   # near the north opening, far from the east one
    by_size = Explorer(OPTIONS).plan(grid, robot, now=0.0)
    assert grid.world_to_cell(*by_size.goal[:2])[1] >= 37
    by_cost = Explorer(ExplorerOptions(**{**OPTIONS.__dict__, 'ranking': 'cost', 'potential_scale': 100.0}))
    near = by_cost.plan(grid, robot, now=0.0)
    assert grid.world_to_cell(*near.goal[:2])[0] >= 37


def test_goals_face_the_way_the_robot_drives():
    explorer = Explorer(OPTIONS)
    grid = east_and_north_openings()
    first = explorer.plan(grid, (0.5, 0.5), now=0.0)
    gx, gy, yaw = first.goal
    assert yaw == pytest.approx(math.atan2(gy - 0.5, gx - 0.5))


def test_goals_keep_the_robots_radius_from_unknown_space_and_walls():
    # A wall may stand unseen just beyond a frontier: the robot must fit at the goal all the same.
    explorer = Explorer(OPTIONS)
    grid = east_and_north_openings()
    unknown_rows, unknown_cols = np.nonzero(grid.values == U)
    wall_rows, wall_cols = np.nonzero(grid.values == O)
    for now in (0.0, 1.0):
        decision = explorer.plan(grid, (0.5, 0.5), now=now)
        assert decision.kind == SEND
        row, col = grid.world_to_cell(*decision.goal[:2])
        assert np.hypot(unknown_rows - row, unknown_cols - col).min() * RES > OPTIONS.clearance
        assert np.hypot(wall_rows - row, wall_cols - col).min() * RES >= OPTIONS.clearance
        explorer.finished(decision.number, ABORTED)


def test_a_detour_round_a_wall_counts_as_progress():
    # The goal is across a wall with the opening far up: driving up, away from the goal in a straight
    # line, gets the robot nearer along its path, which is what counts.
    grid = two_rooms_with_an_opening(slice(30, 38))
    options = ExplorerOptions(**{**OPTIONS.__dict__, 'progress_timeout': 10.0})
    explorer = Explorer(options)
    first = explorer.plan(grid, grid.cell_to_world(10, 10), now=0.0)
    assert first.kind == SEND and grid.world_to_cell(*first.goal[:2])[1] > 20   # in room B
    for k, row in enumerate(range(12, 34, 2)):                                     # up room A, 5 s a step
        assert explorer.plan(grid, grid.cell_to_world(row, 10), now=5.0 * (k + 1)).kind == KEEP


def reach_the_east_opening_with_maps_every_5_s(explorer, grid):
    """Goal 1 sent at 0 s and kept while maps come at 0, 5 and 10 s; reached at 12 s."""
    first = explorer.plan(grid, (0.5, 0.5), now=0.0, map_time=0.0)
    for t in (5.0, 10.0):
        assert explorer.plan(grid, (0.5 + 0.1 * t, 0.5), now=t, map_time=t).kind == KEEP
    assert explorer.finished(first.number, SUCCEEDED, now=12.0) == 'goal 1 reached'
    return first


def test_when_the_map_is_overdue_after_an_arrival_the_robot_turns_on_the_spot_and_the_next_map_judges():
    explorer = Explorer(OPTIONS)
    grid = only_the_east_opening()
    first = reach_the_east_opening_with_maps_every_5_s(explorer, grid)
    # Maps came every 5 s: at 19 s the one due at 15 s is late, but not yet twice the interval.
    assert explorer.plan(grid, first.goal[:2], now=19.0, map_time=10.0).kind == WAIT
    turn = explorer.plan(grid, first.goal[:2], now=20.5, map_time=10.0)
    assert turn.kind == SEND and turn.number == 2 and turn.goal[:2] == first.goal[:2]
    assert turn.message.startswith('goal 2: a turn on the spot at (') and 'since goal 1 was reached' in turn.message
    turned_by = math.atan2(math.sin(turn.goal[2] - first.goal[2]), math.cos(turn.goal[2] - first.goal[2]))
    assert abs(abs(turned_by) - math.pi / 2) < 1e-9
    assert explorer.plan(grid, first.goal[:2], now=21.0, map_time=10.0).kind == KEEP
    assert explorer.finished(turn.number, SUCCEEDED, now=23.0) == 'goal 2 (the turn on the spot) succeeded'
    # The turn made the mapper send a map: it shows the alcove, so nothing is given up and all is explored.
    done = explorer.plan(east_alcove_seen(grid), first.goal[:2], now=24.0, map_time=23.5)
    assert done.kind == COMPLETE and done.message == 'exploration complete: no frontier left'
    assert len(explorer.blacklist) == 0 and explorer.goals_reached == 1


def test_the_robot_turns_once_per_arrival_and_then_waits_progress_timeout_from_the_turns_end():
    explorer = Explorer(OPTIONS)
    grid = only_the_east_opening()
    first = reach_the_east_opening_with_maps_every_5_s(explorer, grid)
    turn = explorer.plan(grid, first.goal[:2], now=21.0, map_time=10.0)
    assert turn.kind == SEND
    # An aborted turn is no strike: the frontier was not judged.
    assert explorer.finished(turn.number, ABORTED, now=25.0) == 'goal 2 (the turn on the spot) aborted'
    assert len(explorer.blacklist) == 0
    waiting = explorer.plan(grid, first.goal[:2], now=54.5, map_time=10.0)
    assert waiting.kind == WAIT and waiting.message == 'waiting for a map made after goal 1 was reached'
    judged = explorer.plan(grid, first.goal[:2], now=55.5, map_time=10.0)
    assert judged.note == ('goal 1 was reached but its frontier is still there (no newer map in 30 s): it is '
                           'given up on')
    assert judged.kind == SEND and judged.number == 3 and explorer.blacklist.strikes(first.goal[:2]) == 1


def test_a_newer_map_during_the_turn_judges_the_arrival_and_ends_the_turn():
    explorer = Explorer(OPTIONS)
    grid = only_the_east_opening()
    first = reach_the_east_opening_with_maps_every_5_s(explorer, grid)
    assert explorer.plan(grid, first.goal[:2], now=21.0, map_time=10.0).number == 2   # the turn
    # A map made after the arrival still has the east frontier: given up on once, then tried again as the
    # only one left, which replaces the turn.
    after = explorer.plan(grid, first.goal[:2], now=22.0, map_time=21.5)
    assert after.note == 'goal 1 was reached but its frontier is still there: it is given up on'
    assert after.kind == SEND and after.number == 3 and after.goal[:2] == first.goal[:2]
    assert explorer.finished(2, PREEMPTED, now=22.1) is None    # the turn's end is no longer ours
