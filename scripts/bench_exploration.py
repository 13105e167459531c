#!/usr/bin/python3
"""Autonomous exploration over seeded start poses (issue 12): each robot's whole headless system
(simulator, mapper, move_base and find_frontier or explore_lite's explore) explores its maze from N
random starts, one fresh bring-up per run, the runs as one sim_batch batch (docs/BATCH.md: each on
a ROS master of its own; on this machine one at a time by default, or --cpus-per-run 1 for two at
once, or on a Ray cluster with --address).

  bench_exploration.py [--robot m_robot|pioneer] [--explorer find_frontier|explore] [--starts N]
                       [--seed S] [--rtf F] [--mapper gmapping|hector]
                       [--out results.jsonl] [--address HOST:PORT] [--cpus-per-run C]

  m_robot  find_frontier explore_maze.launch in the Capstone maze (hector_mapping, laser 6 m), paced
           at 30x real time (2 cores run its whole stack at 25-27x; --rtf 0: as fast as it goes)
  pioneer  pioneer_2dnav explore.launch in its 8 x 8 m maze (laser 30 m), at 22x real time (what
           its stack keeps up with on 2 cores), with slam_gmapping (explore.launch's default), or
           with --mapper hector hector_mapping

Starts are drawn from the cells the robot's centre can reach, at least 0.15 m more than its
inscribed radius from every wall, with a random heading. For each run: completion (the node's
"complete" report), the explored share of the reachable free area at the end (success: >= 99 %),
sim and wall time to 95 % and to completion, the distance driven against the best tour computed
offline (bullet_sim_testing.exploration.best_tour: greedy viewpoints with a 360-degree laser,
nearest-first with 2-opt), wall contacts, the map against the walls, and the real-time factor
(sim over wall time from the first goal to completion).

Each run is `roslaunch <launch> explorer:=E x:=X y:=Y yaw:=YAW` with this script's --check beside
it (it watches the run and prints one JSON line); the batch's points name the start (`start`, and
`starts_seed`, the --seed that drew it). The tables are built from sim_batch's results file.

Output: one line per run, then per robot and explorer
  exploration (<robot>, <explorer>): S/N reached >= 99 %, to 95 % median T95 s sim (W95 s wall), to
  completion median T s sim (W s wall), distance / best tour median D, C wall contacts, map within
  0.1 m of a wall P %, real-time factor R
"""
import argparse
import json
import math
import os
import random
import statistics
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(ROOT, 'src', 'bullet_sim_testing', 'src'))
import bench_batch  # noqa: E402
from bench_node_rtf import set_real_time_factor  # noqa: E402
from bullet_sim_testing.exploration import ReachableArea, best_tour, wall_clearance  # noqa: E402
from bullet_sim_testing.walls import load_walls  # noqa: E402
from explore_demo import Watch  # noqa: E402

ROBOTS = {
    'm_robot': dict(launch=['find_frontier', 'explore_maze.launch'], model='m_robot',
                    walls=os.path.join(ROOT, 'src', 'm_robot_gazebo', 'config', 'capstone_map_walls.yaml'),
                    inscribed=0.12, outline=(0.26, 0.22, 0.0), laser_range=6.0, rtf=30.0, timeout=600.0,
                    mapper='hector'),
    'pioneer': dict(launch=['pioneer_2dnav', 'explore.launch'], model='pioneer',
                    walls=os.path.join(ROOT, 'src', 'pioneer_gazebo_ros', 'pioneer_gazebo', 'config', 'pioneer_maze_walls.yaml'),
                    inscribed=0.2, outline=(0.44, 0.38, -0.045), laser_range=30.0, rtf=22.0, timeout=1500.0,
                    mapper='gmapping'),
}
DEFAULT_START = {'m_robot': (0.0, 0.0), 'pioneer': (-3.2, -3.2)}


def draw_starts(robot, count, seed):
    """`count` (x, y, yaw) starts: reachable centre cells 0.15 m clear of the inscribed radius."""
    walls = load_walls(robot['walls'])
    area = ReachableArea(walls, robot['inscribed'], DEFAULT_START[robot['model']])
    clear = wall_clearance(walls, area.xs, area.ys) >= robot['inscribed'] + 0.15
    rows, cols = (area.centres & clear).nonzero()
    rng = random.Random(seed)
    picks = [rng.randrange(len(rows)) for _ in range(count)]
    return [(round(float(area.xs[rows[k], cols[k]]), 3), round(float(area.ys[rows[k], cols[k]]), 3),
             round(rng.uniform(-math.pi, math.pi), 3)) for k in picks]


