"""Frontiers after Yamauchi (1997), as the Capstone lecture teaches them: a candidate cell is a free
cell with an unknown 8-neighbour, no occupied cell nearby, and at least min_distance from the
robot; candidates are clustered by 8-connectivity; each cluster is a frontier."""
import math
from dataclasses import dataclass

import numpy as np
from scipy import ndimage

EIGHT_CONNECTED = np.ones((3, 3), dtype=bool)


@dataclass
class FrontierOptions:
    min_distance: float = 0.5      # m (the lecture's alpha): candidates nearer the robot are left out
    clearance: float = 0.1         # m: no occupied cell within this of a candidate
    min_size: int = 1              # cells: smaller clusters are left out
    free_threshold: int = 25       # %: a known cell at most this occupied is free
    occupied_threshold: int = 65   # %: at least this is occupied (map_server's occupied_thresh)


@dataclass
class Frontier:
    rows: np.ndarray           # its cells
    cols: np.ndarray
    centroid: tuple            # world (x, y) of the cells' mean
    nearest: tuple             # world (x, y) of its cell nearest to the robot
    distance: float            # m from the robot to that cell, straight

    @property
    def size(self):
        return len(self.rows)


def disk(radius_cells):
    r = int(math.ceil(radius_cells))
    y, x = np.mgrid[-r:r + 1, -r:r + 1]
    return x * x + y * y <= radius_cells * radius_cells + 1e-9


def candidate_cells(grid, robot_xy, options):
    """The mask of frontier candidates (see the module's doc)."""
    free = grid.free(options.free_threshold)
    next_to_unknown = ndimage.binary_dilation(grid.unknown(), structure=EIGHT_CONNECTED)
    candidates = free & next_to_unknown
    occupied = grid.occupied(options.occupied_threshold)
    if options.clearance > 0 and occupied.any():
        candidates &= ~ndimage.binary_dilation(occupied, structure=disk(options.clearance / grid.resolution))
    if options.min_distance > 0:
        rows, cols = np.indices(candidates.shape)
        xs, ys = grid.cell_to_world(rows, cols)
        candidates &= np.hypot(xs - robot_xy[0], ys - robot_xy[1]) >= options.min_distance
    return candidates


def find_frontiers(grid, robot_xy, options=FrontierOptions()):
    """The frontiers, largest first."""
    labels, count = ndimage.label(candidate_cells(grid, robot_xy, options), structure=EIGHT_CONNECTED)
    if count == 0:
        return []
    frontiers = []
    order = np.argsort(labels, axis=None, kind='stable')
    flat = labels.ravel()[order]
    starts = np.searchsorted(flat, np.arange(1, count + 1))
    ends = np.append(starts[1:], len(flat))
    for start, end in zip(starts, ends):
        if end - start < options.min_size:
            continue
        rows, cols = np.unravel_index(order[start:end], labels.shape)
        xs, ys = grid.cell_to_world(rows, cols)
        d = np.hypot(xs - robot_xy[0], ys - robot_xy[1])
        k = int(np.argmin(d))
        frontiers.append(Frontier(rows=rows, cols=cols, centroid=(float(xs.mean()), float(ys.mean())),
                                  nearest=(float(xs[k]), float(ys[k])), distance=float(d[k])))
    frontiers.sort(key=lambda f: (-f.size, f.distance))
    return frontiers
