#!/usr/bin/python3
"""The Katana tutorial's pick-and-stack over seeded random layouts (issues 13 and 38): how many
cans end up in one standing tower, why not when they don't, how long a can takes, and how far the
detected cans are from where they stand.

  bench_katana_stacking.py [--layouts N] [--first-seed S] [--cans C] [--region band|reach]
                           [--out results.jsonl] [--address HOST:PORT] [--cpus-per-run C]
                           (after . scripts/env.sh)

Each layout is one run of `roslaunch katana_pick stack_cans.launch cans_seed:=SEED cans_count:=C
cans_range:=MIN,MAX` (a fresh simulator: C cans drawn by katana_arm_gazebo's
can_layouts.random_layout), the layouts one sim_batch batch over the seeds (docs/BATCH.md: each
run on a ROS master of its own; one at a time on this machine by default, or on a Ray cluster with
--address). --region band draws between 0.34 and 0.42 m from the base (can_layouts' defaults, the
issue 13 benchmark); --region reach over the whole range at which the arm takes a can, from
katana_pick.reach (the URDF's dimensions and limits): 0.315-0.46 m. This script's --check watches
each run: once stack_cans has published the cans it found, the simulator runs as fast as it goes
until stack_cans exits. Then, from /gazebo/get_model_state:

  - stacked: the cans of the highest standing column (each level within 1 cm of its height,
    within 2 cm of the bottom can's axis, tilted less than 10 degrees, still so 3 s later);
    against stackable, the most cans katana_pick.reach says one tower can take (every can's
    spot and every free range on a 1 cm grid as the tower, every order; the reach of each can,
    not the clearance between them);
  - success: every can in the tower; otherwise the cause, the first that applies: unreachable
    (the planner refused a can), no release (attached and never let go), no attach (a moved
    can never attached to the gripper), tip-over (a can lies tilted more than 20 degrees), slip
    (a can was carried and let go, but is not on the tower); before those, not detected
    (stack_cans found fewer cans than stand);
  - knocked over: cans tilted more than 20 degrees; unreported: cans left out of the tower that
    stack_cans did not report as skipped, with the reason;
  - seconds per moved can, sim and wall, from the cans' detection to stack_cans' exit;
  - the detection error: each can found against where it was spawned.
"""
import argparse
import itertools
import json
import math
import os
import re
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import bench_batch  # noqa: E402
from bench_node_rtf import set_real_time_factor  # noqa: E402

TABLE = 0.4
CAN_HEIGHT = 0.12


def tilt(q):
    return math.degrees(2 * math.asin(min(1.0, math.hypot(q.x, q.y))))


def layout_rules(region):
    """The random layouts' rules: the issue 13 band, or over the arm's whole reach."""
    from katana_arm_gazebo.can_layouts import LayoutRules
    if region == 'band':
        return LayoutRules()
    from katana_pick.arm_geometry import KatanaGeometry
    from katana_pick.reach import taking_range
    near, far = taking_range(KatanaGeometry())
    return LayoutRules(min_range=near, max_range=far)


def stackable(layout):
    """The most cans of the layout one tower can hold by the arm's reach (katana_pick.reach): on a
    can's own spot, or on a free spot (a 1 cm grid of ranges) the first can is set down at."""
    from katana_pick.arm_geometry import KatanaGeometry
    from katana_pick.free_spots import tower_size
    from katana_pick.reach import reach_map
    ranges = [round(math.hypot(x, y), 6) for x, y in layout]
    grid = [round(0.25 + 0.01 * i, 6) for i in range(26)]  # 0.25-0.50 m
    reach = reach_map(KatanaGeometry(), sorted(set(ranges + grid)), max_level=len(layout) - 1)
    own = max(tower_size(reach, ranges[:t] + ranges[t + 1:], ranges[t], False) for t in range(len(layout)))
    return max([own] + [tower_size(reach, ranges, r, True) for r in grid])


def tallest_column(poses):
    """The cans (names, bottom first) of the highest column standing on the table."""
    def upright(n):
        return tilt(poses[n].orientation) < 10.0
    best = []
    for bottom in poses:
        b = poses[bottom].position
        if not (upright(bottom) and abs(b.z - TABLE) < 0.01):
            continue
        column = [bottom]
        while True:
            level = len(column)
            above = [n for n in poses if n not in column and upright(n)
                     and abs(poses[n].position.z - (TABLE + level * CAN_HEIGHT)) < 0.01
                     and math.hypot(poses[n].position.x - b.x, poses[n].position.y - b.y) < 0.02]
            if not above:
                break
            column.append(above[0])
        if len(column) > len(best):
            best = column
    return best