def check(name, explorer, start, rtf, mapper):
    """One run's check: the launch is up on this run's master (ROS_MASTER_URI); waits for the first
    exploration goal, paces the simulator, watches until the explorer reports completion (or the
    robot's timeout of sim time) and prints one JSON line."""
    import rospy
    robot = ROBOTS[name]
    x, y, yaw = start
    walls = load_walls(robot['walls'])
    area = ReachableArea(walls, robot['inscribed'], (x, y))
    # hector_mapping's map frame starts at the spawn pose; slam_gmapping's is the world's.
    map_in_world = (0.0, 0.0, 0.0) if mapper == 'gmapping' else (x, y, yaw)
    rospy.init_node('bench_exploration', anonymous=True, disable_signals=True)
    rospy.wait_for_service('/gazebo/set_physics_properties', timeout=90)
    watch = Watch(area, walls, map_in_world, '/%s/status' % explorer, robot['model'], robot['outline'],
                  robot['laser_range'])
    bench_batch.wait_until(lambda: watch.status.startswith('exploring'), 120, 'first exploration goal')
    set_real_time_factor(rtf)
    sim0, wall0 = rospy.get_time(), time.monotonic()
    wall_at_95 = None
    while watch.completed_at is None and rospy.get_time() - sim0 < robot['timeout']:
        if wall_at_95 is None and watch.share() >= 0.95:
            wall_at_95 = time.monotonic() - wall0
        time.sleep(0.1)
    sim, wall = rospy.get_time() - sim0, time.monotonic() - wall0
    time.sleep(1.0)  # the last map
    t95 = watch.time_to(0.95)
    precision, mean, coverage, _ = watch.map_accuracy(map_in_world)
    print(json.dumps(dict(
        complete=watch.completed_at is not None, status=watch.status, explored=watch.share(),
        sim_to_95=(t95 - sim0) if t95 else None, wall_to_95=wall_at_95, sim=sim, wall=wall, sim_time=rospy.get_time(),
        distance=watch.distance(), contacts=watch.contacts, map_precision=precision, map_mean=mean)), flush=True)


def median(values):
    values = [v for v in values if v is not None]
    return statistics.median(values) if values else float('nan')


def scenario(name, explorer, starts, seed, rtf, mapper):
    """The batch's scenario: one run per start."""
    robot = ROBOTS[name]
    args = {'explorer': explorer, 'x': '${x}', 'y': '${y}', 'yaw': '${yaw}'}
    if name == 'pioneer':  # explore.launch's choice of mapper
        args['mapper'] = mapper
    return {
        'name': 'exploration_%s_%s' % (name, explorer),
        'launch': ' '.join(robot['launch']),
        'args': args,
        'check': bench_batch.check_command(__file__, '--robot', name, '--explorer', explorer, '--rtf', rtf,
                                           '--mapper', mapper, '--check', '${x}', '${y}', '${yaw}'),
        'points': [{'starts_seed': seed, 'start': k + 1, 'x': x, 'y': y, 'yaw': yaw}
                   for k, (x, y, yaw) in enumerate(draw_starts(robot, starts, seed))],
        # sim seconds at >= 1x real time, and the bring-up
        'time_limit': robot['timeout'] + 180.0,
    }


