#!/usr/bin/python3
"""A dense log made from a sparse one, for measuring the mapper at a dense log's pace (issue 39).

Radish's Intel and ACES logs have a scan every 3 s or so; a log like Freiburg 079 has 4.5 a second,
where the mapper's cost per scan decides whether it keeps up. This writes a bag with scans at --rate
per second along the log's corrected trajectory (interpolated between the logged poses, in the log's
own time), each cast into the building the log itself maps: every logged scan's end points at its
corrected pose, marked in a grid of --cell metres and grown by one cell so that neighbouring beams'
end points join into walls, and cleared within --clearance of the laser's path (where the robot went
was free: people and noise the laser saw there are not walls). The bag is laid out as carmen_to_bag's (scans on /scan in frame laser,
the mount on /tf_static, the exact pose on /ground_truth), so bench_mapping_bag, bench_radish.py's
measures and `rosbag play` take it as they take a real log. The scans are cleaner than a real
laser's (Gaussian noise of --noise, no clutter, no people), so it measures cost, not robustness.

  dense_radish_bag.py LOG BAG [--rate 4.5] [--beams 361] [--fov 180] [--max-range 30] [--noise 0.01]
"""
import argparse
import math
import sys

import numpy as np
import rosbag
import rospy
from tf2_msgs.msg import TFMessage

from hector_style_mapping_tools.carmen import read_log, saturation_range
from hector_style_mapping_tools.carmen_bag import laser_mount, scan_message, truth_message


class Pose:
    """What carmen_bag's writers read from a scan: its poses, ranges and beam angles."""

    def __init__(self, stamp, robot, laser, ranges, angle_min, angle_increment, kind):
        self.stamp, self.robot_pose, self.laser_pose = stamp, robot, laser
        self.ranges, self.angle_min, self.angle_increment, self.kind = ranges, angle_min, angle_increment, kind
        self.max_range = None


def building(log, cell, max_range):
    """(occupied grid, origin): every logged end point short of max_range, grown by one cell."""
    points = []
    for s in log.scans:
        r = np.asarray(s.ranges, dtype=float)
        a = s.laser_pose[2] + s.angle_min + s.angle_increment * np.arange(len(r))
        keep = np.isfinite(r) & (r < max_range) & (r > 0.05)
        points.append(np.stack([s.laser_pose[0] + r[keep] * np.cos(a[keep]),
                                s.laser_pose[1] + r[keep] * np.sin(a[keep])], axis=1))
    points = np.concatenate(points)
    origin = points.min(axis=0) - 2.0
    size = np.ceil((points.max(axis=0) + 2.0 - origin) / cell).astype(int)
    grid = np.zeros((size[1], size[0]), dtype=bool)
    cells = np.floor((points - origin) / cell).astype(int)
    grid[cells[:, 1], cells[:, 0]] = True
    grown = grid.copy()
    for dy in (-1, 0, 1):
        for dx in (-1, 0, 1):
            grown |= np.roll(np.roll(grid, dy, axis=0), dx, axis=1)
    return grown, origin


def clear_path(grid, origin, cell, positions, radius):
    """Every cell within `radius` of a position on the path made free."""
    reach = int(math.ceil(radius / cell))
    offsets = [(dx, dy) for dy in range(-reach, reach + 1) for dx in range(-reach, reach + 1)
               if math.hypot(dx, dy) * cell <= radius]
    cells = np.floor((np.asarray(positions) - origin) / cell).astype(int)
    for dx, dy in offsets:
        x, y = cells[:, 0] + dx, cells[:, 1] + dy
        inside = (x >= 0) & (y >= 0) & (x < grid.shape[1]) & (y < grid.shape[0])
        grid[y[inside], x[inside]] = False


