#!/usr/bin/python3
"""The mapper live against the mapper offline on real robot logs (issue 39, item 3).

Each Radish log in ../shared/datasets/radish (or --logs) goes through carmen_to_bag; then, in one run,
- offline: bench_mapping_bag with the search and loop closure (bench_radish.py's "loops" run);
- live, at each --rates (default 1, 4 and 10): the hector_mapping node (same settings, sim time) fed
  by `rosbag play --clock -r RATE`, as a user plays a log into it. At the end of the bag the clock is
  moved on a few seconds so that the node's timers publish its final trajectory, which is scored as
  the offline one: each matched scan's pose (moved with its keyframe by loop closure) against the
  logged corrected pose at its stamp.

Per log and run it prints one line:

  <log> <offline|live Nx>: M of S scans matched (K skipped); absolute RMS A m after alignment, relative
        mean R m, Q deg; mapper mean X ms, max Y ms per scan

Errors as bench_radish.py's (absolute after the best rigid 2-D fit; relative: each scan against the first
scan at least 1 s later). The target: at 10x the live errors within 10 % of offline, every scan matched.
Playing a log faster than 10x (--rates 40,100) puts the scans as close together as a dense log's at 10x
(Intel's 0.34 scans a second at 100x: 34 a second; Freiburg 079's 4.5 at 10x: 45). --dense HZ plays, instead
of each log, the dense log dense_radish_bag.py makes of it (HZ scans a second, 361 beams).

  bench_radish_live.py [--logs DIR] [--rates 1,4,10] [--only NAME] [--dense HZ] [--out DIR]
"""
import argparse
import math
import os
import re
import signal
import socket
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import bench_radish  # noqa: E402  (the same logs, settings and error measures)

SUMMARY = re.compile(r'(\d+) scans processed, ([\d.]+) ms mean, ([\d.]+) ms max per scan, (\d+) skipped')
# bench_radish's loops run as the node's private parameters.
NODE_PARAMS = bench_radish.MAP_PARAMS + bench_radish.CONFIGS[-1][1] + [
    '_scan_topic:=/scan', '_base_frame:=base_link', '_odom_frame:=base_link']


def free_port():
    with socket.socket() as s:
        s.bind(('127.0.0.1', 0))
        return s.getsockname()[1]


def truth_by_stamp(bag_path):
    import rosbag
    truth = {}
    with rosbag.Bag(bag_path) as bag:
        for _, msg, _ in bag.read_messages(topics=['/ground_truth']):
            q = msg.pose.pose.orientation
            yaw = bench_radish.wrap(2.0 * math.atan2(q.z, q.w))
            truth[msg.header.stamp.to_nsec()] = (msg.pose.pose.position.x, msg.pose.pose.position.y, yaw)
    return truth


