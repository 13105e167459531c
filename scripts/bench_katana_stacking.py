#!/usr/bin/python3
"""The Katana tutorial's pick-and-stack over seeded random layouts (issue 13): how often the three
cans end up as one standing tower, why not when they don't, how long a can takes, and how far the
detected cans are from where they stand.

  bench_katana_stacking.py [--layouts N] [--first-seed S]      (after . scripts/env.sh)

Each layout is one run of `roslaunch katana_pick stack_cans.launch cans_seed:=SEED` on a roscore of
its own (a fresh simulator: three cans drawn by katana_arm_gazebo's can_layouts.random_layout), in
a process of its own; once stack_cans has published the cans it found, the simulator runs as fast
as it goes until stack_cans exits. Then, from /gazebo/get_model_state:

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
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from bench_node_rtf import launch_on_private_master, run_with_processes, set_real_time_factor, wait_until  # noqa: E402

TABLE = 0.4
CAN_HEIGHT = 0.12


def tilt(q):
    return math.degrees(2 * math.asin(min(1.0, math.hypot(q.x, q.y))))


def one_layout(seed, procs):
    """Runs one layout; prints one JSON line with what happened."""
    from katana_arm_gazebo.can_layouts import random_layout
    from katana_pick.stacking import choose_tower
    layout = random_layout(3, seed)
    names = ['can_%d' % (i + 1) for i in range(3)]
    tower = names[choose_tower(layout)]

    launch_on_private_master(procs, 'bench_katana_stacking',
                             ['katana_pick', 'stack_cans.launch', 'cans_seed:=%d' % seed])
    import rosnode
    import rospy
    from gazebo_grasp_plugin_ros.msg import GazeboGraspEvent
    from gazebo_msgs.srv import GetModelState, GetWorldProperties
    from geometry_msgs.msg import PoseArray

    events = []
    rospy.Subscriber('/gazebo/grasp_events', GazeboGraspEvent, lambda e: events.append((e.object, e.attached)))
    detected = []
    rospy.Subscriber('/stack_cans/cans', PoseArray, lambda m: detected.append(m))
    wait_until(lambda: bool(detected), 90, 'stack_cans to publish the cans it found', procs)
    world = rospy.ServiceProxy('/gazebo/get_world_properties', GetWorldProperties)
    get_state = rospy.ServiceProxy('/gazebo/get_model_state', GetModelState)
    set_real_time_factor(0.0)
    sim0, wall0 = world().sim_time, time.monotonic()
    wait_until(lambda: '/stack_cans' not in rosnode.get_node_names(), 600, 'stack_cans to finish', procs)
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

    log = procs.log_tail('launch', lines=400)
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
                      'errors': errors_line[:3]}), flush=True)


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


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument('--layouts', type=int, default=50)
    parser.add_argument('--first-seed', type=int, default=1)
    parser.add_argument('--one-layout', type=int, help=argparse.SUPPRESS)
    args = parser.parse_args()
    if args.one_layout is not None:
        return run_with_processes('bench_katana_stacking', lambda procs: one_layout(args.one_layout, procs))
    command = 'scripts/bench_katana_stacking.py --layouts %d --first-seed %d' % (args.layouts, args.first_seed)
    results = []
    for seed in range(args.first_seed, args.first_seed + args.layouts):
        run = subprocess.run([sys.executable, os.path.abspath(__file__), '--one-layout', str(seed)],
                             stdout=subprocess.PIPE, text=True, timeout=900)
        lines = [line for line in run.stdout.splitlines() if line.startswith('{')]
        if run.returncode != 0 or not lines:
            print('seed %d: the run failed (exit %d): %s' % (seed, run.returncode, run.stdout[-500:]), flush=True)
            results.append({'seed': seed, 'success': False, 'cause': 'run failed', 'sim_s': 0, 'wall_s': 0,
                            'found': 0, 'detection_errors': [], 'errors': []})
            if len(results) == 3 and all(r['cause'] == 'run failed' for r in results):
                print('bench_katana_stacking: the first three runs failed to run at all; is the workspace '
                      'built and scripts/env.sh sourced?', file=sys.stderr)
                return 1
            continue
        r = json.loads(lines[-1])
        print('seed %3d: %s  sim %.1f s, wall %.1f s, %d cans found' % (
            seed, 'stacked' if r['success'] else r['cause'], r['sim_s'], r['wall_s'], r['found']), flush=True)
        results.append(r)
    summarise(results, command)
    return 0


if __name__ == '__main__':
    sys.exit(main())
