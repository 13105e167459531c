#!/usr/bin/python3
"""Navigation success rate, time to goal and whole-system real-time factor (issue 11): each robot's
navigation bring-up (simulator, mapper, move_base), headless at the robot's pace (m_robot 20x
real time, the Pioneer 10x: what the whole stack keeps up with on 2 cores; --rtf 0 runs as fast
as the simulator goes), drives to seeded random reachable goals one after the other.

  bench_navigation.py [--robot m_robot|pioneer] [--goals N] [--seeds K] [--first-seed S]
                      [--rtf F | --realtime] [--mapper hector|gmapping] [--cpu] [--trace CSV]
                      [--out results.jsonl] [--address HOST:PORT] [--cpus-per-run C]

The runs are split by seed: one run (a fresh bring-up, N goals one after the other) per seed, the
runs one sim_batch batch (docs/BATCH.md: each on a ROS master of its own; one at a time on this
machine by default, or on a Ray cluster with --address). This script's --check drives each run
and prints one JSON line; the table is built from sim_batch's results file.

  m_robot  find_frontier m_robot_navigation.launch (navfn + DWAPlannerROS) in the Capstone maze
  pioneer  pioneer_2dnav pioneer_navigation.launch (navfn + TrajectoryPlannerROS) in its 8 x 8 m maze

Goals are drawn from a ground-truth grid of the maze (0.05 m cells, from the walls yaml): cells at
least `goal clearance` from every wall (room to turn at the goal) in the part of the maze the
robot's inscribed circle can reach from its start, at least 1 m of path from the previous goal.
The robot starts each goal where the last one left it. A goal counts as reached when move_base
succeeds and the true position is within xy_goal_tolerance + 0.06 m (the mapper's error). For
each goal: the outcome, the sim time it took against the shortest path's length at max_vel_x (the
lower bound), and wall contact (the robot's outline from /gazebo/model_states against the walls,
every 10 ms of sim time).
The real-time factor is sim time over wall time from the first goal to the last.

Output lines (one per robot):
  navigation (<robot>): N goals (K seeds), S succeeded (P %), C wall contacts, time/lower bound
  median M (worst W), real-time factor R (sim T s in wall U s)
and with --cpu each process's CPU time over the same span, in % of one core (this benchmark's own
process included: it checks the outline against the walls every 10 ms of sim time).
"""
import argparse
import json
import heapq
import math
import os
import random
import sys
import threading
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(ROOT, 'src', 'bullet_sim_testing', 'src'))
import bench_batch  # noqa: E402
from bench_node_rtf import set_real_time_factor  # noqa: E402
from process_cpu import ProcessCpu  # noqa: E402
from bullet_sim_testing.mobile import yaw_of  # noqa: E402
from bullet_sim_testing.navigation import outline, touches_a_wall  # noqa: E402
from bullet_sim_testing.walls import load_walls  # noqa: E402

CELL = 0.05
# m: how far the mapper's pose may be off the truth when move_base says "reached"
LOCALISATION_ALLOWANCE = 0.06

# Each robot: its bring-up, model, walls, spawn pose (the map frame starts there), outline (length,
# width, centre ahead of the base), the planners' inscribed radius and max_vel_x, the goal clearance.
ROBOTS = {
    'm_robot': dict(launch=['find_frontier', 'm_robot_navigation.launch'], model='m_robot',
                    walls=os.path.join(ROOT, 'src', 'm_robot_gazebo', 'config', 'capstone_map_walls.yaml'),
                    spawn=(0.0, 0.0, 0.0), outline=(0.26, 0.22, 0.0), inscribed=0.12, max_vel=0.3,
                    goal_clearance=0.25, xy_tolerance=0.15, rtf=20.0),
    'pioneer': dict(launch=['pioneer_2dnav', 'pioneer_navigation.launch'], model='pioneer',
                    walls=os.path.join(ROOT, 'src', 'pioneer_gazebo_ros', 'pioneer_gazebo', 'config', 'pioneer_maze_walls.yaml'),
                    spawn=(-3.2, -3.2, 0.0), outline=(0.44, 0.38, -0.045), inscribed=0.22, max_vel=0.5,
                    goal_clearance=0.42, xy_tolerance=0.2, rtf=10.0),
}


