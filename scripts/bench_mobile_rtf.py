#!/usr/bin/python3
"""Real-time factor of the mobile robots' worlds with all their sensors on (issue 4), each
brought up by its own launch file, headless, on a private roscore, while it drives a slow circle.

  bench_mobile_rtf.py [--seconds S] [--robot m_robot|pioneer]

  m_robot  m_robot_gazebo m_robot_world.launch: skid steer at 100 Hz, 359-beam lidar at 5.5 Hz,
           800x800 camera at 30 Hz, in the Capstone maze
  pioneer  pioneer_gazebo pioneer_world.launch: diff drive at 100 Hz, 720-beam Hokuyo at 40 Hz,
           800x800 camera at 30 Hz, in the 8 x 8 m maze

The laser and the camera are subscribed (they only work with a reader, as in Gazebo). For each
robot: the factor at the world's real_time_factor 1, unthrottled (max_update_rate 0), and
unthrottled with the camera unsubscribed (what the camera costs). Reuses bench_node_rtf.py's
process handling and its C++ /clock and scan listener (the images are counted here). Output lines (parsed by scripts/bench):
  mobile real-time factor (<robot>, real time): X
  mobile real-time factor (<robot>, unthrottled): Y
  mobile real-time factor (<robot>, unthrottled, no camera): Z
"""
import argparse
import os
import struct
import sys
import threading
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from bench_node_rtf import (ArrivalListener, each_robot_in_its_own_process, launch_on_private_master,  # noqa: E402
                            measure, rosgraph_service_up, run_with_processes, unthrottle, wait_until, wall_window)

# name, launch, model, cmd_vel, scan, image
ROBOTS = [
    ('m_robot', ['m_robot_gazebo', 'm_robot_world.launch'], 'm_robot', '/cmd_vel', '/m_robot/laser/scan',
     '/m_robot/camera1/image_raw'),
    ('pioneer', ['pioneer_gazebo', 'pioneer_world.launch'], 'pioneer', '/pioneer/cmd_vel', '/pioneer/laser/scan',
     '/pioneer/camera1/image_raw'),
]


class ImageCounter:
    """Image arrivals as (wall time, header stamp), from the serialized bytes."""

    def __init__(self):
        self.lock = threading.Lock()
        self.images = []

    def on_image(self, msg):  # sensor_msgs/Image: Header first: uint32 seq, time stamp
        secs, nsecs = struct.unpack_from('<II', msg._buff, 4)
        with self.lock:
            self.images.append((time.monotonic(), secs + 1e-9 * nsecs))

    def rate(self, start, end, sim_start, sim_end):
        """(images per second of sim time, per wall second) received between start and end."""
        with self.lock:
            got = [i for i in self.images if start <= i[0] <= end]
        in_span = [i for i in got if sim_start < i[1] <= sim_end]
        sim = sim_end - sim_start
        return (len(in_span) / sim if sim > 0 else 0.0), len(got) / (end - start)


def bench(robot, launch, model, cmd_vel, scan_topic, image_topic, seconds, procs):
    import rospy
    from gazebo_msgs.srv import GetModelState
    from geometry_msgs.msg import Twist

    master = launch_on_private_master(procs, 'bench_mobile_rtf', launch)
    wait_until(lambda: rosgraph_service_up(master, '/gazebo/get_model_state'), 90, '/gazebo/get_model_state', procs)
    get_state = rospy.ServiceProxy('/gazebo/get_model_state', GetModelState)
    wait_until(lambda: get_state(model_name=model).success, 60, 'model %s spawned' % model, procs)

    listener, images = ArrivalListener(procs, robot, scan_topic), ImageCounter()
    image_sub = rospy.Subscriber(image_topic, rospy.AnyMsg, images.on_image, queue_size=10, tcp_nodelay=True)
    # A slow circle, so that the wheels, contacts and sensors all have work to do.
    cmd = rospy.Publisher(cmd_vel, Twist, queue_size=1)
    twist = Twist()
    twist.linear.x, twist.angular.z = 0.1, 0.4
    stop = threading.Event()

    def drive():
        while not stop.is_set():
            cmd.publish(twist)
            time.sleep(0.05)
    driver = threading.Thread(target=drive, daemon=True)
    driver.start()
    listener.wait_ready()
    time.sleep(2.0)

    windows = [wall_window('real time', seconds)]
    unthrottle()
    time.sleep(1.0)
    windows.append(wall_window('unthrottled', seconds))
    image_sub.unregister()
    time.sleep(1.0)
    windows.append(wall_window('unthrottled, no camera', seconds))
    stop.set()
    arrivals = listener.stop()
    results = []
    for label, start, end in windows:
        r = measure(arrivals, start, end, label)
        r['image_hz_sim'], r['image_hz_wall'] = images.rate(start, end, *r['sim_span'])
        results.append(r)
    for r in results:
        print('mobile real-time factor (%s, %s): %.2f' % (robot, r['label'], r['rtf']))
        print('  %.2f s sim in %.2f s wall; laser %.1f Hz sim time (%.1f Hz wall); camera %.1f Hz sim time '
              '(%.1f Hz wall)' % (r['sim'], r['wall'], r['scan_hz_sim'], r['scan_hz_wall'], r['image_hz_sim'],
                                  r['image_hz_wall']))
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
    return run_with_processes('bench_mobile_rtf', lambda procs: bench(*robot, args.seconds, procs))


if __name__ == '__main__':
    sys.exit(main())
