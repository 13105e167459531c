"""How much of a maze an exploration has mapped, against the maze's wall geometry (numpy, no ROS),
and what an exploration rostest checks, as a unittest mixin.

The reachable free area is where the robot's body can be: the cells its centre reaches from the
start keeping its inscribed radius from every wall, grown by that radius, and never inside a wall.
A cell of it is explored when the map knows it (free or occupied)."""
import math

import numpy as np
from scipy import ndimage

from frontier_exploration.reachability import path_lengths


def wall_clearance(walls, xs, ys):
    """Distance (m) from each point to the nearest wall's outline; negative inside a wall."""
    best = np.full(np.shape(xs), np.inf)
    for w in walls:
        c, s = math.cos(w.yaw), math.sin(w.yaw)
        u = c * (xs - w.x) + s * (ys - w.y)
        v = -s * (xs - w.x) + c * (ys - w.y)
        du, dv = np.abs(u) - w.sx / 2, np.abs(v) - w.sy / 2
        outside = np.hypot(np.maximum(du, 0.0), np.maximum(dv, 0.0))
        inside = np.minimum(np.maximum(du, dv), 0.0)
        best = np.minimum(best, np.where((du > 0) | (dv > 0), outside, inside))
    return best


class ReachableArea:
    """The reachable free area (see the module's doc) on a grid of `resolution` over the walls' bounds."""

    def __init__(self, walls, inscribed_radius, start_xy, resolution=0.05):
        reach = max(math.hypot(w.sx, w.sy) / 2 for w in walls)
        self.x0 = min(w.x for w in walls) - reach
        self.y0 = min(w.y for w in walls) - reach
        nx = int(math.ceil((max(w.x for w in walls) + reach - self.x0) / resolution))
        ny = int(math.ceil((max(w.y for w in walls) + reach - self.y0) / resolution))
        self.resolution = resolution
        cols, rows = np.meshgrid(np.arange(nx), np.arange(ny))
        self.xs = self.x0 + (cols + 0.5) * resolution
        self.ys = self.y0 + (rows + 0.5) * resolution
        clearance = wall_clearance(walls, self.xs, self.ys)
        centre_ok = clearance >= inscribed_radius
        labels, _ = ndimage.label(centre_ok, structure=np.ones((3, 3), dtype=bool))
        start = (int((start_xy[1] - self.y0) / resolution), int((start_xy[0] - self.x0) / resolution))
        if not centre_ok[start]:
            raise ValueError('the start (%.2f, %.2f) is within %.2f m of a wall' % (start_xy[0], start_xy[1], inscribed_radius))
        centres = labels == labels[start]
        r = int(round(inscribed_radius / resolution))
        y, x = np.mgrid[-r:r + 1, -r:r + 1]
        self.mask = ndimage.binary_dilation(centres, structure=x * x + y * y <= r * r) & (clearance > 0)
        self.centres = centres

    @property
    def area(self):
        return float(self.mask.sum()) * self.resolution ** 2

    def explored_fraction(self, values, map_resolution, map_origin, map_in_world=(0.0, 0.0, 0.0)):
        """The fraction of the area a map knows. values[row, col] are the map's cells (-1 unknown),
        map_origin (x, y) its cell (0, 0) corner in the map frame (unrotated), map_in_world the map
        frame's pose in the world."""
        mx, my, myaw = map_in_world
        c, s = math.cos(myaw), math.sin(myaw)
        dx, dy = self.xs[self.mask] - mx, self.ys[self.mask] - my
        px, py = c * dx + s * dy, -s * dx + c * dy  # the area's cells in the map frame
        col = np.floor((px - map_origin[0]) / map_resolution).astype(int)
        row = np.floor((py - map_origin[1]) / map_resolution).astype(int)
        height, width = values.shape
        inside = (row >= 0) & (row < height) & (col >= 0) & (col < width)
        known = np.zeros(len(px), dtype=bool)
        known[inside] = values[row[inside], col[inside]] >= 0
        return float(known.mean()) if len(known) else 0.0