def bench(name, explorer, starts, seed, rtf, mapper, args):
    robot = ROBOTS[name]
    walls = load_walls(robot['walls'])
    records, _ = bench_batch.run(scenario(name, explorer, starts, seed, rtf, mapper), args, 2, 'bench_exploration')
    runs = []
    for record in records:
        p = record.get('params') or {}
        k, start = p.get('start'), (p.get('x'), p.get('y'), p.get('yaw'))
        r = bench_batch.result_of(record)
        if r is None:
            print('  %s: %s' % (record['run_id'], bench_batch.describe_failure(record)), flush=True)
            runs.append(None)
            continue
        area = ReachableArea(walls, robot['inscribed'], start[:2])
        r['tour'], _ = best_tour(area, walls, start[:2], robot['laser_range'])
        runs.append(r)
        print('  start %2d (%5.2f, %5.2f, %5.2f): %s, explored %5.1f %%, 95 %% at %s s sim, done at %6.1f s sim '
              '(%5.1f s wall), driven %5.1f m (best tour %4.1f m), %d contacts, map %.1f %% within 0.1 m [%s]' % (
                  k, *start, 'complete' if r['complete'] else 'NOT COMPLETE', 100 * r['explored'],
                  '%5.1f' % r['sim_to_95'] if r['sim_to_95'] is not None else '  -  ', r['sim'], r['wall'],
                  r['distance'], r['tour'], r['contacts'], 100 * r['map_precision'], record.get('host')), flush=True)
        if r['explored'] < 0.99:  # what the node said when it stopped short
            print('    status: %s' % r['status'], flush=True)
    done = [r for r in runs if r]
    good = sum(1 for r in done if r['complete'] and r['explored'] >= 0.99)
    sim_total, wall_total = sum(r['sim'] for r in done), sum(r['wall'] for r in done)
    print('exploration (%s, %s): %d/%d reached >= 99 %%, to 95 %% median %.0f s sim (%.1f s wall), to completion '
          'median %.0f s sim (%.1f s wall), distance / best tour median %.2f, %d wall contacts, map within 0.1 m of a '
          'wall %.1f %% (worst), real-time factor %.1f' % (
              name, explorer, good, len(runs), median(r['sim_to_95'] for r in done),
              median(r['wall_to_95'] for r in done), median(r['sim'] for r in done), median(r['wall'] for r in done),
              median(r['distance'] / r['tour'] if r['tour'] > 0 else None for r in done),
              sum(r['contacts'] for r in done), 100 * min((r['map_precision'] for r in done), default=float('nan')),
              sim_total / wall_total if wall_total else float('nan')), flush=True)
    return 0 if good == len(runs) else 1


def mapper_of(name, requested):
    """m_robot maps with hector_mapping (it has no odometry); the Pioneer with the one asked for."""
    return (requested or ROBOTS[name]['mapper']) if name == 'pioneer' else ROBOTS[name]['mapper']


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n\n')[0])
    parser.add_argument('--robot', choices=sorted(ROBOTS), help='one robot (default: both)')
    parser.add_argument('--explorer', choices=['find_frontier', 'explore'], help='one explorer (default: both)')
    parser.add_argument('--starts', type=int, default=10, help='start poses per robot (default 10)')
    parser.add_argument('--seed', type=int, default=1, help='the starts\' random seed (default 1)')
    parser.add_argument('--rtf', type=float, help='target real-time factor (default: the robot\'s, 0 = as fast as it goes)')
    parser.add_argument('--mapper', choices=['gmapping', 'hector'],
                        help='the Pioneer\'s mapper: slam_gmapping (default) or hector_mapping (m_robot: always hector)')
    bench_batch.add_arguments(parser)
    parser.add_argument('--check', type=float, nargs=3, metavar=('X', 'Y', 'YAW'), help=argparse.SUPPRESS)
    args = parser.parse_args()
    if args.check:
        return check(args.robot, args.explorer, args.check, args.rtf, args.mapper)
    if args.out and not (args.robot and args.explorer):
        parser.error('--out needs one --robot and one --explorer (a results file holds one batch)')
    status = 0
    for name in [args.robot] if args.robot else sorted(ROBOTS):
        for explorer in [args.explorer] if args.explorer else ['find_frontier', 'explore']:
            rtf = ROBOTS[name]['rtf'] if args.rtf is None else args.rtf
            mapper = mapper_of(name, args.mapper)
            print('command: scripts/bench_exploration.py --robot %s --explorer %s --starts %d --seed %d --rtf %g%s' % (
                name, explorer, args.starts, args.seed, rtf, ' --mapper ' + mapper if name == 'pioneer' else ''),
                flush=True)
            status |= bench(name, explorer, args.starts, args.seed, rtf, mapper, args)
    return status


if __name__ == '__main__':
    sys.exit(main())