def cast(grid, origin, cell, x, y, theta, angles, max_range):
    """Ranges from (x, y) along theta + angles to the first occupied cell (inf when none within max_range)."""
    step = cell / 2
    distances = np.arange(step, max_range, step)
    a = theta + angles
    px = x + np.outer(np.cos(a), distances)
    py = y + np.outer(np.sin(a), distances)
    cx = np.floor((px - origin[0]) / cell).astype(int)
    cy = np.floor((py - origin[1]) / cell).astype(int)
    inside = (cx >= 0) & (cy >= 0) & (cx < grid.shape[1]) & (cy < grid.shape[0])
    hit = np.zeros(cx.shape, dtype=bool)
    hit[inside] = grid[cy[inside], cx[inside]]
    first = np.where(hit.any(axis=1), hit.argmax(axis=1), -1)
    return np.where(first >= 0, distances[np.maximum(first, 0)], np.inf)


def interpolate(a, b, f):
    return (a[0] + f * (b[0] - a[0]), a[1] + f * (b[1] - a[1]),
            a[2] + f * math.remainder(b[2] - a[2], 2 * math.pi))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n\n')[0])
    parser.add_argument('log')
    parser.add_argument('bag')
    parser.add_argument('--rate', type=float, default=4.5, help='scans per second of the log (Freiburg 079: 4.5)')
    parser.add_argument('--beams', type=int, default=361)
    parser.add_argument('--fov', type=float, default=180.0, help='degrees')
    parser.add_argument('--max-range', type=float, default=30.0, help='m; beyond: no return (inf)')
    parser.add_argument('--noise', type=float, default=0.01, help='m, Gaussian, per range')
    parser.add_argument('--cell', type=float, default=0.05, help='m, the building grid the scans are cast in')
    parser.add_argument('--clearance', type=float, default=0.3, help='m round the laser\'s path kept free')
    parser.add_argument('--seed', type=int, default=1)
    args = parser.parse_args()
    log = read_log(args.log)
    scans = sorted(log.scans, key=lambda s: s.stamp)
    grid, origin = building(log, args.cell, saturation_range(log) or args.max_range)
    rng = np.random.default_rng(args.seed)
    fov = math.radians(args.fov)
    increment = fov / (args.beams - 1)
    angles = -fov / 2 + increment * np.arange(args.beams)
    shift = 1.0 - scans[0].stamp if scans[0].stamp < 1.0 else 0.0
    # The dense poses: (t, robot pose, laser pose, the logged scan before them).
    poses, k = [], 0
    t = scans[0].stamp
    while t <= scans[-1].stamp:
        while k + 2 < len(scans) and scans[k + 1].stamp < t:
            k += 1
        a, b = scans[k], scans[k + 1]
        f = 0.0 if b.stamp <= a.stamp else min(1.0, (t - a.stamp) / (b.stamp - a.stamp))
        poses.append((t, interpolate(a.robot_pose, b.robot_pose, f), interpolate(a.laser_pose, b.laser_pose, f), a))
        t = scans[0].stamp + len(poses) / args.rate
    clear_path(grid, origin, args.cell, [laser[:2] for _, _, laser, _ in poses], args.clearance)
    with rosbag.Bag(args.bag, 'w') as bag:
        first = rospy.Time.from_sec(scans[0].stamp + shift)
        bag.write('/tf_static', TFMessage([laser_mount(log, scans[0], first, 'base_link', 'laser')]),
                  first - rospy.Duration(0, 1000000))
        for t, robot, laser, logged in poses:
            ranges = cast(grid, origin, args.cell, laser[0], laser[1], laser[2], angles, args.max_range)
            ranges = np.maximum(ranges + rng.normal(0.0, args.noise, ranges.shape), 0.01)
            pose = Pose(t, robot, laser, ranges.tolist(), -fov / 2, increment, logged.kind)
            stamp = rospy.Time.from_sec(t + shift)
            bag.write('/scan', scan_message(pose, stamp, 'laser', args.max_range, 0.0), stamp)
            bag.write('/ground_truth', truth_message(pose, stamp, 'world', 'base_link'), stamp)
    count = len(poses)
    print('%s: %d scans of %d beams, %.1f a second over %.0f s, cast in a %d x %d grid of %.2f m cells' % (
        args.bag, count, args.beams, args.rate, scans[-1].stamp - scans[0].stamp, grid.shape[1], grid.shape[0],
        args.cell))
    return 0


if __name__ == '__main__':
    sys.exit(main())
