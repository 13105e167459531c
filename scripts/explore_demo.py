#!/usr/bin/python3
"""The main demo: m_robot explores the Capstone maze on its own (find_frontier explore_maze.launch:
the simulator, hector_mapping, move_base and find_frontier, or explore_lite's explore), headless
at 20 times real time (2 cores keep up with its whole stack to 25-27x), on a ROS master of its own.

  explore_demo.py [--explorer find_frontier|explore] [--gui | gui:=true] [--rtf F] [--start X Y YAW] [--out DIR]

While it runs it prints the explored share of the maze's reachable free area (from the walls and
the robot's footprint), the goals, and sim and wall time; at the end, a summary (explored share,
time to 95 %, sim and wall time, distance driven, wall contacts, the map against the walls) and
the files in DIR (default demo_output/): the map as map_server writes it (capstone_maze.pgm,
.yaml), capstone_maze.png with the robot's path, and explored_area.png, the explored share over
time. The exit status is 0 when the node reported completion with at least 95 % explored.
"""
import argparse
import math
import os
import subprocess
import sys
import threading
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(ROOT, 'src', 'bullet_sim_testing', 'src'))
from bench_node_rtf import (launch_on_private_master, rosgraph_service_up, run_with_processes,  # noqa: E402
                            set_real_time_factor, wait_until)
from bullet_sim_testing.exploration import ReachableArea  # noqa: E402
from bullet_sim_testing.mobile import yaw_of  # noqa: E402
from bullet_sim_testing.navigation import outline, touches_a_wall  # noqa: E402
from bullet_sim_testing.walls import load_walls  # noqa: E402

WALLS = os.path.join(ROOT, 'src', 'm_robot_gazebo', 'config', 'capstone_map_walls.yaml')
INSCRIBED = 0.12            # m_robot's padded footprint (find_frontier/config/costmap_common.yaml)
OUTLINE = (0.26, 0.22)      # its body and wheels (m)
LASER_RANGE = 6.0


