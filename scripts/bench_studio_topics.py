#!/usr/bin/python3
"""What a browser client's topics cost the simulator (issue 35): the Katana tutorial's world
unthrottled, with and without a subscriber on /gazebo/pose_info and /gazebo/scene_info, in one run.

  bench_studio_topics.py [--seconds S] [--rounds N]      (after . scripts/env.sh)

Brings up `roslaunch katana_arm_gazebo katana_arm.launch katana_type:=katana_450_6m90a` (the arm on
its table, its trajectory and joint state controllers at every 1 ms step, robot_state_publisher, the
three cans) headless on a roscore of its own, waits for the controllers and the cans, and runs the
simulation as fast as it goes (max_update_rate 0). Then N rounds (default 8) of two windows of S
wall seconds (default 5), one without and one with bullet_sim/studio_topics_listener subscribed to
both topics (a C++ subscriber, started 1 s before its window and stopped after it), in the order
without-with, with-without, ... so that a drift of the machine's speed falls on both alike. The
real-time factor of each window is sim time over wall time from /clock (bullet_sim/topic_arrivals);
on a VM shared with other work it drifts by more than the cost sought, so each window also records
the simulator's own CPU time (/proc) per simulated second, which the other processes change little:
what the topics cost is the ratio of that, with over without. Output:
  window N without|with: real-time factor X, simulator CPU M ms per sim s  [pose_info at H Hz of wall time]
  studio topics: real-time factor without A (median), with B (median); median of the rounds' ratios R
  studio topics: simulator CPU per sim second without P ms (median), with Q ms (median); median of the rounds' ratios S
  studio topics cost: C % of the real-time factor, D % more simulator CPU per sim second  (target < 5 %)
Then, with the simulation paused, bullet_sim/bench_studio_messages times what one message costs to
build and serialize in the same world (its world file and the launch's robot, table and can
descriptions), and the wall clock read each step makes while pose_info has a subscriber:
  pose_info: X us to build and serialize one message (B bytes) ...
  studio topics' own work: W ms per wall second at 60 Hz and F steps/s = P % of one core
Every process it starts is stopped at the end, also on errors and Ctrl-C.
"""
import argparse
import os
import statistics
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from bench_node_rtf import (ArrivalListener, launch_on_private_master, measure, rosgraph_service_up,  # noqa: E402
                            run_with_processes, unthrottle, wait_until)
from process_cpu import _command_line, _cpu_seconds  # noqa: E402

LAUNCH = ['katana_arm_gazebo', 'katana_arm.launch', 'katana_type:=katana_450_6m90a']
COMMAND = '/usr/bin/python3 scripts/bench_studio_topics.py'


def read_counts(path):
    counts = {}
    with open(path) as f:
        for line in f:
            name, *values = line.split()
            counts[name] = [float(v) for v in values]
    return counts


def bring_up(procs):
    import rospy
    from controller_manager_msgs.srv import ListControllers
    from gazebo_msgs.srv import GetWorldProperties
    master = launch_on_private_master(procs, 'bench_studio_topics', LAUNCH)
    wait_until(lambda: rosgraph_service_up(master, '/controller_manager/list_controllers'), 120,
               "the Katana's controller manager", procs)
    lister = rospy.ServiceProxy('/controller_manager/list_controllers', ListControllers)
    wait_until(lambda: sum(c.state == 'running' for c in lister().controller) == 2, 120,
               'katana_arm_controller and joint_state_controller running', procs)
    world = rospy.ServiceProxy('/gazebo/get_world_properties', GetWorldProperties)
    wait_until(lambda: sum(n.startswith('can_') for n in world().model_names) == 3, 120, 'the three cans', procs)
    return world().model_names


def simulator_pid(procs):
    """The bullet_sim_node of this bring-up: its log folder is ours (launch_on_private_master)."""
    for pid in filter(str.isdigit, os.listdir('/proc')):
        args = _command_line(pid)
        if '__name:=gazebo' in args and any(procs.log_dir in a for a in args):
            return pid
    raise RuntimeError('no bullet_sim_node (__name:=gazebo) with its log in ' + procs.log_dir)


def window(procs, index, with_subscriber, seconds, simulator):
    """One measured window; returns (label, start, end, pose_info Hz or None, simulator CPU seconds)."""
    listener = None
    out = os.path.join(procs.log_dir, 'studio_%d.txt' % index)
    if with_subscriber:
        listener = procs.start('studio_%d' % index, ['rosrun', 'bullet_sim', 'studio_topics_listener', out],
                               os.environ)
        wait_until(lambda: os.path.exists(out + '.ready'), 30, 'a scene and a pose on the studio topics', procs)
    time.sleep(1.0)  # past the start (or the stop) of a process
    cpu_start, start = _cpu_seconds(simulator), time.monotonic()
    time.sleep(seconds)
    cpu_end, end = _cpu_seconds(simulator), time.monotonic()
    rate = None
    if listener:
        procs.stop(listener)  # it writes its counts as it exits
        counts = read_counts(out)
        poses, span = counts['pose_info']
        rate = (poses - 1) / span if span > 0 else float('nan')
    return ('with' if with_subscriber else 'without'), start, end, rate, cpu_end - cpu_start


