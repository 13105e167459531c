"""The pioneer maze: the walls' yaml agrees exactly with models/pioneer_maze/model.sdf, the
maze is what its comments promise (8 x 8 m, corridors >= 1.2 m, every cell reachable, the
spawn spot free), and the ray geometry that tests use as ground truth (no ROS master needed)."""
import math
import os
import re
import sys
import xml.etree.ElementTree as ET

import pytest

PACKAGE = os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..')
sys.path.insert(0, os.path.join(PACKAGE, 'src'))

from pioneer_gazebo.maze_walls import (Wall, clearance, load_maze, maze_from_dict, model_sdf,  # noqa: E402
                                    ray_distance, ray_hit, scan_ranges)

WALLS_YAML = os.path.join(PACKAGE, 'config', 'pioneer_maze_walls.yaml')
MODEL_SDF = os.path.join(PACKAGE, 'models', 'pioneer_maze', 'model.sdf')
WORLD = os.path.join(PACKAGE, 'worlds', 'pioneer_maze.world')
LAUNCH = os.path.join(PACKAGE, 'launch', 'pioneer_world.launch')
ROBOT_RADIUS = 0.27  # the Pioneer 3-DX's swing radius (m)


@pytest.fixture(scope='module')
def maze():
    return load_maze(WALLS_YAML)


def test_model_sdf_is_the_one_the_yaml_writes(maze):
    with open(MODEL_SDF) as f:
        assert f.read() == model_sdf(maze), 'run scripts/write_maze_model after editing the yaml'


def test_model_sdf_boxes_match_the_yaml(maze):
    model = ET.parse(MODEL_SDF).getroot().find('model')
    assert model.get('name') == maze.model_name
    assert model.find('static').text == 'true'
    links = model.findall('link')
    assert len(links) == 1 and links[0].find('pose') is None  # wall poses are model (= world) poses
    collisions = links[0].findall('collision')
    assert [c.get('name') for c in collisions] == [w.name for w in maze.walls]
    for c, w in zip(collisions, maze.walls):
        x, y, z, roll, pitch, yaw = (float(v) for v in c.find('pose').text.split())
        sx, sy, sz = (float(v) for v in c.find('geometry/box/size').text.split())
        assert (x, y, z, roll, pitch, yaw) == (w.x, w.y, maze.height / 2, 0.0, 0.0, w.yaw)
        assert (sx, sy, sz) == (w.size_x, w.size_y, maze.height)


def test_world_includes_the_model_at_the_origin(maze):
    world = ET.parse(WORLD).getroot().find('world')
    includes = {i.find('uri').text: i for i in world.findall('include')}
    assert set(includes) == {'model://ground_plane', 'model://sun', 'model://' + maze.model_name}
    pose = includes['model://' + maze.model_name].find('pose').text.split()
    assert [float(v) for v in pose] == [0.0] * 6


def test_maze_is_8_by_8_metres_and_closed(maze):
    xs = [w.x + s * w.size_x / 2 for w in maze.walls for s in (-1, 1)]
    ys = [w.y + s * w.size_y / 2 for w in maze.walls for s in (-1, 1)]
    assert min(xs) == pytest.approx(-4.075) and max(xs) == pytest.approx(4.075)
    assert min(ys) == pytest.approx(-4.075) and max(ys) == pytest.approx(4.075)
    # From anywhere inside, every direction hits a wall.
    for heading in [k * math.pi / 36 for k in range(72)]:
        assert ray_distance(maze.walls, 0.0, 0.0, heading) < 6.0


CELLS = [-3.2, -1.6, 0.0, 1.6, 3.2]


def test_corridors_are_at_least_1_2_m_wide(maze):
    # Every cell centre sees at least 0.6 m to any wall, and the gap between two wall faces
    # across a cell is 1.45 m.
    for x in CELLS:
        for y in CELLS:
            assert clearance(maze.walls, x, y) >= 0.6
    assert ray_distance(maze.walls, -3.2, -3.2, math.pi / 2) + ray_distance(maze.walls, -3.2, -3.2, -math.pi / 2) \
        == pytest.approx(1.45)


