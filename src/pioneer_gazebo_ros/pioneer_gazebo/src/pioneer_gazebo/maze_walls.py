"""The pioneer maze's walls as plain data: loading config/pioneer_maze_walls.yaml, writing the
model's SDF from it, and the 2D geometry tests need (ray distances, clearance). No ROS.

A wall is a box standing on the floor: centre (x, y), footprint size_x * size_y before a yaw
about its centre, and the maze's height. Horizontal laser beams above the floor and below the
walls' tops see exactly the 2D footprints, which is what ray_distance() intersects.
"""
import math
from collections import namedtuple

import yaml

Wall = namedtuple('Wall', 'name x y size_x size_y yaw')
Maze = namedtuple('Maze', 'model_name height walls')

WALL_KEYS = ('name', 'x', 'y', 'size_x', 'size_y', 'yaw')


def maze_from_dict(data):
    """A Maze from the yaml's dictionary; ValueError naming the field that is wrong."""
    if not isinstance(data, dict):
        raise ValueError('expected a mapping with model_name, height and walls')
    height = float(data.get('height', 0.0))
    if not height > 0.0:
        raise ValueError('height: expected a positive number of metres, got %r' % data.get('height'))
    walls = []
    for i, entry in enumerate(data.get('walls') or []):
        missing = [k for k in WALL_KEYS if k not in entry]
        if missing:
            raise ValueError('walls[%d]: missing %s' % (i, ', '.join(missing)))
        wall = Wall(str(entry['name']), *(float(entry[k]) for k in WALL_KEYS[1:]))
        if not (wall.size_x > 0.0 and wall.size_y > 0.0):
            raise ValueError('walls[%d] (%s): expected positive size_x and size_y' % (i, wall.name))
        walls.append(wall)
    if not walls:
        raise ValueError('walls: expected at least one wall')
    names = [w.name for w in walls]
    duplicates = sorted({n for n in names if names.count(n) > 1})
    if duplicates:
        raise ValueError('walls: duplicate names %s' % ', '.join(duplicates))
    return Maze(str(data.get('model_name', 'pioneer_maze')), height, walls)


def load_maze(path):
    with open(path) as f:
        return maze_from_dict(yaml.safe_load(f))


def _number(value):
    """Shortest text that reads back as the same float (0.15, -4, 8.15)."""
    text = repr(float(value))
    return text[:-2] if text.endswith('.0') else text


def model_sdf(maze):
    """The static SDF model of the maze: one link, a collision and a visual per wall."""
    lines = [
        '<?xml version="1.0"?>',
        '<!-- Written by pioneer_gazebo/scripts/write_maze_model from config/pioneer_maze_walls.yaml;',
        '     edit that file and run the script again rather than editing this one. -->',
        '<sdf version="1.6">',
        '  <model name="%s">' % maze.model_name,
        '    <static>true</static>',
        '    <link name="walls">',
    ]
    for w in maze.walls:
        pose = ' '.join(_number(v) for v in (w.x, w.y, maze.height / 2.0, 0.0, 0.0, w.yaw))
        size = ' '.join(_number(v) for v in (w.size_x, w.size_y, maze.height))
        geometry = '<geometry><box><size>%s</size></box></geometry>' % size
        lines += [
            '      <collision name="%s">' % w.name,
            '        <pose>%s</pose>' % pose,
            '        %s' % geometry,
            '      </collision>',
            '      <visual name="%s">' % w.name,
            '        <pose>%s</pose>' % pose,
            '        %s' % geometry,
            '        <material><ambient>0.6 0.6 0.6 1</ambient><diffuse>0.7 0.7 0.7 1</diffuse></material>',
            '      </visual>',
        ]
    lines += ['    </link>', '  </model>', '</sdf>', '']
    return '\n'.join(lines)


def _to_wall_frame(wall, x, y):
    c, s = math.cos(wall.yaw), math.sin(wall.yaw)
    dx, dy = x - wall.x, y - wall.y
    return c * dx + s * dy, -s * dx + c * dy


def ray_hit(wall, x, y, heading):
    """Distance along the ray from (x, y) in direction heading to the wall's footprint:
    0 when the point is inside it, math.inf when the ray misses it."""
    px, py = _to_wall_frame(wall, x, y)
    dx, dy = math.cos(heading - wall.yaw), math.sin(heading - wall.yaw)
    t_near, t_far = -math.inf, math.inf
    for p, d, half in ((px, dx, wall.size_x / 2.0), (py, dy, wall.size_y / 2.0)):
        if abs(d) < 1e-12:
            if abs(p) > half:
                return math.inf  # parallel to this slab and outside it
            continue
        t0, t1 = sorted(((-half - p) / d, (half - p) / d))
        t_near, t_far = max(t_near, t0), min(t_far, t1)
    if t_near > t_far or t_far < 0.0:
        return math.inf
    return max(t_near, 0.0)


def ray_distance(walls, x, y, heading):
    """Distance from (x, y) along heading to the nearest wall (math.inf if none)."""
    return min((ray_hit(w, x, y, heading) for w in walls), default=math.inf)


def scan_ranges(walls, x, y, yaw, angle_min, angle_increment, count):
    """Noise-free ranges of a horizontal scanner at (x, y) facing yaw: beam i points at
    yaw + angle_min + i * angle_increment (sensor_msgs/LaserScan's convention)."""
    return [ray_distance(walls, x, y, yaw + angle_min + i * angle_increment) for i in range(count)]


def clearance(walls, x, y):
    """Distance from (x, y) to the nearest wall footprint; 0 inside a wall."""
    best = math.inf
    for w in walls:
        px, py = _to_wall_frame(w, x, y)
        ex, ey = max(abs(px) - w.size_x / 2.0, 0.0), max(abs(py) - w.size_y / 2.0, 0.0)
        best = min(best, math.hypot(ex, ey))
    return best