class Watch:
    """What the demo reports, from the topics: the map's explored share, the ground-truth path and
    wall contacts, the exploration node's status and goals."""

    def __init__(self, area, walls, map_in_world, status_topic, model='m_robot', outline_spec=OUTLINE,
                 laser_range=LASER_RANGE):
        import numpy as np
        import rospy
        from move_base_msgs.msg import MoveBaseActionResult
        from nav_msgs.msg import OccupancyGrid
        from std_msgs.msg import String
        self.np, self.area, self.walls, self.map_in_world = np, area, walls, map_in_world
        self.laser_range = laser_range
        self.model = model
        self.points = outline(outline_spec[0], outline_spec[1], centre_x=outline_spec[2] if len(outline_spec) > 2 else 0.0)
        self.lock = threading.Lock()
        self.explored = []          # (sim time, share)
        self.path = []              # (sim time, x, y) of the truth, every 0.1 s
        self.contacts = 0
        self.status = ''
        self.completed_at = None    # sim time of the first "complete" (the node goes on if the map opens new frontiers)
        self.completion = ''
        self.results = {}           # move_base outcome -> count
        self.last_map = None
        rospy.Subscriber('/map', OccupancyGrid, self.on_map, queue_size=1)
        # Raw, decoded only when a sample is due (every 0.1 s of sim time): model_states comes up to
        # a thousand times a wall second, and decoding each in Python took 15 % of a core.
        rospy.Subscriber('/gazebo/model_states', rospy.AnyMsg, self.on_raw_states, queue_size=1)
        rospy.Subscriber(status_topic, String, self.on_status, queue_size=10)
        rospy.Subscriber('/move_base/result', MoveBaseActionResult, self.on_result, queue_size=10)

    def on_map(self, msg):
        import rospy
        values = self.np.asarray(msg.data, dtype=self.np.int16).reshape(msg.info.height, msg.info.width)
        share = self.area.explored_fraction(values, msg.info.resolution,
                                            (msg.info.origin.position.x, msg.info.origin.position.y), self.map_in_world)
        with self.lock:
            self.explored.append((rospy.get_time(), share))
            self.last_map = msg

    def on_raw_states(self, raw):
        import rospy
        from gazebo_msgs.msg import ModelStates
        now = rospy.get_time()
        with self.lock:
            if self.path and now - self.path[-1][0] < 0.1:
                return
        msg = ModelStates()
        msg.deserialize(raw._buff)
        if self.model not in msg.name:
            return
        p = msg.pose[msg.name.index(self.model)]
        with self.lock:
            self.path.append((now, p.position.x, p.position.y))
        if touches_a_wall(self.walls, self.points, p.position.x, p.position.y, yaw_of(p.orientation)):
            with self.lock:
                self.contacts += 1

    def on_status(self, msg):
        import rospy
        with self.lock:
            self.status = msg.data
            if msg.data.startswith('complete') and self.completed_at is None:
                self.completed_at, self.completion = rospy.get_time(), msg.data

    def on_result(self, msg):
        text = {3: 'reached', 4: 'aborted', 2: 'preempted'}.get(msg.status.status, 'other')
        with self.lock:
            self.results[text] = self.results.get(text, 0) + 1

    def share(self):
        with self.lock:
            return self.explored[-1][1] if self.explored else 0.0

    def distance(self):
        with self.lock:
            xy = [(x, y) for _, x, y in self.path]
        return sum(math.dist(a, b) for a, b in zip(xy, xy[1:]))

    def time_to(self, share):
        with self.lock:
            return next((t for t, s in self.explored if s >= share), None)

    def map_accuracy(self, start_pose):
        """map_alignment of the last map's occupied cells (in the world through the start pose)
        against the walls: (share within 0.1 m of a wall, mean distance, share of visible faces)."""
        from bullet_sim_testing.map_scoring import map_alignment
        np = self.np
        with self.lock:
            msg, seen_from = self.last_map, [(px, py) for _, px, py in self.path[::20]]
        values = np.asarray(msg.data, dtype=np.int16).reshape(msg.info.height, msg.info.width)
        rows, cols = np.nonzero(values >= 65)
        res, ox, oy = msg.info.resolution, msg.info.origin.position.x, msg.info.origin.position.y
        x, y, yaw = start_pose
        c, s = math.cos(yaw), math.sin(yaw)
        mx, my = ox + (cols + 0.5) * res, oy + (rows + 0.5) * res
        points = list(zip(x + c * mx - s * my, y + s * mx + c * my))
        return map_alignment(self.walls, points, seen_from, self.laser_range) + (len(points),)


def plot_explored(path, explored, start):
    import matplotlib
    matplotlib.use('Agg')
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(6, 3.5))
    ax.plot([t - start for t, _ in explored], [100 * s for _, s in explored], color='tab:blue')
    ax.axhline(95, color='grey', linestyle='--', linewidth=0.8)
    ax.set_xlabel('sim time (s)')
    ax.set_ylabel('explored (% of reachable free area)')
    ax.set_ylim(0, 102)
    ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(path, dpi=100)
    plt.close(fig)


