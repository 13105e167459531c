#!/usr/bin/python3
"""readmarker end to end on m_robot's simulated camera: how many of the camera's frames come back as
crops, how fast, and how late (issue 14).

  bench_readmarker_sim.py [--seconds S]      (after . scripts/env.sh)

Brings up readmarker_maze.launch headless on a roscore of its own (the board on the Capstone maze's
west wall, m_robot 1.1 m in front of it; the camera renders 800 x 800 at 30 Hz of sim time,
readmarker_node reads every frame it can). For S wall seconds (default 10) in each of two modes,
real time (real_time_factor 1) and as fast as the simulator goes (0), it counts:

  - camera frames (their camera_info messages, stamped like the images) and crops (cropped_img),
    per wall second and per sim second, and the share of frames read;
  - both pictures available, and the lag from a frame's camera_info to its crops (wall time).

This script's own node subscribes only to those small messages, so it takes little of the CPU.
"""
import argparse
import os
import sys
import threading
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from bench_node_rtf import launch_on_private_master, run_with_processes, set_real_time_factor, wait_until  # noqa: E402


class Counts:
    """Arrivals of camera frames and crops, by wall time and stamp."""

    def __init__(self):
        self.lock = threading.Lock()
        self.frames = {}   # stamp -> monotonic wall time of its camera_info
        self.crops = []    # (wall, stamp, both available)
        self.clock = []    # (wall, sim)

    def on_frame(self, msg):
        with self.lock:
            self.frames[msg.header.stamp.to_sec()] = time.monotonic()

    def on_crops(self, msg):
        with self.lock:
            both = bool(msg.image1_available and msg.image2_available)
            self.crops.append((time.monotonic(), msg.cimage1.header.stamp.to_sec(), both))

    def on_clock(self, msg):
        with self.lock:
            self.clock.append((time.monotonic(), msg.clock.to_sec()))

    def window(self, start, end):
        with self.lock:
            clock = [c for c in self.clock if start <= c[0] <= end]
            frames = {s: w for s, w in self.frames.items() if start <= w <= end}
            crops = [c for c in self.crops if start <= c[0] <= end]
            lags = [w - self.frames[s] for w, s, _ in crops if s in self.frames]
        wall = end - start
        sim = clock[-1][1] - clock[0][1] if len(clock) > 1 else 0.0
        return {'wall': wall, 'sim': sim, 'frames': len(frames), 'crops': len(crops),
                'both': sum(b for _, _, b in crops), 'lags': sorted(lags)}


def report(label, r):
    lags = r['lags']
    lag = ('lag mean %.0f ms, median %.0f ms, worst %.0f ms' % (1e3 * sum(lags) / len(lags), 1e3 * lags[len(lags) // 2],
                                                                 1e3 * lags[-1]) if lags else 'no lag measured')
    print('%s: real-time factor %.2f; %d camera frames = %.1f/s wall, %.1f/s sim; %d crops = %.1f/s wall '
          '(%.0f %% of the frames), both pictures in %d; %s' % (
              label, r['sim'] / r['wall'], r['frames'], r['frames'] / r['wall'], r['frames'] / max(r['sim'], 1e-9),
              r['crops'], r['crops'] / r['wall'], 100.0 * r['crops'] / max(r['frames'], 1), r['both'], lag), flush=True)


def bench(args, procs):
    import rospy
    from rosgraph_msgs.msg import Clock
    from sensor_msgs.msg import CameraInfo

    from readmarker.msg import markermsg
    launch = os.path.join(HERE, os.pardir, 'src', 'readmarker', 'launch', 'readmarker_maze.launch')
    launch_on_private_master(procs, 'bench_readmarker_sim', [launch, 'rviz:=false'])
    counts = Counts()
    rospy.Subscriber('/clock', Clock, counts.on_clock, queue_size=100)
    rospy.Subscriber('/m_robot/camera1/camera_info', CameraInfo, counts.on_frame, queue_size=100)
    rospy.Subscriber('/cropped_img', markermsg, counts.on_crops, queue_size=100)
    wait_until(lambda: sum(b for _, _, b in counts.crops) >= 5, 120, 'crops with both pictures', procs)
    for label, rtf in (('real time', 1.0), ('as fast as it goes', 0.0)):
        set_real_time_factor(rtf)
        time.sleep(1.0)  # the new pace settles
        start = time.monotonic()
        time.sleep(args.seconds)
        report(label, counts.window(start, time.monotonic()))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n\n')[0])
    parser.add_argument('--seconds', type=float, default=10.0, help='wall seconds per mode (default 10)')
    args = parser.parse_args()
    print('command: scripts/bench_readmarker_sim.py --seconds %g' % args.seconds, flush=True)
    return run_with_processes('bench_readmarker_sim', lambda procs: bench(args, procs))


if __name__ == '__main__':
    sys.exit(main())
