"""An occupancy grid as nav_msgs/OccupancyGrid holds it, without ROS: values -1 (unknown) and
0..100 (occupancy in %), row-major from the origin cell; the origin and resolution come from the
message (never assumed)."""
import math

import numpy as np

UNKNOWN = -1


class Grid:
    """values[row, col] is the cell at column col (x) and row row (y) from the origin; the origin is
    the world pose of cell (0, 0)'s outer corner, as in nav_msgs/MapMetaData."""

    def __init__(self, values, resolution, origin_x=0.0, origin_y=0.0, origin_yaw=0.0):
        values = np.asarray(values, dtype=np.int16)
        if values.ndim != 2:
            raise ValueError('grid: expected a 2-D array of cell values, got shape %s' % (values.shape,))
        if not (resolution > 0 and math.isfinite(resolution)):
            raise ValueError('grid: resolution: expected a number > 0, got %r' % resolution)
        self.values = values
        self.resolution = float(resolution)
        self.origin_x, self.origin_y, self.origin_yaw = float(origin_x), float(origin_y), float(origin_yaw)

    @classmethod
    def from_flat(cls, data, width, height, resolution, origin_x=0.0, origin_y=0.0, origin_yaw=0.0):
        """From an OccupancyGrid's data list (width * height values, row-major)."""
        if width * height != len(data):
            raise ValueError('grid: data has %d values where width x height is %d x %d = %d'
                             % (len(data), width, height, width * height))
        return cls(np.asarray(data, dtype=np.int16).reshape(height, width), resolution, origin_x, origin_y, origin_yaw)

    @property
    def height(self):
        return self.values.shape[0]

    @property
    def width(self):
        return self.values.shape[1]

    def unknown(self):
        return self.values < 0

    def free(self, free_threshold):
        """Known cells with occupancy at most free_threshold (%)."""
        return (self.values >= 0) & (self.values <= free_threshold)

    def occupied(self, occupied_threshold):
        return self.values >= occupied_threshold

    def world_to_cell(self, x, y):
        """(row, col) of the cell holding world point (x, y), or None off the grid."""
        c, s = math.cos(self.origin_yaw), math.sin(self.origin_yaw)
        dx, dy = x - self.origin_x, y - self.origin_y
        col = math.floor((c * dx + s * dy) / self.resolution)
        row = math.floor((-s * dx + c * dy) / self.resolution)
        if 0 <= row < self.height and 0 <= col < self.width:
            return row, col
        return None

    def cell_to_world(self, row, col):
        """The world position of a cell's centre (row and col may be arrays)."""
        u = (np.asarray(col, dtype=float) + 0.5) * self.resolution
        v = (np.asarray(row, dtype=float) + 0.5) * self.resolution
        c, s = math.cos(self.origin_yaw), math.sin(self.origin_yaw)
        return self.origin_x + c * u - s * v, self.origin_y + s * u + c * v

    def cropped_to_known(self, margin=2):
        """The smallest sub-grid holding every known cell plus `margin` cells round it (origin moved
        to match), or self when nothing is known. Maps are mostly unknown at first; the searches
        then work on the part that matters."""
        rows, cols = np.nonzero(self.values >= 0)
        if len(rows) == 0:
            return self
        r0, r1 = max(int(rows.min()) - margin, 0), min(int(rows.max()) + margin + 1, self.height)
        c0, c1 = max(int(cols.min()) - margin, 0), min(int(cols.max()) + margin + 1, self.width)
        if (r0, c0, r1, c1) == (0, 0, self.height, self.width):
            return self
        c, s = math.cos(self.origin_yaw), math.sin(self.origin_yaw)
        u, v = c0 * self.resolution, r0 * self.resolution
        return Grid(self.values[r0:r1, c0:c1], self.resolution, self.origin_x + c * u - s * v,
                    self.origin_y + s * u + c * v, self.origin_yaw)


def yaw_of_quaternion(q):
    """The rotation about z of a quaternion with x, y, z, w (the map origin's yaw)."""
    return math.atan2(2.0 * (q.w * q.z + q.x * q.y), 1.0 - 2.0 * (q.y * q.y + q.z * q.z))