def reports_of(node, rosout_log):
    """The messages `node` logged, from the lines of a rosout.log (the rosout node's file)."""
    line = re.compile(r'^\S+ \w+ %s \[[^\]]*\] \[topics: [^\]]*\] (.*)$' % re.escape(node))
    return [m.group(1) for m in map(line.match, rosout_log) if m]


def stack_cans_reports():
    """What stack_cans logged, as its terminal showed it: from this run's rosout.log, written by
    the rosout node from the start (a subscriber to /rosout started beside the launch misses the
    reports stack_cans makes before it connects, such as the cans it skips at once)."""
    import rospkg
    import rospy
    with open(os.path.join(rospkg.get_log_dir(), rospy.get_param('/run_id'), 'rosout.log'), errors='replace') as log:
        return reports_of('/stack_cans', log)


def check(seed, count, region):
    """One run's check: stack_cans.launch is up on this run's master (ROS_MASTER_URI); prints one
    JSON line with what happened."""
    from katana_arm_gazebo.can_layouts import random_layout
    layout = random_layout(count, seed, layout_rules(region))
    names = ['can_%d' % (i + 1) for i in range(count)]
    most = stackable(layout)

    import rosnode
    import rospy
    from gazebo_grasp_plugin_ros.msg import GazeboGraspEvent
    from gazebo_msgs.srv import GetModelState, GetWorldProperties
    from geometry_msgs.msg import PoseArray

    rospy.init_node('bench_katana_stacking', anonymous=True, disable_signals=True)
    events = []
    rospy.Subscriber('/gazebo/grasp_events', GazeboGraspEvent, lambda e: events.append((e.object, e.attached)))
    detected = []
    rospy.Subscriber('/stack_cans/cans', PoseArray, lambda m: detected.append(m))
    bench_batch.wait_until(lambda: bool(detected), 90, 'cans published by stack_cans')
    world = rospy.ServiceProxy('/gazebo/get_world_properties', GetWorldProperties)
    get_state = rospy.ServiceProxy('/gazebo/get_model_state', GetModelState)
    set_real_time_factor(0.0)
    sim0, wall0 = world().sim_time, time.monotonic()
    bench_batch.wait_until(lambda: '/stack_cans' not in rosnode.get_node_names(), 900, 'end of stack_cans')
    sim_s, wall_s = world().sim_time - sim0, time.monotonic() - wall0

    def poses():
        return {n: get_state(n, '').pose for n in names}

    before = poses()
    end = world().sim_time + 3.0
    while world().sim_time < end:
        time.sleep(0.05)
    after = poses()
    # The column as it stands 3 s on, up to its first can that was still moving.
    column = list(itertools.takewhile(
        lambda n: math.dist((after[n].position.x, after[n].position.y, after[n].position.z),
                            (before[n].position.x, before[n].position.y, before[n].position.z)) < 0.005,
        tallest_column(after)))

    log = '\n'.join(stack_cans_reports())
    knocked = [n for n in names if tilt(after[n].orientation) > 20.0]
    reported = len(re.findall(r'stack_cans: can at .*(?:skipped|given up after)', log))
    success = len(column) == count
    cause = None
    if not success:
        moved = [n for n in names if n not in column[:1]]
        if len(detected[0].poses) < count:
            cause = 'not detected'
        elif 'unreachable' in log:
            cause = 'unreachable'
        elif any((n, True) in events and (n, False) not in events for n in moved):
            cause = 'no release'  # first: a can left in the gripper spoils the moves after it
        elif knocked:
            cause = 'tip-over'  # before 'no attach': with the whole tower down, the tower's own can counts as moved
        elif any((n, True) not in events for n in moved):
            cause = 'no attach'
        else:
            cause = 'slip'
    # How far each can in the column stands off the bottom can's axis (a place's lateral error, summed up the tower).
    offsets = [math.hypot(after[n].position.x - after[column[0]].position.x,
                          after[n].position.y - after[column[0]].position.y) for n in column[1:]]
    seen = [(p.position.x, p.position.y) for p in detected[0].poses]
    errors = [min(math.dist(s, c) for s in seen) for c in layout] if seen else []
    errors_line = re.findall(r'stack_cans: .*(?:unreachable|nothing between|ended the move|did not|given up).*', log)
    print(json.dumps({'seed': seed, 'cans': count, 'region': region, 'layout': layout, 'success': success,
                      'stacked': len(column), 'stackable': most, 'knocked': knocked,
                      'unreported': max(0, count - len(column) - reported), 'cause': cause,
                      'sim_s': sim_s, 'wall_s': wall_s, 'moved': len({o for o, held in events if held}),
                      'found': len(seen), 'detection_errors': errors, 'offsets': offsets, 'events': events,
                      'errors': errors_line[:4], 'sim_time': world().sim_time}), flush=True)


