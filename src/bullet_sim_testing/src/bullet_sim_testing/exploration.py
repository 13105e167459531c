"""How much of a maze an exploration has mapped, against the maze's wall geometry (numpy, no ROS),
and what an exploration rostest checks, as a unittest mixin.

The reachable free area is where the robot's body can be: the cells its centre reaches from the
start keeping its inscribed radius from every wall, grown by that radius, and never inside a wall.
A cell of it is explored when the map knows it (free or occupied)."""
import math

import numpy as np
from scipy import ndimage


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
