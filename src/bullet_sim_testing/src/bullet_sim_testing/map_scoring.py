"""How well a mapper did, against ground truth: poses (compose, relative, interpolate in time) and a
map's occupied cells against the walls it should show (map_alignment). Pure Python, no ROS."""
import bisect
import math

import numpy as np


def angle_diff(a, b):
    """a - b wrapped to [-pi, pi]."""
    return math.atan2(math.sin(a - b), math.cos(a - b))


def compose(a, b):
    """Pose b (x, y, yaw) given in frame a, in a's parent frame."""
    c, s = math.cos(a[2]), math.sin(a[2])
    return a[0] + c * b[0] - s * b[1], a[1] + s * b[0] + c * b[1], a[2] + b[2]


def relative(a, b):
    """Pose b (parent frame) in frame a."""
    c, s = math.cos(a[2]), math.sin(a[2])
    dx, dy = b[0] - a[0], b[1] - a[1]
    return c * dx + s * dy, -s * dx + c * dy, angle_diff(b[2], a[2])


def interpolate(samples, t, max_gap=0.25):
    """The (x, y, yaw) at sim time t from samples [(t, x, y, yaw)] sorted by t; None outside or across a gap."""
    i = bisect.bisect_left([s[0] for s in samples], t)
    if i == 0 or i == len(samples):
        return None
    (t0, *p0), (t1, *p1) = samples[i - 1], samples[i]
    if t1 - t0 > max_gap:
        return None
    f = (t - t0) / (t1 - t0) if t1 > t0 else 0.0
    return (p0[0] + f * (p1[0] - p0[0]), p0[1] + f * (p1[1] - p0[1]), p0[2] + f * angle_diff(p1[2], p0[2]))


def map_alignment(walls, points, seen_from, max_range, tolerance=0.1, spacing=0.05):
    """How a map's occupied cells (world frame, N x 2) line up with the walls.

    A wall is a box seen from above with x, y, sx, sy, yaw, distance(px, py) to its outline and
    ray_distance(ox, oy, dx, dy) along a unit ray (None if it misses), like bullet_sim_testing's Wall.

    Returns (precision, mean distance, coverage): the fraction of occupied cells within `tolerance`
    of a wall's outline, their mean distance to it, and the fraction of the wall faces the robot could
    see (from any of the positions `seen_from`, within max_range, nothing in between) that have an
    occupied cell within `tolerance`."""
    distances = np.array([min(w.distance(x, y) for w in walls) for x, y in points])
    faces = []
    for w in walls:
        c, s = math.cos(w.yaw), math.sin(w.yaw)
        for (u0, v0), (u1, v1) in _outline(w.sx / 2, w.sy / 2):
            n = max(int(math.hypot(u1 - u0, v1 - v0) / spacing), 1)
            for k in range(n):
                u, v = u0 + (u1 - u0) * (k + 0.5) / n, v0 + (v1 - v0) * (k + 0.5) / n
                faces.append((w.x + c * u - s * v, w.y + s * u + c * v))
    visible = []
    for fx, fy in faces:
        for px, py in seen_from:
            d = math.hypot(fx - px, fy - py)
            if d > max_range:
                continue
            if abs(_first_hit(walls, px, py, (fx - px) / d, (fy - py) / d) - d) < 0.01:
                visible.append((fx, fy))
                break
    covered = 0
    if len(points) and visible:
        pts = np.asarray(points)
        covered = sum(1 for fx, fy in visible if np.min(np.hypot(pts[:, 0] - fx, pts[:, 1] - fy)) <= tolerance)
    precision = float(np.mean(distances <= tolerance)) if len(distances) else 0.0
    mean = float(distances.mean()) if len(distances) else math.inf
    return precision, mean, (covered / len(visible) if visible else 0.0)


def _first_hit(walls, x, y, dx, dy):
    """Distance from (x, y) along the unit direction (dx, dy) to the nearest wall, or inf."""
    hits = [d for d in (w.ray_distance(x, y, dx, dy) for w in walls) if d is not None]
    return min(hits) if hits else math.inf


def _outline(hx, hy):
    corners = [(-hx, -hy), (hx, -hy), (hx, hy), (-hx, hy)]
    return [(corners[i], corners[(i + 1) % 4]) for i in range(4)]