def summarise(results, count, command):
    n = len(results)
    ok = [r for r in results if r['success']]
    causes = {}
    for r in results:
        if not r['success']:
            causes[r['cause']] = causes.get(r['cause'], 0) + 1
    per_can_sim = [r['sim_s'] / r['moved'] for r in results if r.get('moved')]
    per_can_wall = [r['wall_s'] / r['moved'] for r in results if r.get('moved')]
    errors = [e for r in results for e in r['detection_errors']]
    missed = sum(count - min(r['found'], count) for r in results)
    stacked = sum(min(r.get('stacked', 0), r.get('stackable', count)) for r in results)
    most = sum(r.get('stackable', count) for r in results)
    mean = lambda v: sum(v) / len(v) if v else float('nan')  # noqa: E731
    print('\n%d layouts of %d cans: %d towers of all %d (%.0f %%)'
          % (n, count, len(ok), count, 100.0 * len(ok) / n if n else 0))
    print('cans in the tower against the most the reach allows: %d of %d (%.1f %%); layouts with a can knocked '
          'over: %d; cans left out and not reported: %d'
          % (stacked, most, 100.0 * stacked / most if most else 0, sum(1 for r in results if r.get('knocked')),
             sum(r.get('unreported', 0) for r in results)))
    for cause in ('not detected', 'unreachable', 'no attach', 'no release', 'tip-over', 'slip', 'run failed'):
        print('  %-12s %d' % (cause, causes.get(cause, 0)))
    print('seconds per moved can: sim %.1f mean (%.1f-%.1f), wall %.1f mean'
          % (mean(per_can_sim), min(per_can_sim, default=float('nan')), max(per_can_sim, default=float('nan')),
             mean(per_can_wall)))
    print('detection: %d of %d cans found; error mean %.1f mm, max %.1f mm'
          % (count * n - missed, count * n, 1e3 * mean(errors), 1e3 * max(errors, default=float('nan'))))
    offsets = sorted(o for r in results for o in r.get('offsets', []))
    if offsets:
        print('tower: %d cans on another; off the bottom can\'s axis mean %.1f mm, 95th percentile %.1f mm, max %.1f mm'
              % (len(offsets), 1e3 * mean(offsets), 1e3 * offsets[int(0.95 * (len(offsets) - 1))], 1e3 * offsets[-1]))
    for r in results:
        if not r['success']:
            print('  seed %d: %s, %d of %d stacked (reach: %d) %s'
                  % (r['seed'], r['cause'], r.get('stacked', 0), count, r.get('stackable', count),
                     '; '.join(r['errors'])))
    print('command: %s' % command)


def scenario(args):
    rules = layout_rules(args.region)
    return {'name': 'katana_stacking', 'launch': 'katana_pick stack_cans.launch',
            'args': {'cans_seed': '${seed}', 'cans_count': str(args.cans),
                     'cans_range': '%g,%g' % (rules.min_range, rules.max_range)},
            'check': bench_batch.check_command(__file__, '--check', '${seed}', '--cans', args.cans,
                                               '--region', args.region),
            'seeds': list(range(args.first_seed, args.first_seed + args.layouts)), 'time_limit': 900}


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument('--layouts', type=int, default=50)
    parser.add_argument('--first-seed', type=int, default=1)
    parser.add_argument('--cans', type=int, default=3)
    parser.add_argument('--region', choices=('band', 'reach'), default='band')
    bench_batch.add_arguments(parser)
    parser.add_argument('--check', type=int, metavar='SEED', help=argparse.SUPPRESS)
    args = parser.parse_args()
    if args.check is not None:
        return check(args.check, args.cans, args.region)
    command = 'scripts/bench_katana_stacking.py --layouts %d --first-seed %d --cans %d --region %s' % (
        args.layouts, args.first_seed, args.cans, args.region)
    records, _ = bench_batch.run(scenario(args), args, 2, 'bench_katana_stacking')
    results = []
    for record in records:
        r = bench_batch.result_of(record)
        if r is None:
            print('%s: the run failed: %s' % (record['run_id'], bench_batch.describe_failure(record)), flush=True)
            results.append({'seed': record.get('seed'), 'success': False, 'cause': 'run failed', 'sim_s': 0,
                            'wall_s': 0, 'found': 0, 'detection_errors': [], 'errors': []})
            continue
        print('seed %3d: %s  %d of %d stacked (reach: %d), sim %.1f s, wall %.1f s, %d cans found' % (
            r['seed'], 'stacked' if r['success'] else r['cause'], r['stacked'], args.cans, r['stackable'],
            r['sim_s'], r['wall_s'], r['found']), flush=True)
        results.append(r)
    summarise(results, args.cans, command)
    return 0


if __name__ == '__main__':
    sys.exit(main())
