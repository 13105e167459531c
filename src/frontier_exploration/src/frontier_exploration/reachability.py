"""Where the robot can go on an occupancy grid: the known free cells at least `clearance` from every
occupied cell, 8-connected to the robot, and how far each is by the shortest such path.

Unknown cells are not entered: a goal must be reachable through space the map has seen, so that
it is never inside a wall the laser has not yet found."""
import math
from dataclasses import dataclass

import numpy as np
from scipy import ndimage
from scipy.sparse import coo_matrix
from scipy.sparse.csgraph import dijkstra

EIGHT_CONNECTED = np.ones((3, 3), dtype=bool)


@dataclass
class Reachable:
    mask: np.ndarray        # [row, col] of the whole grid: reachable cells
    distance: np.ndarray    # [row, col]: path length (m) from the robot, inf where not reachable
    start: tuple            # (row, col) of the cell the paths start from (the robot's, or its nearest)


def clear_cells(grid, clearance, free_threshold, occupied_threshold):
    """Known free cells whose centre is at least `clearance` (m) from every occupied cell's centre."""
    free = grid.free(free_threshold)
    occupied = grid.occupied(occupied_threshold)
    if clearance <= 0 or not occupied.any():
        return free
    distance = ndimage.distance_transform_edt(~occupied) * grid.resolution
    return free & (distance >= clearance)


def seen_round(grid, radius):
    """Cells with no unknown cell within `radius` (m) of their centre."""
    unknown = grid.unknown()
    if not unknown.any():
        return np.ones(unknown.shape, dtype=bool)
    return ndimage.distance_transform_edt(~unknown) * grid.resolution > radius


def reachable_cells(grid, robot_xy, clearance, free_threshold=25, occupied_threshold=65):
    """The cells the robot reaches (see the module's doc), or None when the robot is off the grid or
    no clear cell lies within clearance + 2 cells of it (boxed in, or standing in unknown space)."""
    robot = grid.world_to_cell(*robot_xy)
    if robot is None:
        return None
    clear = clear_cells(grid, clearance, free_threshold, occupied_threshold)
    start = _nearest_clear_cell(grid, clear, robot, clearance + 2 * grid.resolution)
    if start is None:
        return None
    labels, _ = ndimage.label(clear, structure=EIGHT_CONNECTED)
    mask = labels == labels[start]
    return Reachable(mask=mask, distance=path_lengths(mask, [start], grid.resolution)[0], start=start)


def _nearest_clear_cell(grid, clear, cell, radius):
    """The clear cell nearest `cell` within `radius` (m), or None. The robot may stand nearer a wall
    than the clearance; its paths then start from the nearest cell that has it."""
    if clear[cell]:
        return cell
    r = int(math.ceil(radius / grid.resolution))
    r0, c0 = max(cell[0] - r, 0), max(cell[1] - r, 0)
    window = clear[r0:cell[0] + r + 1, c0:cell[1] + r + 1]
    rows, cols = np.nonzero(window)
    if len(rows) == 0:
        return None
    d = np.hypot(rows + r0 - cell[0], cols + c0 - cell[1])
    k = int(np.argmin(d))
    if d[k] * grid.resolution > radius:
        return None
    return int(rows[k] + r0), int(cols[k] + c0)


def path_lengths(mask, sources, resolution):
    """Shortest 8-connected path lengths (m) through `mask` from each (row, col) of `sources`:
    one [row, col] array per source, inf where the path cannot go."""
    rows, cols = np.nonzero(mask)
    index = np.full(mask.shape, -1, dtype=np.int64)
    index[rows, cols] = np.arange(len(rows))
    tails, heads, weights = [], [], []  # the graph's edges
    height, width = mask.shape
    for dr, dc, step in ((0, 1, 1.0), (1, 0, 1.0), (1, 1, math.sqrt(2)), (1, -1, math.sqrt(2))):
        r2, c2 = rows + dr, cols + dc
        inside = (r2 < height) & (c2 >= 0) & (c2 < width)
        a = index[rows[inside], cols[inside]]
        b = index[r2[inside], c2[inside]]
        linked = b >= 0
        tails.append(a[linked])
        heads.append(b[linked])
        weights.append(np.full(int(linked.sum()), step * resolution))
    n = len(rows)
    graph = coo_matrix((np.concatenate(weights), (np.concatenate(tails), np.concatenate(heads))),
                       shape=(n, n)).tocsr()
    lengths = np.atleast_2d(dijkstra(graph, directed=False, indices=[int(index[s]) for s in sources]))
    distance = np.full((len(sources),) + mask.shape, np.inf)
    distance[:, rows, cols] = lengths
    return distance
