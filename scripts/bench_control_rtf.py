#!/usr/bin/python3
"""Real-time factor of the simulator with controllers running (issue 3): the tutorials' robots
brought up by their own launch files, headless, each on a private roscore.

  bench_control_rtf.py [--seconds S]

  simple_model  simple_model_control simple_model.launch: JointStateController + an effort
                JointPositionController at 1 kHz, the 32-beam lidar subscribed (so it casts)
  arm           arm_control exercise.launch bringup:=true: six controllers at 1 kHz while the
                exercise node commands both arms at 50 Hz

For each: the factor at the world's real_time_factor 1, then unthrottled (max_update_rate 0).
Reuses bench_node_rtf.py's process handling and its C++ /clock and scan listener. Output lines:
  control real-time factor (<robot>, real time): X
  control real-time factor (<robot>, unthrottled): Y
"""
import argparse
import os
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from bench_node_rtf import (ArrivalListener, each_robot_in_its_own_process, launch_on_private_master,  # noqa: E402
                            measure, rosgraph_service_up, run_with_processes, unthrottle, wait_until, wall_window)

ROBOTS = [
    ('simple_model', ['simple_model_control', 'simple_model.launch'], '/simple_model',
     'joint1_position_controller', '/simple_lidar/scan'),
    ('arm', ['arm_control', 'exercise.launch', 'bringup:=true'], '/arm', 'joint1_1_controller', None),
]


def bench(robot, launch, namespace, controller, scan_topic, seconds, procs):
    import rospy
    from controller_manager_msgs.srv import ListControllers

    master = launch_on_private_master(procs, 'bench_control_rtf', launch)
    listener = ArrivalListener(procs, robot, scan_topic)
    list_service = namespace + '/controller_manager/list_controllers'
    wait_until(lambda: rosgraph_service_up(master, list_service), 90, list_service, procs)
    lister = rospy.ServiceProxy(list_service, ListControllers)
    wait_until(lambda: any(c.name == controller and c.state == 'running' for c in lister().controller), 60,
               '%s running' % controller, procs)
    listener.wait_ready()
    time.sleep(1.0)
    running = sum(c.state == 'running' for c in lister().controller)
    windows = [wall_window('real time', seconds)]
    unthrottle()
    time.sleep(1.0)
    windows.append(wall_window('unthrottled', seconds))
    arrivals = listener.stop()
    for r in [measure(arrivals, start, end, label) for label, start, end in windows]:
        print('control real-time factor (%s, %s): %.2f' % (robot, r['label'], r['rtf']))
        print('  %d controllers running; %.2f s sim in %.2f s wall%s' % (
            running, r['sim'], r['wall'], ('; %d scans on %s' % (r['scans'], scan_topic)) if scan_topic else ''))
    sys.stdout.flush()
    procs.stop_all()


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n\n')[0])
    parser.add_argument('--seconds', type=float, default=8.0, help='wall seconds per measurement (default 8)')
    parser.add_argument('--robot', choices=[r[0] for r in ROBOTS], help='only this robot (default: each in turn)')
    args = parser.parse_args()
    if not args.robot:
        return each_robot_in_its_own_process(__file__, [r[0] for r in ROBOTS], ['--seconds', str(args.seconds)])
    robot = next(r for r in ROBOTS if r[0] == args.robot)
    return run_with_processes('bench_control_rtf', lambda procs: bench(*robot, args.seconds, procs))


if __name__ == '__main__':
    sys.exit(main())
