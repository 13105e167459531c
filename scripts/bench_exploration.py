#!/usr/bin/python3
"""Autonomous exploration over seeded start poses (issue 12): each robot's whole headless system
(simulator, mapper, move_base and find_frontier or explore_lite's explore) explores its maze from N
random starts, one fresh bring-up per run on a private roscore.

  bench_exploration.py [--robot m_robot|pioneer] [--explorer find_frontier|explore] [--starts N]
                       [--seed S] [--rtf F] [--mapper gmapping|hector]

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
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(ROOT, 'src', 'bullet_sim_testing', 'src'))
from bench_node_rtf import (launch_on_private_master, rosgraph_service_up, run_with_processes,  # noqa: E402
                            set_real_time_factor, wait_until)
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


def one_run(name, explorer, start, rtf, mapper, procs):
    """Explores once; prints a RESULT line (json) for the parent."""
    import rospy
    robot = ROBOTS[name]
    x, y, yaw = start
    walls = load_walls(robot['walls'])
    area = ReachableArea(walls, robot['inscribed'], (x, y))
    launch = robot['launch'] + ['explorer:=' + explorer, 'x:=%g' % x, 'y:=%g' % y, 'yaw:=%g' % yaw]
    if name == 'pioneer':  # explore.launch's choice of mapper
        launch = launch + ['mapper:=' + mapper]
    # hector_mapping's map frame starts at the spawn pose; slam_gmapping's is the world's.
    map_in_world = (0.0, 0.0, 0.0) if mapper == 'gmapping' else (x, y, yaw)
    master = launch_on_private_master(procs, 'bench_exploration', launch, node=False)
    master.setParam('/use_sim_time', True)
    rospy.init_node('bench_exploration', anonymous=True, disable_signals=True)
    wait_until(lambda: rosgraph_service_up(master, '/gazebo/set_physics_properties'), 90, 'the simulator', procs)
    watch = Watch(area, walls, map_in_world, '/%s/status' % explorer, robot['model'], robot['outline'],
                  robot['laser_range'])
    wait_until(lambda: watch.status.startswith('exploring'), 120, 'the first exploration goal', procs)
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
    if os.environ.get('BENCH_KEEP_LOGS'):  # the map and path, to look at with the logs
        subprocess.run(['rosrun', 'hector_style_mapping', 'save_map', '-f', os.path.join(procs.log_dir, 'map')],
                       env=os.environ, stdout=subprocess.DEVNULL)
    print('RESULT ' + json.dumps(dict(
        complete=watch.completed_at is not None, status=watch.status, explored=watch.share(),
        sim_to_95=(t95 - sim0) if t95 else None, wall_to_95=wall_at_95, sim=sim, wall=wall,
        distance=watch.distance(), contacts=watch.contacts, map_precision=precision, map_mean=mean)), flush=True)


def median(values):
    values = [v for v in values if v is not None]
    return statistics.median(values) if values else float('nan')


def bench(name, explorer, starts, seed, rtf, mapper):
    robot = ROBOTS[name]
    walls = load_walls(robot['walls'])
    runs = []
    for k, start in enumerate(draw_starts(robot, starts, seed)):
        area = ReachableArea(walls, robot['inscribed'], start[:2])
        tour, _ = best_tour(area, walls, start[:2], robot['laser_range'])
        out = subprocess.run([sys.executable, os.path.abspath(__file__), '--robot', name, '--explorer', explorer,
                              '--rtf', str(rtf), '--mapper', mapper, '--one'] + [str(v) for v in start],
                             stdout=subprocess.PIPE, text=True)
        line = next((ln for ln in out.stdout.splitlines() if ln.startswith('RESULT ')), None)
        if line is None:
            print('  start %2d (%5.2f, %5.2f, %5.2f): the run failed (exit %d)' % (k + 1, *start, out.returncode),
                  flush=True)
            runs.append(None)
            continue
        r = json.loads(line[len('RESULT '):])
        r['tour'] = tour
        runs.append(r)
        print('  start %2d (%5.2f, %5.2f, %5.2f): %s, explored %5.1f %%, 95 %% at %s s sim, done at %6.1f s sim '
              '(%5.1f s wall), driven %5.1f m (best tour %4.1f m), %d contacts, map %.1f %% within 0.1 m' % (
                  k + 1, *start, 'complete' if r['complete'] else 'NOT COMPLETE', 100 * r['explored'],
                  '%5.1f' % r['sim_to_95'] if r['sim_to_95'] is not None else '  -  ', r['sim'], r['wall'],
                  r['distance'], tour, r['contacts'], 100 * r['map_precision']), flush=True)
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
    parser.add_argument('--one', type=float, nargs=3, metavar=('X', 'Y', 'YAW'), help=argparse.SUPPRESS)
    args = parser.parse_args()
    if args.one:
        rtf = ROBOTS[args.robot]['rtf'] if args.rtf is None else args.rtf
        mapper = mapper_of(args.robot, args.mapper)
        return run_with_processes('bench_exploration', lambda procs: one_run(args.robot, args.explorer, args.one, rtf,
                                                                              mapper, procs))
    status = 0
    for name in [args.robot] if args.robot else sorted(ROBOTS):
        for explorer in [args.explorer] if args.explorer else ['find_frontier', 'explore']:
            rtf = ROBOTS[name]['rtf'] if args.rtf is None else args.rtf
            mapper = mapper_of(name, args.mapper)
            print('command: scripts/bench_exploration.py --robot %s --explorer %s --starts %d --seed %d --rtf %g%s' % (
                name, explorer, args.starts, args.seed, rtf, ' --mapper ' + mapper if name == 'pioneer' else ''),
                flush=True)
            status |= bench(name, explorer, args.starts, args.seed, rtf, mapper)
    return status


if __name__ == '__main__':
    sys.exit(main())
