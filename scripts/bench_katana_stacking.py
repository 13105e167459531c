#!/usr/bin/python3
"""The Katana tutorial's pick-and-stack over seeded random layouts (issue 13): how often the three
cans end up as one standing tower, why not when they don't, how long a can takes, and how far the
detected cans are from where they stand.

  bench_katana_stacking.py [--layouts N] [--first-seed S]      (after . scripts/env.sh)
                           [--out results.jsonl] [--address HOST:PORT] [--cpus-per-run C]

Each layout is one run of `roslaunch katana_pick stack_cans.launch cans_seed:=SEED` (a fresh
simulator: three cans drawn by katana_arm_gazebo's can_layouts.random_layout), the layouts one
sim_batch batch over the seeds (docs/BATCH.md: each run on a ROS master of its own; one at a time
on this machine by default, or on a Ray cluster with --address). This script's --check watches
each run: once stack_cans has published the cans it found, the simulator runs as fast as it goes
until stack_cans exits. Then, from /gazebo/get_model_state:

  - success: the three cans stand one on another on the tower's can (each level within 1 cm of
    its height, within 2 cm of the tower's axis, tilted less than 10 degrees), still so 3 s later;
  - otherwise the cause, the first that applies: unreachable (the planner refused a can),
    no attach (a moved can never attached to the gripper), no release (attached and never let go),
    tip-over (a can lies tilted more than 20 degrees), slip (a can was carried and let go, but is
    not on the tower); before those, not detected (stack_cans found fewer than the three cans);
  - seconds per moved can, sim and wall, from the cans' detection to stack_cans' exit;
  - the detection error: each can found against where it was spawned.
"""
import argparse
import json
import math
import os
import re
import sys
import threading
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import bench_batch  # noqa: E402
from bench_node_rtf import set_real_time_factor  # noqa: E402

TABLE = 0.4
CAN_HEIGHT = 0.12


def tilt(q):
    return math.degrees(2 * math.asin(min(1.0, math.hypot(q.x, q.y))))


def check(seed):
    """One run's check: stack_cans.launch is up on this run's master (ROS_MASTER_URI); prints one
    JSON line with what happened."""
    from katana_arm_gazebo.can_layouts import random_layout
    from katana_pick.stacking import choose_tower
    layout = random_layout(3, seed)
    names = ['can_%d' % (i + 1) for i in range(3)]
    tower = names[choose_tower(layout)]

    import rosnode
    import rospy
    from gazebo_grasp_plugin_ros.msg import GazeboGraspEvent
    from gazebo_msgs.srv import GetModelState, GetWorldProperties
    from geometry_msgs.msg import PoseArray
    from rosgraph_msgs.msg import Log

    rospy.init_node('bench_katana_stacking', anonymous=True, disable_signals=True)
    lock, said = threading.Lock(), []  # what stack_cans logged, as its terminal showed it

    def on_log(message):
        if message.name == '/stack_cans':
            with lock:
                said.append(message.msg)
    rospy.Subscriber('/rosout', Log, on_log, queue_size=100)
    events = []
    rospy.Subscriber('/gazebo/grasp_events', GazeboGraspEvent, lambda e: events.append((e.object, e.attached)))
    detected = []
    rospy.Subscriber('/stack_cans/cans', PoseArray, lambda m: detected.append(m))
    bench_batch.wait_until(lambda: bool(detected), 90, 'cans published by stack_cans')
    world = rospy.ServiceProxy('/gazebo/get_world_properties', GetWorldProperties)
    get_state = rospy.ServiceProxy('/gazebo/get_model_state', GetModelState)
    set_real_time_factor(0.0)
    sim0, wall0 = world().sim_time, time.monotonic()
    bench_batch.wait_until(lambda: '/stack_cans' not in rosnode.get_node_names(), 600, 'end of stack_cans')
    sim_s, wall_s = world().sim_time - sim0, time.monotonic() - wall0

    def poses():
        return {n: get_state(n, '').pose for n in names}

    before = poses()
    end = world().sim_time + 3.0
    while world().sim_time < end:
        time.sleep(0.05)
    after = poses()

    base = after[tower].position
    stacked = sorted(names, key=lambda n: after[n].position.z)
    standing = all(
        abs(after[n].position.z - (TABLE + k * CAN_HEIGHT)) < 0.01
        and math.hypot(after[n].position.x - base.x, after[n].position.y - base.y) < 0.02
        and tilt(after[n].orientation) < 10.0
        and math.dist((after[n].position.x, after[n].position.y, after[n].position.z),
                      (before[n].position.x, before[n].position.y, before[n].position.z)) < 0.005
        for k, n in enumerate(stacked))

    with lock:
        log = '\n'.join(said)
    cause = None
    if not standing:
        moved = [n for n in names if n != tower]
        if len(detected[0].poses) < 3:
            cause = 'not detected'
        elif 'unreachable' in log:
            cause = 'unreachable'
        elif any((n, True) not in events for n in moved):
            cause = 'no attach'
        elif any((n, False) not in events for n in moved):
            cause = 'no release'
        elif any(tilt(after[n].orientation) > 20.0 for n in names):
            cause = 'tip-over'
        else:
            cause = 'slip'
    seen = [(p.position.x, p.position.y) for p in detected[0].poses]
    errors = [min(math.dist(s, c) for s in seen) for c in layout] if seen else []
    errors_line = re.findall(r'stack_cans: .*(?:unreachable|nothing between|ended the move|did not).*', log)
    print(json.dumps({'seed': seed, 'success': standing, 'cause': cause, 'sim_s': sim_s, 'wall_s': wall_s,
                      'found': len(seen), 'detection_errors': errors, 'events': events,
                      'errors': errors_line[:3], 'sim_time': world().sim_time}), flush=True)


