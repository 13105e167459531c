"""A goal for a frontier, and the blacklist of frontiers given up on.

A frontier's centroid (the lecture's goal) may lie in a wall, in unknown space or across a wall
from the frontier. The goal here is a reachable cell instead: a cell of the frontier itself when
the robot fits there, else the reachable cell first met going out from the frontier through free
space (never through walls or unknown space), at most `approach_radius` away; of those, the one
nearest the frontier's middle (its cell nearest the centroid)."""
import math

import numpy as np
from scipy import ndimage

EIGHT_CONNECTED = np.ones((3, 3), dtype=bool)


def middle_cell(frontier):
    """(row, col) of the frontier's cell nearest its centroid: a point on the frontier itself."""
    rows, cols = frontier.rows.astype(float), frontier.cols.astype(float)
    k = int(np.argmin(np.hypot(rows - rows.mean(), cols - cols.mean())))
    return int(frontier.rows[k]), int(frontier.cols[k])


def goal_cell(frontier, grid, reachable_mask, approach_radius, free_threshold=25):
    """(row, col) of the frontier's goal (see the module's doc), or None when no reachable cell is
    within approach_radius of it through free space."""
    middle = middle_cell(frontier)
    steps = int(math.ceil(approach_radius / grid.resolution))
    # Only the window the search can reach: maps are large, frontiers small.
    r0 = max(int(frontier.rows.min()) - steps - 1, 0)
    c0 = max(int(frontier.cols.min()) - steps - 1, 0)
    r1 = min(int(frontier.rows.max()) + steps + 2, grid.height)
    c1 = min(int(frontier.cols.max()) + steps + 2, grid.width)
    reachable = reachable_mask[r0:r1, c0:c1]
    passable = grid.free(free_threshold)[r0:r1, c0:c1]
    front = np.zeros_like(reachable)
    front[frontier.rows - r0, frontier.cols - c0] = True
    for _ in range(steps + 1):
        hits = front & reachable
        if hits.any():
            rows, cols = np.nonzero(hits)
            k = int(np.argmin(np.hypot(rows + r0 - middle[0], cols + c0 - middle[1])))
            return int(rows[k] + r0), int(cols[k] + c0)
        grown = ndimage.binary_dilation(front, structure=EIGHT_CONNECTED, mask=passable)
        if (grown == front).all():
            return None
        front = grown
    return None


class Blacklist:
    """Points (world x, y) given up on, with how many times. A frontier is on it when its middle is
    within `radius` of one: frontiers shift a little as the map grows, so an exact match
    (explore_lite's 5-cell box round the centroid) lets a dropped frontier come back, and the robot
    flip-flops."""

    def __init__(self, radius):
        self.radius = radius
        self.points = []  # [x, y, strikes]

    def add(self, xy):
        """One more strike for the point within radius of xy, or a new point with one."""
        for p in self.points:
            if math.hypot(xy[0] - p[0], xy[1] - p[1]) <= self.radius:
                p[2] += 1
                return
        self.points.append([float(xy[0]), float(xy[1]), 1])

    def strikes(self, xy):
        """How many times the frontier at xy was given up on (the most of the points near it)."""
        return max((p[2] for p in self.points if math.hypot(xy[0] - p[0], xy[1] - p[1]) <= self.radius), default=0)

    def contains(self, xy):
        return self.strikes(xy) > 0

    def clear(self):
        self.points = []

    def __len__(self):
        return len(self.points)
