#!/usr/bin/python3
"""The mapper's cost per scan (issue 5), in one run, live in the simulator and from a recorded bag.

  bench_mapping.py [--robot m_robot|pioneer] [--save-maps DIR]

For each robot (m_robot: 359-beam lidar at 5.5 Hz; Pioneer: 720-beam Hokuyo at 40 Hz), on a private
roscore: its mapping launch file (simulator + mapper, headless), the tour of its maze that the
mapping rostest drives (config/mapping_tour.yaml), and `rosbag record` of the scans, tf and the
drive's ground-truth odometry. The
mapper logs its own per-scan time at shutdown (scan conversion + matching + map update + pose
output, wall clock): that is the live figure. Then bench_mapping_bag runs the same code on the
bag, with the mapper's parameters as the launch file set them, without simulator or master, and
also reports the pose errors against the recorded ground truth.
With --save-maps, save_map writes DIR/<robot>_map.{pgm,yaml,png} at the end of the live run (the
docs' pictures). Output lines (parsed by scripts/bench):
  mapping per scan (<robot>, <beams> beams, live): mean X ms, max Y ms over N scans
  mapping per scan (<robot>, <beams> beams, bag): mean X ms, max Y ms over N scans
Run with Debian's /usr/bin/python3 and the workspace sourced (scripts/env.sh).
"""
import argparse
import os
import re
import signal
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
sys.path.insert(0, HERE)
from bench_node_rtf import (each_robot_in_its_own_process, launch_on_private_master,  # noqa: E402
                            rosgraph_service_up, run_with_processes, wait_until)

# name: mapping launch, model, cmd_vel, scan topic, base frame, tour, ground-truth odometry (the drive
# plugin's, odometrySource world)
ROBOTS = {
    'm_robot': (['m_robot_gazebo', 'm_robot_mapping.launch'], 'm_robot', '/cmd_vel', '/m_robot/laser/scan',
                'base_frame', 'src/m_robot_gazebo/config/mapping_tour.yaml', '/odom'),
    'pioneer': (['pioneer_gazebo', 'pioneer_mapping.launch'], 'pioneer', '/pioneer/cmd_vel', '/pioneer/laser/scan',
                'base_link', 'src/pioneer_gazebo_ros/pioneer_gazebo/config/mapping_tour.yaml', '/pioneer/odom'),
}
# The node's parameters bench_mapping_bag takes (the map and the beam filters).
BAG_PARAMETERS = ('map_resolution', 'map_size', 'map_start_x', 'map_start_y', 'map_multi_res_levels',
                  'update_factor_free', 'update_factor_occupied', 'map_update_distance_thresh',
                  'map_update_angle_thresh', 'laser_min_dist', 'laser_max_dist', 'laser_z_min_value',
                  'laser_z_max_value')
SUMMARY = re.compile(r'hector_mapping: (\d+) scans processed, ([\d.]+) ms mean, ([\d.]+) ms max per scan')


def bench(robot, procs, save_maps):
    launch, model, cmd_vel, scan_topic, base_frame, tour, truth_topic = ROBOTS[robot]
    import rospy
    from gazebo_msgs.srv import GetModelState
    from geometry_msgs.msg import Twist
    from bullet_sim_testing.mapping import follow_waypoints, load_tour
    from bullet_sim_testing.mobile import yaw_of

    master = launch_on_private_master(procs, 'bench_mapping', launch)
    wait_until(lambda: rosgraph_service_up(master, '/gazebo/get_model_state'), 90, '/gazebo/get_model_state', procs)
    wait_until(lambda: rosgraph_service_up(master, '/dynamic_map'), 60, 'the mapper', procs)
    get_state = rospy.ServiceProxy('/gazebo/get_model_state', GetModelState, persistent=True)
    wait_until(lambda: get_state(model_name=model).success, 60, 'model %s spawned' % model, procs)
    parameters = rospy.get_param('/hector_mapping')

    bag = os.path.join(tempfile.gettempdir(), 'bench_mapping_%s.bag' % robot)  # kept: reproduce from it
    recorder = procs.start('rosbag', ['rosbag', 'record', '-O', bag, scan_topic, '/tf', '/tf_static', truth_topic],
                           os.environ)
    time.sleep(2.0)  # the recorder subscribes before the robot moves

    def truth():
        s = get_state(model_name=model)
        return s.header.stamp.to_sec(), s.pose.position.x, s.pose.position.y, yaw_of(s.pose.orientation)
    waypoints, speed, max_turn = load_tour(os.path.join(ROOT, tour))
    cmd = rospy.Publisher(cmd_vel, Twist, queue_size=1)
    start = time.monotonic()
    reached = follow_waypoints(truth, cmd, waypoints, speed, max_turn, timeout=600.0)
    drive_seconds = time.monotonic() - start
    time.sleep(1.0)
    if save_maps:
        subprocess.check_call(['rosrun', 'hector_style_mapping', 'save_map', '-f',
                               os.path.join(os.path.abspath(save_maps), robot + '_map')])
    os.killpg(recorder.pid, signal.SIGINT)  # rosbag closes the bag on SIGINT
    recorder.wait(20)
    procs.stop_all()  # SIGINT: the mapper logs its timing summary as it exits

    with open(os.path.join(procs.log_dir, 'launch.log'), errors='replace') as f:
        found = SUMMARY.findall(f.read())
    if not found:
        raise RuntimeError('the mapper printed no timing summary:\n' + procs.log_tail('launch'))
    scans, mean, worst = found[-1]
    beams = {'m_robot': 359, 'pioneer': 720}[robot]
    print('%s: drove %d of %d waypoints in %.0f s (wall)' % (robot, reached, len(waypoints), drive_seconds))
    print('mapping per scan (%s, %d beams, live): mean %s ms, max %s ms over %s scans' % (robot, beams, mean, worst,
                                                                                         scans))
    binary = os.path.join(ROOT, 'devel', 'lib', 'hector_style_mapping', 'bench_mapping_bag')
    argv = [binary, bag, scan_topic, base_frame, '--truth', truth_topic] + [
        '_%s:=%s' % (k, parameters[k]) for k in BAG_PARAMETERS if k in parameters]
    out = subprocess.run(argv, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, timeout=300)
    match = re.search(r'bag: (\d+) scans of (\d+) beams: mean ([\d.]+) ms, max ([\d.]+) ms', out.stdout)
    if out.returncode != 0 or not match:
        raise RuntimeError('bench_mapping_bag failed:\n' + out.stdout)
    print('mapping per scan (%s, %s beams, bag): mean %s ms, max %s ms over %s scans'
          % (robot, match.group(2), match.group(3), match.group(4), match.group(1)))
    print('  ' + out.stdout.strip())
    print('  reproduce the bag figure: %s' % ' '.join(argv))
    sys.stdout.flush()


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n\n')[0])
    parser.add_argument('--robot', choices=sorted(ROBOTS), help='only this robot (default: each in turn)')
    parser.add_argument('--save-maps', metavar='DIR', help='also save each map (PGM, YAML, PNG) into DIR')
    args = parser.parse_args()
    if not args.robot:
        return each_robot_in_its_own_process(__file__, ['m_robot', 'pioneer'],
                                             ['--save-maps', args.save_maps] if args.save_maps else [])
    return run_with_processes('bench_mapping', lambda procs: bench(args.robot, procs, args.save_maps))


if __name__ == '__main__':
    sys.exit(main())