def visible_cells(area, walls_mask, x, y, max_range, rays=1440):
    """Mask of the area's cells a 360-degree laser at (x, y) sees within max_range: rays cast through
    the wall cells in steps of half a cell."""
    step = area.resolution / 2
    angles = np.linspace(0.0, 2 * math.pi, rays, endpoint=False)
    distances = np.arange(step, max_range, step)
    xs = x + np.outer(np.cos(angles), distances)
    ys = y + np.outer(np.sin(angles), distances)
    cols = np.floor((xs - area.x0) / area.resolution).astype(int)
    rows = np.floor((ys - area.y0) / area.resolution).astype(int)
    height, width = walls_mask.shape
    inside = (rows >= 0) & (rows < height) & (cols >= 0) & (cols < width)
    blocked = np.ones(rows.shape, dtype=bool)
    blocked[inside] = walls_mask[rows[inside], cols[inside]]
    # Each ray stops at its first wall (or the grid's edge).
    open_until = np.where(blocked.any(axis=1), blocked.argmax(axis=1), len(distances))
    seen = np.arange(len(distances))[None, :] < open_until[:, None]
    mask = np.zeros(walls_mask.shape, dtype=bool)
    mask[rows[seen], cols[seen]] = True
    return mask & area.mask


def best_tour(area, walls, start_xy, max_range, coverage=0.99, spacing=0.3):
    """A short path from the start that sees `coverage` of the area with a 360-degree laser of
    max_range: viewpoints chosen greedily (most unseen cells first) among the robot's reachable
    centres every `spacing` m, visited nearest-first and shortened by 2-opt, along shortest paths
    through the reachable centres. Returns (length m, [(x, y) of the viewpoints in order]).
    A reference for exploration runs, not a proven optimum."""
    walls_mask = wall_clearance(walls, area.xs, area.ys) <= 0
    k = max(1, int(round(spacing / area.resolution)))
    rows, cols = np.nonzero(area.centres)
    keep = (rows % k == 0) & (cols % k == 0)
    candidates = list(zip(rows[keep], cols[keep]))
    views = [visible_cells(area, walls_mask, area.xs[r, c], area.ys[r, c], max_range) for r, c in candidates]
    start = (int((start_xy[1] - area.y0) / area.resolution), int((start_xy[0] - area.x0) / area.resolution))
    seen = visible_cells(area, walls_mask, start_xy[0], start_xy[1], max_range)
    target = coverage * area.mask.sum()
    chosen = []
    while seen.sum() < target:
        gains = [int((v & ~seen).sum()) for v in views]
        best = int(np.argmax(gains))
        if gains[best] == 0:
            break
        chosen.append(candidates[best])
        seen |= views[best]
    if not chosen:
        return 0.0, []
    # Shortest paths between the start and the viewpoints, through the reachable centres.
    nodes = [start] + chosen
    lengths = path_lengths(area.centres, nodes, area.resolution)
    d = np.array([[lengths[i][n] for n in nodes] for i in range(len(nodes))])
    order = [0]
    left = set(range(1, len(nodes)))
    while left:
        nxt = min(left, key=lambda j: d[order[-1], j])
        order.append(nxt)
        left.remove(nxt)
    improved = True
    while improved:  # 2-opt on the open path (the start stays first)
        improved = False
        for i in range(1, len(order) - 1):
            for j in range(i + 1, len(order)):
                after = order[j + 1] if j + 1 < len(order) else None
                old = d[order[i - 1], order[i]] + (d[order[j], after] if after is not None else 0.0)
                new = d[order[i - 1], order[j]] + (d[order[i], after] if after is not None else 0.0)
                if new < old - 1e-9:
                    order[i:j + 1] = reversed(order[i:j + 1])
                    improved = True
    length = float(sum(d[a, b] for a, b in zip(order, order[1:])))
    return length, [(float(area.xs[nodes[i]]), float(area.ys[nodes[i]])) for i in order[1:]]
