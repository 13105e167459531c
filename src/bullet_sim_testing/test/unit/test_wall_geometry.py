"""bullet_sim_testing.walls: the ground truth the robots' laser tests rely on."""
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(__file__), '..', '..', 'src'))
from bullet_sim_testing.walls import Wall, compare_scan, expected_range, load_walls  # noqa: E402


def test_ray_hits_the_near_face_of_an_axis_aligned_wall():
    wall = Wall(2.0, 0.0, 0.2, 4.0)
    assert math.isclose(wall.ray_distance(0, 0, 1, 0), 1.9)
    assert wall.ray_distance(0, 0, -1, 0) is None
    assert wall.ray_distance(0, 3, 1, 0) is None


def test_rotated_wall_and_inside_start():
    wall = Wall(0.0, 2.0, 4.0, 0.2, yaw=math.pi / 2)  # now 0.2 wide in x, 4 long in y
    assert math.isclose(wall.ray_distance(-1, 2, 1, 0), 0.9, abs_tol=1e-9)
    assert wall.ray_distance(0, 2, 1, 0) == 0.0


def test_nearest_of_several_walls_and_inf_when_open():
    walls = [Wall(3, 0, 0.2, 10), Wall(-2, 0, 0.2, 10)]
    assert math.isclose(expected_range(walls, 0, 0, 0), 2.9)
    assert math.isclose(expected_range(walls, 0, 0, math.pi), 1.9)
    assert expected_range(walls, 0, 0, math.pi / 2) == math.inf


class Scan:
    def __init__(self, ranges, angle_min, increment, range_min=0.1, range_max=5.0):
        self.ranges, self.angle_min, self.angle_increment = ranges, angle_min, increment
        self.range_min, self.range_max = range_min, range_max


def test_compare_scan_flags_a_wrong_beam_and_checks_out_of_range():
    walls = [Wall(3, 0, 0.2, 10)]
    scan = Scan([expected_range(walls, 0, 0, -0.5 + 0.5 * i) for i in range(3)] + [math.inf], -0.5, 0.5,
                range_max=4.0)  # the beams at -0.5, 0 and 0.5 rad hit; the one at 1.0 rad (5.4 m) is out of range
    errors, beyond, failures = compare_scan(walls, 0, 0, 0, scan, 0.01)
    assert failures == [] and len(errors) == 3 and beyond == 1
    scan.ranges[1] += 0.1
    scan.ranges[3] = 3.9
    _, _, failures = compare_scan(walls, 0, 0, 0, scan, 0.01)
    assert [f[0] for f in failures] == [1, 3]


def test_load_walls_puts_model_frame_walls_into_the_world(tmp_path):
    path = tmp_path / 'maze.yaml'
    path.write_text('model_pose_in_world: {x: 1.0, y: 2.0, yaw: 1.5707963267948966}\n'
                    'walls:\n'
                    '  - {x: 1.0, y: 0.0, size_x: 2.0, size_y: 0.1, yaw: 0.0}\n'
                    '  - {x: 0.0, y: 0.0, sx: 0.5, sy: 0.5}\n')
    wall, post = load_walls(str(path))
    assert (round(wall.x, 9), round(wall.y, 9)) == (1.0, 3.0)  # model +x is world +y
    assert math.isclose(wall.yaw, math.pi / 2)
    assert (wall.sx, wall.sy) == (2.0, 0.1)
    assert (post.x, post.y, post.sx) == (1.0, 2.0, 0.5)
    # The rotated wall runs along world y from 2 to 4, x 0.95..1.05.
    assert math.isclose(expected_range([wall], 0.0, 3.0, 0.0), 0.95)


def test_distance_to_a_wall_is_to_its_outline_from_outside_and_inside():
    wall = Wall(0.0, 0.0, 2.0, 0.2, math.pi / 2)  # along y, x -0.1 .. 0.1
    assert math.isclose(wall.distance(0.5, 0.0), 0.4)
    assert math.isclose(wall.distance(0.05, 0.3), 0.05)   # inside, 5 cm from the face
    assert math.isclose(wall.distance(0.4, 1.4), 0.5)     # off the corner: (0.3, 0.4)
