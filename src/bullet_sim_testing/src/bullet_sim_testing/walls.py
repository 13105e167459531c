"""Ground-truth laser ranges in a 2D world of box walls (pure Python, no ROS).

A wall is a box seen from above: centre (x, y), size (sx, sy) and yaw. Mazes list theirs in a
yaml file that matches their model.sdf: {walls: [{x, y, size_x, size_y, yaw}, ...]} (sx, sy
also accepted), in the world frame, or in the model frame with the model's world pose given as
model_pose_in_world: {x, y, yaw}."""
import math

import yaml


class Wall:
    def __init__(self, x, y, sx, sy, yaw=0.0):
        self.x, self.y, self.sx, self.sy, self.yaw = x, y, sx, sy, yaw

    def ray_distance(self, ox, oy, dx, dy):
        """Distance along the unit ray (ox, oy) + t (dx, dy) to this box, or None if it misses."""
        c, s = math.cos(self.yaw), math.sin(self.yaw)
        # The ray in the box's frame.
        px, py = c * (ox - self.x) + s * (oy - self.y), -s * (ox - self.x) + c * (oy - self.y)
        vx, vy = c * dx + s * dy, -s * dx + c * dy
        t_near, t_far = -math.inf, math.inf
        for p, v, half in ((px, vx, self.sx / 2), (py, vy, self.sy / 2)):
            if abs(v) < 1e-12:
                if abs(p) > half:
                    return None
                continue
            t1, t2 = (-half - p) / v, (half - p) / v
            t_near, t_far = max(t_near, min(t1, t2)), min(t_far, max(t1, t2))
        if t_near > t_far or t_far < 0:
            return None
        return max(t_near, 0.0)

    def distance(self, px, py):
        """Distance from (px, py) to the box's outline (inside or out), e.g. a map cell to the wall face."""
        c, s = math.cos(self.yaw), math.sin(self.yaw)
        u, v = c * (px - self.x) + s * (py - self.y), -s * (px - self.x) + c * (py - self.y)
        du, dv = abs(u) - self.sx / 2, abs(v) - self.sy / 2
        if du > 0 or dv > 0:
            return math.hypot(max(du, 0.0), max(dv, 0.0))
        return -max(du, dv)

    def contains(self, px, py):
        """Whether (px, py) is inside the box (on its outline counts)."""
        c, s = math.cos(self.yaw), math.sin(self.yaw)
        u, v = c * (px - self.x) + s * (py - self.y), -s * (px - self.x) + c * (py - self.y)
        return abs(u) <= self.sx / 2 and abs(v) <= self.sy / 2


def load_walls(path):
    """The walls of a maze yaml, in the world frame."""
    with open(path) as f:
        data = yaml.safe_load(f)
    pose = data.get('model_pose_in_world', {})
    mx, my, myaw = pose.get('x', 0.0), pose.get('y', 0.0), pose.get('yaw', 0.0)
    c, s = math.cos(myaw), math.sin(myaw)
    walls = []
    for w in data['walls']:
        sx, sy = w.get('size_x', w.get('sx')), w.get('size_y', w.get('sy'))
        walls.append(Wall(mx + c * w['x'] - s * w['y'], my + s * w['x'] + c * w['y'], sx, sy,
                          myaw + w.get('yaw', 0.0)))
    return walls


def nearest_wall(walls, x, y, heading):
    """(distance, index of the wall hit) from (x, y) along heading; (inf, None) if none."""
    dx, dy = math.cos(heading), math.sin(heading)
    best = (math.inf, None)
    for i, w in enumerate(walls):
        d = w.ray_distance(x, y, dx, dy)
        if d is not None and d < best[0]:
            best = (d, i)
    return best


def expected_range(walls, x, y, heading):
    """Distance from (x, y) along heading to the nearest wall, or inf."""
    return nearest_wall(walls, x, y, heading)[0]


def compare_scan(walls, x, y, yaw, scan, max_error, edge_angle=0.01):
    """Per-beam comparison of a LaserScan-like object with the wall geometry.

    Beams within edge_angle (rad) of a wall's end or corner (the wall hit changes when the
    heading moves that much) are skipped: there the answer hangs on the exact pose.
    Returns (errors of compared beams, number of out-of-range beams checked, list of failures)."""
    errors, beyond, failures = [], 0, []
    for i, measured in enumerate(scan.ranges):
        heading = yaw + scan.angle_min + i * scan.angle_increment
        expected, wall = nearest_wall(walls, x, y, heading)
        if any(nearest_wall(walls, x, y, heading + d)[1] != wall for d in (-edge_angle, edge_angle)):
            continue
        if expected > scan.range_max + 3 * max_error:
            beyond += 1
            if measured != math.inf:
                failures.append((i, expected, measured))
        elif scan.range_min + 3 * max_error < expected < scan.range_max - 3 * max_error:
            errors.append(measured - expected)
            if not abs(measured - expected) <= max_error:
                failures.append((i, expected, measured))
    return errors, beyond, failures