def test_every_cell_is_reachable(maze):
    def open_between(a, b):
        # A passage: the straight line between the two cell centres crosses no wall.
        (x0, y0), (x1, y1) = a, b
        return ray_distance(maze.walls, x0, y0, math.atan2(y1 - y0, x1 - x0)) > math.hypot(x1 - x0, y1 - y0)

    start = (CELLS[0], CELLS[0])
    seen, frontier = {start}, [start]
    while frontier:
        x, y = frontier.pop()
        for dx, dy in ((1.6, 0), (-1.6, 0), (0, 1.6), (0, -1.6)):
            n = (round(x + dx, 3), round(y + dy, 3))
            if n[0] in CELLS and n[1] in CELLS and n not in seen and open_between((x, y), n):
                seen.add(n)
                frontier.append(n)
    assert len(seen) == 25


def test_the_launch_files_spawn_spot_is_free(maze):
    with open(LAUNCH) as f:
        text = f.read()
    default = {k: float(re.search(r'<arg name="%s" default="([^"]+)"' % k, text).group(1)) for k in ('x', 'y')}
    assert clearance(maze.walls, default['x'], default['y']) > ROBOT_RADIUS + 0.3


def test_ray_hits_an_axis_aligned_box():
    wall = Wall('w', 2.0, 0.0, 0.2, 1.0, 0.0)
    assert ray_hit(wall, 0.0, 0.0, 0.0) == pytest.approx(1.9)
    assert ray_hit(wall, 0.0, 0.0, math.pi) == math.inf
    assert ray_hit(wall, 0.0, 0.0, math.atan2(0.5, 1.9)) == pytest.approx(math.hypot(1.9, 0.5))
    assert ray_hit(wall, 0.0, 0.0, math.atan2(0.6, 1.9)) == math.inf
    assert ray_hit(wall, 0.0, 0.6, 0.0) == math.inf  # parallel, beside it
    assert ray_hit(wall, 2.0, 0.0, 1.0) == 0.0       # inside


def test_ray_hits_a_rotated_box():
    wall = Wall('w', 0.0, 3.0, 6.0, 0.2, math.pi / 4)  # a diagonal wall
    # Its lower face is the line through (0, 3 - 0.1 * sqrt(2)) at 45 degrees.
    assert ray_hit(wall, 0.0, 0.0, math.pi / 2) == pytest.approx(3.0 - 0.1 * math.sqrt(2))
    assert clearance([wall], 0.0, 0.0) == pytest.approx(3.0 * math.sqrt(0.5) - 0.1)


def test_scan_ranges_follow_laser_scan_angles(maze):
    ranges = scan_ranges(maze.walls, -3.2, -3.2, 0.0, -math.pi, 2 * math.pi / 719, 720)
    assert len(ranges) == 720
    assert ranges[0] == pytest.approx(0.725)      # behind: outer_west's face at x = -3.925
    # Ahead: wall_03's face at x = 0.725; beam 360 points pi / 719 to the left of straight ahead.
    assert ranges[360] == pytest.approx(3.925 / math.cos(math.pi / 719))
    # Facing north, the same beams turn by 90 degrees.
    north = scan_ranges(maze.walls, -3.2, -3.2, math.pi / 2, -math.pi, 2 * math.pi / 719, 720)
    assert north[360] == pytest.approx(0.725, abs=1e-3)  # wall_06's face at y = -2.475


@pytest.mark.parametrize('data,match', [
    ({'height': 0, 'walls': [{'name': 'a', 'x': 0, 'y': 0, 'size_x': 1, 'size_y': 1, 'yaw': 0}]}, 'height'),
    ({'height': 1, 'walls': [{'name': 'a', 'x': 0, 'y': 0, 'size_x': 1, 'yaw': 0}]}, r'walls\[0\]: missing size_y'),
    ({'height': 1, 'walls': [{'name': 'a', 'x': 0, 'y': 0, 'size_x': -1, 'size_y': 1, 'yaw': 0}]}, 'positive'),
    ({'height': 1, 'walls': []}, 'at least one'),
    ({'height': 1, 'walls': [{'name': 'a', 'x': 0, 'y': 0, 'size_x': 1, 'size_y': 1, 'yaw': 0}] * 2}, 'duplicate'),
])
def test_bad_wall_lists_are_refused(data, match):
    with pytest.raises(ValueError, match=match):
        maze_from_dict(data)