class Live:
    """One roscore for the whole run; a fresh mapper for each play."""

    def __init__(self):
        self.env = dict(os.environ, ROS_MASTER_URI='http://127.0.0.1:%d' % free_port())
        os.environ['ROS_MASTER_URI'] = self.env['ROS_MASTER_URI']
        self.core = subprocess.Popen(['roscore', '-p', self.env['ROS_MASTER_URI'].rsplit(':', 1)[1]],
                                     env=self.env, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        deadline = time.time() + 30
        while subprocess.run(['rosparam', 'get', '/run_id'], env=self.env, stdout=subprocess.DEVNULL,
                             stderr=subprocess.DEVNULL).returncode != 0:
            if time.time() > deadline:
                raise RuntimeError('roscore did not come up')
            time.sleep(0.2)
        subprocess.run(['rosparam', 'set', '/use_sim_time', 'true'], env=self.env, check=True)
        import rospy
        from geometry_msgs.msg import PoseStamped
        from nav_msgs.msg import Path
        from rosgraph_msgs.msg import Clock
        self.rospy = rospy
        rospy.init_node('bench_radish_live', disable_signals=True)
        self.matched = []
        self.trajectory = None
        rospy.Subscriber('/slam_out_pose', PoseStamped, lambda m: self.matched.append(m.header.stamp), queue_size=10000)
        rospy.Subscriber('/trajectory', Path, self._keep_trajectory, queue_size=1)
        self.clock = rospy.Publisher('/clock', Clock, queue_size=1)
        self.Clock = Clock

    def _keep_trajectory(self, msg):
        self.trajectory = msg

    def play(self, bag, rate, log_path):
        """(matched stamps, final trajectory, mapper summary match) for one play at `rate`."""
        self.matched, self.trajectory = [], None
        with open(log_path, 'w') as log:
            mapper = subprocess.Popen(['rosrun', 'hector_style_mapping', 'hector_mapping'] + NODE_PARAMS,
                                      env=self.env, stdout=log, stderr=subprocess.STDOUT)
            time.sleep(3.0)  # the node up and subscribed
            subprocess.run(['rosbag', 'play', '--clock', '--quiet', '-d', '1', '-r', str(rate), bag], env=self.env,
                           stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=True)
            # The last scans matched, then the clock on so that the trajectory goes out as it ends.
            last = self.rospy.Time.now()
            count = -1
            while count != len(self.matched):
                count = len(self.matched)
                time.sleep(1.0)
            for i in range(1, 31):
                self.clock.publish(self.Clock(clock=last + self.rospy.Duration(0.2 * i)))
                time.sleep(0.1)
            time.sleep(0.5)
            mapper.send_signal(signal.SIGINT)
            mapper.wait(timeout=30)
        with open(log_path) as log:
            summary = SUMMARY.search(log.read())
        return list(self.matched), self.trajectory, summary

    def close(self):
        self.rospy.signal_shutdown('done')
        self.core.send_signal(signal.SIGINT)
        self.core.wait(timeout=30)


def score_live(name, rate, bag, truth, live, out):
    matched, trajectory, summary = live.play(bag, rate, os.path.join(out, '%s_live_%g.log' % (name, rate)))
    scans = len(truth)
    if trajectory is None or summary is None:
        print('%s live %gx: no trajectory or no exit summary from the mapper (log in %s)' % (name, rate, out))
        return False
    rows = []
    for p in trajectory.poses:
        t = truth.get(p.header.stamp.to_nsec())
        if t is None:
            continue
        q = p.pose.orientation
        yaw = 2.0 * math.atan2(q.z, q.w)
        rows.append((p.header.stamp.to_sec(), (p.pose.position.x, p.pose.position.y, yaw), t))
    rel_d, rel_a, _ = bench_radish.relative_errors(rows)
    print('%s live %gx: %d of %d scans matched (%s skipped); absolute RMS %.2f m after alignment, relative mean '
          '%.3f m, %.2f deg; mapper mean %s ms, max %s ms per scan' % (
              name, rate, len(set(matched)), scans, summary.group(4), bench_radish.aligned_rms(rows), rel_d,
              math.degrees(rel_a), summary.group(2), summary.group(3)), flush=True)
    return True


def dense_bag(log, out, rate):
    name = os.path.basename(log).split('-')[0] + '_dense'
    bag = os.path.join(out, name + '.bag')
    subprocess.run([sys.executable, os.path.join(HERE, 'dense_radish_bag.py'), log, bag, '--rate', str(rate)],
                   check=True, stdout=subprocess.DEVNULL)
    return name, bag


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n\n')[0])
    parser.add_argument('--logs', default=bench_radish.DEFAULT_LOGS)
    parser.add_argument('--rates', default='1,4,10', help='comma-separated rosbag play rates')
    parser.add_argument('--only', help='only the log whose name starts with this (aces, intel)')
    parser.add_argument('--out', help='keep the bags, poses and mapper logs here')
    parser.add_argument('--dense', type=float, default=0.0,
                        help='scans a second: the dense log dense_radish_bag.py makes of each log instead')
    args = parser.parse_args()
    rates = [float(r) for r in args.rates.split(',')]
    logs = sorted(os.path.join(args.logs, f) for f in os.listdir(args.logs) if f.endswith(('.log', '.log.gz')))
    if args.only:
        logs = [log for log in logs if os.path.basename(log).startswith(args.only)]
    print('command: scripts/bench_radish_live.py --logs %s --rates %s%s%s' % (
        args.logs, args.rates, ' --only ' + args.only if args.only else '',
        ' --dense %g' % args.dense if args.dense else ''), flush=True)
    ok = True
    with tempfile.TemporaryDirectory(prefix='bench_radish_live.') as tmp:
        out = args.out or tmp
        os.makedirs(out, exist_ok=True)
        live = Live()
        try:
            for log in logs:
                name, bag = dense_bag(log, out, args.dense) if args.dense else bench_radish.to_bag(log, out)
                ok &= bench_radish.run_mapper(name, ('offline', bench_radish.CONFIGS[-1][1]), bag, out, []) is not None
                truth = truth_by_stamp(bag)
                for rate in rates:
                    ok &= score_live(name, rate, bag, truth, live, out)
        finally:
            live.close()
    return 0 if ok else 1


if __name__ == '__main__':
    sys.exit(main())
