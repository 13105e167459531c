"""frontier_exploration's grid and frontier search on small hand-made grids (no ROS)."""
import math
import os
import sys

import numpy as np
import pytest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..', 'src'))
from frontier_exploration.frontiers import FrontierOptions, candidate_cells, find_frontiers  # noqa: E402
from frontier_exploration.grid import Grid  # noqa: E402

U, F, O = -1, 0, 100  # unknown, free, occupied


def room_with_two_openings():
    """A 12 x 12 grid of 0.1 m cells at origin (-1, -2): walls round a free room (rows and columns
    0-9); unknown beyond a 4-cell opening in the east wall and a 2-cell opening in the north wall."""
    g = np.full((12, 12), U)
    g[1:9, 1:9] = F
    g[0, 0:10] = O
    g[9, 0:10] = O
    g[0:10, 0] = O
    g[0:10, 9] = O
    g[3:7, 9] = F   # east opening, rows 3-6
    g[9, 4:6] = F   # north opening, columns 4-5
    return Grid(g, 0.1, origin_x=-1.0, origin_y=-2.0)


def test_cells_map_to_the_world_through_the_messages_origin_and_resolution():
    grid = room_with_two_openings()
    assert grid.world_to_cell(-1.0 + 0.05, -2.0 + 0.05) == (0, 0)
    assert grid.world_to_cell(-1.0 + 1.15, -2.0 + 0.95) == (9, 11)  # both axes bounded by their own size
    assert grid.world_to_cell(-1.0 + 1.25, -2.0 + 0.5) is None
    assert grid.world_to_cell(-1.0 + 0.5, -2.0 + 1.25) is None
    x, y = grid.cell_to_world(9, 11)
    assert (x, y) == pytest.approx((0.15, -1.05))


def test_a_turned_origin_is_honoured():
    grid = Grid(np.zeros((4, 6)), 0.5, origin_x=1.0, origin_y=2.0, origin_yaw=math.pi / 2)
    x, y = grid.cell_to_world(0, 0)  # the cell's centre is 0.25 m along the turned x and y axes
    assert (x, y) == pytest.approx((0.75, 2.25))
    assert grid.world_to_cell(x, y) == (0, 0)


def test_bad_grids_are_refused_with_the_field_named():
    with pytest.raises(ValueError, match='resolution'):
        Grid(np.zeros((2, 2)), 0.0)
    with pytest.raises(ValueError, match='width x height'):
        Grid.from_flat([0] * 5, 2, 3, 0.05)


def test_the_two_openings_are_two_frontiers_the_larger_first():
    grid = room_with_two_openings()
    frontiers = find_frontiers(grid, (-0.5, -1.5), FrontierOptions(min_distance=0.0, clearance=0.0))
    assert [f.size for f in frontiers] == [4, 2]
    east, north = frontiers
    assert sorted(set(east.cols.tolist())) == [9] and sorted(east.rows.tolist()) == [3, 4, 5, 6]
    assert sorted(set(north.rows.tolist())) == [9] and sorted(north.cols.tolist()) == [4, 5]
    assert east.centroid == pytest.approx((-1.0 + 0.95, -2.0 + 0.5))


def test_cells_next_to_a_wall_are_not_candidates():
    # With 0.1 m clearance, the opening's end cells (beside the wall cells) drop out.
    grid = room_with_two_openings()
    frontiers = find_frontiers(grid, (-0.5, -1.5), FrontierOptions(min_distance=0.0, clearance=0.1))
    assert [f.size for f in frontiers] == [2]
    assert sorted(frontiers[0].rows.tolist()) == [4, 5]


def test_cells_within_min_distance_of_the_robot_are_not_candidates():
    grid = room_with_two_openings()
    east_cell = grid.cell_to_world(4, 9)
    near = find_frontiers(grid, east_cell, FrontierOptions(min_distance=0.5, clearance=0.0))
    assert [f.size for f in near] == [2]  # the east opening is within 0.5 m; the north one is not
    mask = candidate_cells(grid, east_cell, FrontierOptions(min_distance=0.5, clearance=0.0))
    assert not mask[3:7, 9].any()


def test_a_closed_room_has_no_frontier():
    g = np.full((6, 6), O)
    g[1:5, 1:5] = F
    assert find_frontiers(Grid(g, 0.05), (0.15, 0.15), FrontierOptions(min_distance=0.0)) == []


def test_min_size_drops_small_clusters():
    grid = room_with_two_openings()
    frontiers = find_frontiers(grid, (-0.5, -1.5), FrontierOptions(min_distance=0.0, clearance=0.0, min_size=3))
    assert [f.size for f in frontiers] == [4]