def run(args, procs):
    import rospy
    x, y, yaw = args.start
    walls = load_walls(WALLS)
    area = ReachableArea(walls, INSCRIBED, (x, y))
    launch = ['find_frontier', 'explore_maze.launch', 'explorer:=' + args.explorer, 'gui:=%s' % str(args.gui).lower(),
              'rviz:=%s' % str(args.gui and bool(os.environ.get('DISPLAY'))).lower(),
              'x:=%g' % x, 'y:=%g' % y, 'yaw:=%g' % yaw]
    print('demo: starting the simulator, hector_mapping, move_base and %s (roslaunch %s)' % (args.explorer, ' '.join(launch)),
          flush=True)
    wall_start = time.monotonic()
    master = launch_on_private_master(procs, 'explore_demo', launch, node=False)
    master.setParam('/use_sim_time', True)
    rospy.init_node('explore_demo', anonymous=True, disable_signals=True)
    wait_until(lambda: rosgraph_service_up(master, '/gazebo/set_physics_properties'), 90, 'the simulator', procs)
    status_topic = '/%s/status' % args.explorer
    watch = Watch(area, walls, (x, y, yaw), status_topic)
    wait_until(lambda: watch.status.startswith('exploring'), 120, 'the first exploration goal', procs)
    set_real_time_factor(args.rtf)
    if args.gui:
        wait_until(lambda: master.hasParam('/gazebo_gui/url'), 30, 'the studio', procs)
        print('demo: the studio (gzclient in a browser): open %s' % master.getParam('/gazebo_gui/url'), flush=True)
    up = time.monotonic() - wall_start
    sim0, wall0 = rospy.get_time(), time.monotonic()
    print('demo: up in %.0f s; exploring %.1f m2 of reachable free area (%s)' % (
        up, area.area, 'as fast as it goes' if args.rtf == 0 else '%gx real time' % args.rtf), flush=True)
    next_print = 0.0
    while watch.completed_at is None:
        sim, wall = rospy.get_time() - sim0, time.monotonic() - wall0
        if sim > args.timeout:
            print('demo: no completion within %.0f s of sim time' % args.timeout, flush=True)
            break
        if wall >= next_print:
            next_print = wall + args.every
            with watch.lock:
                results = dict(watch.results)
            print('  sim %6.1f s  wall %5.1f s  explored %5.1f %%  goals reached %d  driven %5.1f m' % (
                sim, wall, 100 * watch.share(), results.get('reached', 0), watch.distance()), flush=True)
        time.sleep(0.2)
    sim, wall = rospy.get_time() - sim0, time.monotonic() - wall0
    time.sleep(1.0)  # the last map (every 2 s of sim time)
    os.makedirs(args.out, exist_ok=True)
    base = os.path.join(args.out, 'capstone_maze')
    subprocess.run(['rosrun', 'hector_style_mapping', 'save_map', '-f', base], check=True, env=os.environ,
                   stdout=subprocess.DEVNULL)
    with watch.lock:
        explored, status, contacts = list(watch.explored), watch.completion or watch.status, watch.contacts
    plot_explored(os.path.join(args.out, 'explored_area.png'), explored, sim0)
    precision, mean, coverage, occupied = watch.map_accuracy((x, y, yaw))
    share = watch.share()
    t95 = watch.time_to(0.95)
    print('demo: %s' % status)
    print('demo: explored %.1f %% of the %.1f m2 reachable free area; 95 %% after %s of sim time' % (
        100 * share, area.area, '%.0f s' % (t95 - sim0) if t95 else 'never'))
    print('demo: %.0f s of sim time in %.0f s of wall time (%.1fx real time; %.0f s to start up); driven %.1f m; '
          '%d wall contacts' % (sim, wall, sim / wall if wall else 0, up, watch.distance(), contacts))
    print('demo: map: %.1f %% of %d occupied cells within 0.1 m of a wall (mean %.0f mm); %.1f %% of the visible '
          'wall faces mapped' % (100 * precision, occupied, 1e3 * mean, 100 * coverage))
    print('demo: wrote %s.pgm, %s.yaml, %s.png (the map and the path) and %s' % (
        base, base, base, os.path.join(args.out, 'explored_area.png')), flush=True)
    if not (watch.completed_at is not None and share >= 0.95):
        raise RuntimeError('the exploration did not complete with 95 % explored')


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n\n')[0])
    parser.add_argument('--explorer', choices=['find_frontier', 'explore'], default='find_frontier')
    parser.add_argument('--gui', action='store_true', help='start the studio (a page in the browser, URL printed) and, with a display, rviz')
    parser.add_argument('--rtf', type=float, default=20.0,
                        help='target real-time factor (default 20; 2 cores keep up with the whole stack to 25-27x; '
                             '0: as fast as the simulator goes)')
    parser.add_argument('--start', type=float, nargs=3, default=(0.0, 0.0, 0.0), metavar=('X', 'Y', 'YAW'),
                        help='m_robot\'s start in the world (default 0 0 0, the lecture\'s)')
    parser.add_argument('--out', default=os.path.join(ROOT, 'demo_output'), help='where the map and plot go')
    parser.add_argument('--timeout', type=float, default=900.0, help='sim seconds before giving up (default 900)')
    parser.add_argument('--every', type=float, default=2.0, help='wall seconds between progress lines (default 2)')
    # roslaunch-style gui:=true, as the other launch files take it
    args = parser.parse_args(['--gui' if a in ('gui:=true', 'gui:=True') else a for a in sys.argv[1:]
                              if a not in ('gui:=false', 'gui:=False')])
    return run_with_processes('explore_demo', lambda procs: run(args, procs))


if __name__ == '__main__':
    sys.exit(main())