def summarise(results, command):
    n = len(results)
    ok = [r for r in results if r['success']]
    causes = {}
    for r in results:
        if not r['success']:
            causes[r['cause']] = causes.get(r['cause'], 0) + 1
    per_can_sim = [r['sim_s'] / 2 for r in ok]
    per_can_wall = [r['wall_s'] / 2 for r in ok]
    errors = [e for r in results for e in r['detection_errors']]
    missed = sum(3 - min(r['found'], 3) for r in results)
    mean = lambda v: sum(v) / len(v) if v else float('nan')  # noqa: E731
    print('\n%d layouts of 3 cans: %d stacked (%.0f %%)' % (n, len(ok), 100.0 * len(ok) / n if n else 0))
    for cause in ('not detected', 'unreachable', 'no attach', 'no release', 'tip-over', 'slip', 'run failed'):
        print('  %-12s %d' % (cause, causes.get(cause, 0)))
    print('seconds per can (successful layouts, 2 cans moved each): sim %.1f mean (%.1f-%.1f), wall %.1f mean'
          % (mean(per_can_sim), min(per_can_sim, default=float('nan')), max(per_can_sim, default=float('nan')),
             mean(per_can_wall)))
    print('detection: %d of %d cans found; error mean %.1f mm, max %.1f mm'
          % (3 * n - missed, 3 * n, 1e3 * mean(errors), 1e3 * max(errors, default=float('nan'))))
    for r in results:
        if not r['success']:
            print('  seed %d: %s %s' % (r['seed'], r['cause'], '; '.join(r['errors'])))
    print('command: %s' % command)


def scenario(layouts, first_seed):
    return {'name': 'katana_stacking', 'launch': 'katana_pick stack_cans.launch', 'args': {'cans_seed': '${seed}'},
            'check': bench_batch.check_command(__file__, '--check', '${seed}'),
            'seeds': list(range(first_seed, first_seed + layouts)), 'time_limit': 900}


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument('--layouts', type=int, default=50)
    parser.add_argument('--first-seed', type=int, default=1)
    bench_batch.add_arguments(parser)
    parser.add_argument('--check', type=int, metavar='SEED', help=argparse.SUPPRESS)
    args = parser.parse_args()
    if args.check is not None:
        return check(args.check)
    command = 'scripts/bench_katana_stacking.py --layouts %d --first-seed %d' % (args.layouts, args.first_seed)
    records, _ = bench_batch.run(scenario(args.layouts, args.first_seed), args, 2, 'bench_katana_stacking')
    results = []
    for record in records:
        r = bench_batch.result_of(record)
        if r is None:
            print('%s: the run failed: %s' % (record['run_id'], bench_batch.describe_failure(record)), flush=True)
            results.append({'seed': record.get('seed'), 'success': False, 'cause': 'run failed', 'sim_s': 0,
                            'wall_s': 0, 'found': 0, 'detection_errors': [], 'errors': []})
            continue
        print('seed %3d: %s  sim %.1f s, wall %.1f s, %d cans found' % (
            r['seed'], 'stacked' if r['success'] else r['cause'], r['sim_s'], r['wall_s'], r['found']), flush=True)
        results.append(r)
    summarise(results, command)
    return 0


if __name__ == '__main__':
    sys.exit(main())