def message_costs(procs, steps_per_second):
    """bench_studio_messages on this bring-up's world; prints its figures and what they add up to."""
    import re
    import subprocess

    import rospkg
    import rospy
    from std_srvs.srv import Empty
    rospy.ServiceProxy('/gazebo/pause_physics', Empty)()
    files = []
    for name, copies in (('robot_description', 1), ('table_description', 1), ('can_description', 3)):
        path = os.path.join(procs.log_dir, name + '.urdf')
        with open(path, 'w') as f:
            f.write(rospy.get_param('/' + name))
        files += [path] * copies
    world = os.path.join(rospkg.RosPack().get_path('katana_arm_gazebo'), 'worlds', 'katana.world')
    done = subprocess.run(['rosrun', 'bullet_sim', 'bench_studio_messages', world] + files,
                          stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, timeout=120)
    if done.returncode != 0:
        raise RuntimeError('bench_studio_messages failed:\n' + done.stdout[-2000:])
    print(done.stdout.strip())
    pose_us = float(re.search(r'pose_info: ([0-9.]+) us', done.stdout).group(1))
    clock_ns = float(re.search(r'wall clock read: ([0-9.]+) ns', done.stdout).group(1))
    per_second = 60 * pose_us * 1e-3 + steps_per_second * clock_ns * 1e-6  # ms of work per wall second
    print('studio topics\' own work: %.2f ms per wall second at 60 Hz and %.0f steps/s = %.2f %% of one core '
          '(roscpp\'s send of each message not counted)' % (per_second, steps_per_second, per_second / 10))


def run(args, procs):
    models = bring_up(procs)
    simulator = simulator_pid(procs)
    clock = ArrivalListener(procs, 'katana')
    clock.wait_ready()
    unthrottle()
    time.sleep(2.0)
    windows = []
    for r in range(args.rounds):
        order = (False, True) if r % 2 == 0 else (True, False)
        for with_subscriber in order:
            windows.append(window(procs, len(windows), with_subscriber, args.seconds, simulator))
    arrivals = clock.stop()

    print('command: %s --seconds %g --rounds %d' % (COMMAND, args.seconds, args.rounds))
    print('world: %s (%d models: %s)' % (' '.join(LAUNCH), len(models), ', '.join(models)))
    rtf, cpu = {'without': [], 'with': []}, {'without': [], 'with': []}
    rtf_ratios, cpu_ratios = [], []
    for i, (label, start, end, rate, cpu_seconds) in enumerate(windows):
        r = measure(arrivals, start, end, label)
        rtf[label].append(r['rtf'])
        cpu[label].append(1000.0 * cpu_seconds / r['sim'])  # ms of simulator CPU per simulated second
        print('window %2d %-7s: real-time factor %5.2f, simulator CPU %5.1f ms per sim s%s'
              % (i, label, r['rtf'], cpu[label][-1], '  pose_info at %.1f Hz of wall time' % rate if rate else ''))
        if i % 2 == 1:  # a round ends: its two windows are the last of each kind
            rtf_ratios.append(rtf['with'][-1] / rtf['without'][-1])
            cpu_ratios.append(cpu['with'][-1] / cpu['without'][-1])
    median = statistics.median
    print('studio topics: real-time factor without %.2f (median of %d), with %.2f; median of the rounds\' '
          'ratios %.3f (range %.3f-%.3f)' % (median(rtf['without']), len(rtf['without']), median(rtf['with']),
                                             median(rtf_ratios), min(rtf_ratios), max(rtf_ratios)))
    print('studio topics: simulator CPU per sim second without %.1f ms (median), with %.1f ms; median of the '
          'rounds\' ratios %.3f (range %.3f-%.3f)' % (median(cpu['without']), median(cpu['with']),
                                                      median(cpu_ratios), min(cpu_ratios), max(cpu_ratios)))
    print('studio topics cost: %.1f %% of the real-time factor, %.1f %% more simulator CPU per sim second  '
          '(target < 5 %%)' % (100 * (1 - median(rtf_ratios)), 100 * (median(cpu_ratios) - 1)))
    sys.stdout.flush()
    message_costs(procs, 1000 * median(rtf['with']))  # 1 ms steps
    sys.stdout.flush()


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n\n')[0])
    parser.add_argument('--seconds', type=float, default=5.0, help='wall seconds per window (default 5)')
    parser.add_argument('--rounds', type=int, default=8, help='pairs of windows, without and with (default 8)')
    args = parser.parse_args()
    return run_with_processes('bench_studio_topics', lambda procs: run(args, procs))


if __name__ == '__main__':
    sys.exit(main())