class MazeGrid:
    """Wall clearance of every 0.05 m cell over the maze's bounds, and shortest paths between cells."""

    def __init__(self, walls, passable_clearance):
        xs = [w.x + s * math.hypot(w.sx, w.sy) / 2 for w in walls for s in (-1, 1)]
        ys = [w.y + s * math.hypot(w.sx, w.sy) / 2 for w in walls for s in (-1, 1)]
        self.x0, self.y0 = min(xs), min(ys)
        self.nx, self.ny = int((max(xs) - self.x0) / CELL) + 1, int((max(ys) - self.y0) / CELL) + 1
        self.clearance = [min(w.distance(*self.centre(i, j)) if not w.contains(*self.centre(i, j)) else -1.0
                              for w in walls)
                          for j in range(self.ny) for i in range(self.nx)]
        self.passable = [c >= passable_clearance for c in self.clearance]

    def centre(self, i, j):
        return self.x0 + (i + 0.5) * CELL, self.y0 + (j + 0.5) * CELL

    def cell(self, x, y):
        return int((x - self.x0) / CELL), int((y - self.y0) / CELL)

    def distances(self, x, y):
        """Shortest 8-connected path length (m) from (x, y) to every passable cell (inf elsewhere)."""
        i, j = self.cell(x, y)
        dist = [math.inf] * (self.nx * self.ny)
        start = j * self.nx + i
        dist[start] = 0.0
        queue = [(0.0, start)]
        while queue:
            d, n = heapq.heappop(queue)
            if d > dist[n]:
                continue
            ci, cj = n % self.nx, n // self.nx
            for di in (-1, 0, 1):
                for dj in (-1, 0, 1):
                    ni, nj = ci + di, cj + dj
                    if (di or dj) and 0 <= ni < self.nx and 0 <= nj < self.ny:
                        m = nj * self.nx + ni
                        step = CELL * (1.4142135 if di and dj else 1.0)
                        if self.passable[m] and d + step < dist[m]:
                            dist[m] = d + step
                            heapq.heappush(queue, (d + step, m))
        return dist


class Truth:
    """The robot's pose from /gazebo/model_states; its outline checked against the walls every 10 ms
    of sim time."""

    def __init__(self, model, walls, outline_spec):
        import rospy
        from gazebo_msgs.msg import ModelStates
        self.model, self.walls = model, walls
        length, width, centre_x = outline_spec
        self.points = outline(length, width, centre_x=centre_x)
        self.lock = threading.Lock()
        self.pose, self.last_check, self.contacts = None, -1.0, 0
        # (goal number, sim time, x, y, yaw, then the mapper's last pose: its stamp, x, y, yaw in the
        # world) every 0.25 s, for --trace. The mapper's pose is as old as its stamp says.
        self.goal, self.trace = 0, []
        self.mapped = (math.nan, math.nan, math.nan, math.nan)
        self.sub = rospy.Subscriber('/gazebo/model_states', ModelStates, self.on_states, queue_size=1)

    def follow_mapper(self, spawn):
        """Also trace the mapper's pose (slam_out_pose, in the map frame that starts at `spawn`)."""
        import rospy
        from geometry_msgs.msg import PoseStamped
        sx, sy, syaw = spawn

        def on_pose(msg):
            p = msg.pose.position
            x = sx + math.cos(syaw) * p.x - math.sin(syaw) * p.y
            y = sy + math.sin(syaw) * p.x + math.cos(syaw) * p.y
            with self.lock:
                self.mapped = (msg.header.stamp.to_sec(), x, y, syaw + yaw_of(msg.pose.orientation))
        self.pose_sub = rospy.Subscriber('/slam_out_pose', PoseStamped, on_pose, queue_size=1)

    def on_states(self, msg):
        import rospy
        if self.model not in msg.name:
            return
        p = msg.pose[msg.name.index(self.model)]
        yaw = yaw_of(p.orientation)
        now = rospy.get_time()
        with self.lock:
            self.pose = (p.position.x, p.position.y, yaw)
            if not self.trace or now - self.trace[-1][1] >= 0.25:
                self.trace.append((self.goal, now, p.position.x, p.position.y, yaw) + self.mapped)
            if now - self.last_check < 0.01:
                return
            self.last_check = now
        if touches_a_wall(self.walls, self.points, p.position.x, p.position.y, yaw):
            with self.lock:
                self.contacts += 1


def check(name, goals, seed, rtf, trace_file=None, cpu=False, mapper='hector'):
    """One run's check: the robot's navigation launch is up on this run's master (ROS_MASTER_URI);
    drives to `goals` goals drawn from `seed`, one after the other, and prints one JSON line."""
    import actionlib
    import rospy
    from actionlib_msgs.msg import GoalStatus
    from move_base_msgs.msg import MoveBaseAction, MoveBaseGoal

    robot = ROBOTS[name]
    walls = load_walls(robot['walls'])
    grid = MazeGrid(walls, robot['inscribed'])
    sx, sy, _ = robot['spawn']
    reachable = grid.distances(sx, sy)
    candidates = [n for n, d in enumerate(reachable) if d < math.inf and grid.clearance[n] >= robot['goal_clearance']]
    rng = random.Random(seed)

    # hector_mapping's map frame starts at the spawn pose; slam_gmapping's is the odom frame, which
    # the Pioneer's drive (odometrySource world) puts at the world's origin.
    map_in_world = (0.0, 0.0, 0.0) if mapper == 'gmapping' else robot['spawn']
    mx, my, myaw = map_in_world
    rospy.init_node('bench_navigation', anonymous=True, disable_signals=True)  # the launch set /use_sim_time
    rospy.wait_for_service('/gazebo/set_physics_properties', timeout=90)
    client = actionlib.SimpleActionClient('move_base', MoveBaseAction)
    bench_batch.wait_until(lambda: client.wait_for_server(rospy.Duration(1.0)), 120, 'move_base')
    truth = Truth(robot['model'], walls, robot['outline'])
    if trace_file:
        truth.follow_mapper(map_in_world)
    bench_batch.wait_until(lambda: truth.pose is not None, 30, '/gazebo/model_states')
    if rtf != 1.0:
        set_real_time_factor(rtf)

    results = []  # (succeeded, sim seconds, lower bound seconds)
    wall_start, sim_start = time.monotonic(), rospy.get_time()
    cpu_use = ProcessCpu(os.environ['ROS_LOG_DIR']) if cpu else None  # the run's nodes log there
    contacts_start = truth.contacts
    for k in range(goals):
        with truth.lock:
            x, y, _ = truth.pose
        from_here = grid.distances(x, y)
        far_enough = [n for n in candidates if 1.0 <= from_here[n] < math.inf]
        n = rng.choice(far_enough or candidates)
        gx, gy = grid.centre(n % grid.nx, n // grid.nx)
        gyaw = rng.uniform(-math.pi, math.pi)
        # The goal in the map frame.
        dx, dy = gx - mx, gy - my
        goal = MoveBaseGoal()
        goal.target_pose.header.frame_id = 'map'
        goal.target_pose.pose.position.x = math.cos(myaw) * dx + math.sin(myaw) * dy
        goal.target_pose.pose.position.y = -math.sin(myaw) * dx + math.cos(myaw) * dy
        goal.target_pose.pose.orientation.z = math.sin((gyaw - myaw) / 2)
        goal.target_pose.pose.orientation.w = math.cos((gyaw - myaw) / 2)
        bound = from_here[n] / robot['max_vel']
        with truth.lock:
            truth.goal = k + 1
        started = rospy.get_time()
        client.send_goal(goal)
        finished = client.wait_for_result(rospy.Duration(max(120.0, 10 * bound)))
        took = rospy.get_time() - started
        if not finished:
            client.cancel_goal()
            client.wait_for_result(rospy.Duration(10))
        with truth.lock:
            px, py, _ = truth.pose
        error = math.hypot(px - gx, py - gy)
        said_reached = finished and client.get_state() == GoalStatus.SUCCEEDED
        # Reached by ground truth too: within the tolerance, give or take the mapper's error.
        ok = said_reached and error <= robot['xy_tolerance'] + LOCALISATION_ALLOWANCE
        results.append({'goal': [round(gx, 3), round(gy, 3)], 'ok': ok, 'outcome': None,
                        'sim_s': took, 'bound_s': bound, 'error_m': error})
        if ok:
            results[-1]['outcome'] = 'reached'
        elif said_reached:
            results[-1]['outcome'] = 'FAILED (move_base succeeded, but the robot is beyond tolerance)'
        else:
            results[-1]['outcome'] = 'FAILED (%s)' % (client.get_goal_status_text() or 'timeout')
    wall = time.monotonic() - wall_start
    sim = rospy.get_time() - sim_start
    if trace_file:
        with open(trace_file, 'w') as f, truth.lock:
            f.write('goal,t,x,y,yaw,mapped_t,mapped_x,mapped_y,mapped_yaw\n')
            f.writelines('%d,%.2f,%.3f,%.3f,%.3f,%.3f,%.3f,%.3f,%.3f\n' % row for row in truth.trace)
    print(json.dumps({'seed': seed, 'goals': results, 'contacts': truth.contacts - contacts_start, 'sim': sim,
                      'wall': wall, 'sim_time': rospy.get_time(), 'cpu': cpu_use.report() if cpu_use else None}),
          flush=True)


def scenario(name, goals, seeds, rtf, mapper, trace, cpu):
    """The batch's scenario: one run (one bring-up, `goals` goals one after the other) per seed."""
    robot = ROBOTS[name]
    options = ['--robot', name, '--goals', goals, '--rtf', rtf, '--mapper', mapper] + (['--cpu'] if cpu else [])
    if trace:  # one file per seed
        options += ['--trace', '%s.seed${seed}.csv' % os.path.abspath(trace)]
    return {'name': 'navigation_%s' % name, 'launch': ' '.join(robot['launch']),
            'args': {'mapper': 'gmapping'} if mapper == 'gmapping' else {},
            'check': bench_batch.check_command(__file__, *(options + ['--check', '${seed}'])),
            'seeds': seeds, 'time_limit': 300.0 + goals * 120.0}


def bench(name, goals, seeds, rtf, mapper, trace, cpu, args):
    records, _ = bench_batch.run(scenario(name, goals, seeds, rtf, mapper, trace, cpu), args, 2, 'bench_navigation')
    results, contacts, sim, wall, lost = [], 0, 0.0, 0.0, 0
    for record in records:
        r = bench_batch.result_of(record)
        if r is None:
            print('  %s: %s' % (record['run_id'], bench_batch.describe_failure(record)), flush=True)
            lost += 1
            continue
        print('  seed %d (%s):' % (r['seed'], record.get('host')), flush=True)
        for k, g in enumerate(r['goals']):
            print('    goal %2d (%5.2f, %5.2f): %s in %5.1f s (lower bound %4.1f s), stopped %.3f m from it' % (
                k + 1, g['goal'][0], g['goal'][1], g['outcome'], g['sim_s'], g['bound_s'], g['error_m']), flush=True)
        if r['cpu']:
            print('    cpu, %% of one core from the first goal to the last: %s' % r['cpu'], flush=True)
        results += r['goals']
        contacts, sim, wall = contacts + r['contacts'], sim + r['sim'], wall + r['wall']
    planned = goals * len(seeds)
    succeeded = sum(1 for g in results if g['ok'])
    ratios = sorted(g['sim_s'] / g['bound_s'] for g in results if g['ok'] and g['bound_s'] > 0)
    median = ratios[len(ratios) // 2] if ratios else float('nan')
    worst = ratios[-1] if ratios else float('nan')
    print('navigation (%s): %d goals (%d seeds), %d succeeded (%.0f %%), %d wall contacts, time/lower bound median '
          '%.2f (worst %.2f), real-time factor %.2f (sim %.0f s in wall %.0f s)' % (
              name, planned, len(seeds), succeeded, 100.0 * succeeded / planned, contacts, median, worst,
              sim / wall if wall else float('nan'), sim, wall), flush=True)
    return 1 if lost else 0  # a run that did not run; missed goals are the benchmark's figures


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n\n')[0])
    parser.add_argument('--robot', choices=sorted(ROBOTS), help='one robot (default: both, each in its own process)')
    parser.add_argument('--goals', type=int, default=10, help='goals per run, one after the other (default 10)')
    parser.add_argument('--seeds', type=int, default=5, help='runs per robot, one per seed (default 5)')
    parser.add_argument('--first-seed', type=int, default=1, help='the first run\'s goals\' random seed (default 1)')
    parser.add_argument('--seed', type=int, help='one run, with this seed: --first-seed S --seeds 1 (what the '
                                                 'benchmark did before it was split by seed)')
    parser.add_argument('--rtf', type=float,
                        help='the simulator\'s target real-time factor (default: the robot\'s, m_robot 20, the Pioneer '
                             '10; 0: as fast as it goes)')
    parser.add_argument('--realtime', action='store_true', help='the same as --rtf 1')
    parser.add_argument('--mapper', choices=['hector', 'gmapping'], default='hector',
                        help='the Pioneer\'s mapper: hector_mapping (default) or the report\'s slam_gmapping')
    parser.add_argument('--cpu', action='store_true', help='print each process\'s CPU use (one robot)')
    parser.add_argument('--trace', metavar='CSV',
                        help='write the true pose and the mapper\'s every 0.25 s of sim time to CSV.seedN.csv')
    bench_batch.add_arguments(parser)
    parser.add_argument('--check', type=int, metavar='SEED', help=argparse.SUPPRESS)
    args = parser.parse_args()
    rtf = 1.0 if args.realtime else args.rtf
    if args.check is not None:
        return check(args.robot, args.goals, args.check, rtf, args.trace, args.cpu, args.mapper)
    if args.mapper == 'gmapping' and args.robot != 'pioneer':
        parser.error('--mapper gmapping: only the Pioneer has odometry for slam_gmapping')
    if args.out and not args.robot:
        parser.error('--out needs one --robot (a results file holds one batch)')
    if args.seed is not None:
        args.first_seed, args.seeds = args.seed, 1
    seeds = list(range(args.first_seed, args.first_seed + args.seeds))
    status = 0
    for name in [args.robot] if args.robot else sorted(ROBOTS):
        robot_rtf = ROBOTS[name]['rtf'] if rtf is None else rtf
        print('command: scripts/bench_navigation.py --robot %s --goals %d --seeds %d --first-seed %d --rtf %g%s%s' % (
            name, args.goals, args.seeds, args.first_seed, robot_rtf,
            ' --mapper gmapping' if args.mapper == 'gmapping' else '', ' --cpu' if args.cpu else ''), flush=True)
        status |= bench(name, args.goals, seeds, robot_rtf, args.mapper, args.trace, args.cpu, args)
    return status


if __name__ == '__main__':
    sys.exit(main())
