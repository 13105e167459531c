#!/usr/bin/python3
"""Real-time factor of the whole bullet_sim_node against PyBullet's step rate, in one run (issue 10).

  bench_node_rtf.py [--seconds S] [--rounds N] [--world empty|no_ground|both] [--no-pybullet]

For each world, starts its own roscore on a free port (so it never touches a running ROS system)
and brings up src/bullet_sim/bench/arm5_node_bench.launch: gazebo_ros's empty_world.launch (/clock
at its pub_clock_frequency of 100 Hz of sim time) with either the empty world (a ground plane) or
bench/no_ground.world (nothing: as physics_bench and PyBullet have it), the benchmark arm of
physics_bench and bench_pybullet.py (5 joints, a 720-beam 40 Hz laser) with ros_control running the
same PD law on every joint at every 1 ms step, and /arm5/joint_states at 50 Hz. A C++ listener
(bullet_sim/topic_arrivals) subscribes to /clock, /arm5/scan and /arm5/joint_states (the laser only
casts its rays while someone listens) and records every arrival; this script is no ROS node (so
nothing else of it listens to /clock) and measures windows of S wall seconds (default 3):

  1. real time:    the world as loaded (real_time_factor 1)                 -> expect 1.0
  2. N rounds (default 9) of: PyBullet on the same arm (bench_pybullet.py, one run of 60 s of sim
     time, with the simulation paused), then the node unthrottled (max_update_rate 0). The
     machine's speed drifts, so each round compares the two measured back to back, and the median
     ratio is reported. The node's steps/s is its factor times 1000 (1 ms steps).

then brings the node up again with --timing for one unthrottled window and prints where its loop's
time went (timing costs the loop about a tenth, so the measured rounds run without it). PyBullet comes from
`scripts/setup --bench`. Every process it starts is stopped at the end, also on errors and Ctrl-C.
Run with Debian's /usr/bin/python3 and the workspace sourced (scripts/env.sh).
Output (parsed by scripts/bench):
  node real-time factor (real time): X
  node real-time factor (unthrottled): Y
  node / PyBullet steps per second (WORLD, median of N rounds): R
"""
import argparse
import os
import shutil
import signal
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
DEFAULT_URDF = os.path.join(HERE, '..', 'src', 'bullet_sim_core', 'bench', 'arm5.urdf')
BENCH_LAUNCH = os.path.join(HERE, '..', 'src', 'bullet_sim', 'bench', 'arm5_node_bench.launch')
# gazebo_ros's empty world (with the ground plane), and the arm alone, as physics_bench and PyBullet have it.
WORLDS = {'empty': os.path.join(HERE, '..', 'src', 'bullet_sim', 'worlds', 'empty.world'),
          'no_ground': os.path.join(HERE, '..', 'src', 'bullet_sim', 'bench', 'no_ground.world')}
SCAN_TOPIC = '/arm5/scan'
JOINT_STATES_TOPIC = '/arm5/joint_states'


class Processes:
    """The processes this script started, each in its own process group; stops them all."""

    def __init__(self, log_dir):
        self.log_dir = log_dir
        self.procs = []

    def start(self, name, argv, env):
        log = open(os.path.join(self.log_dir, name + '.log'), 'wb')
        proc = subprocess.Popen(argv, env=env, stdout=log, stderr=subprocess.STDOUT, stdin=subprocess.DEVNULL,
                                start_new_session=True)
        log.close()
        self.procs.append((name, proc))
        return proc

    def log_tail(self, name, lines=15):
        try:
            with open(os.path.join(self.log_dir, name + '.log'), 'rb') as f:
                return b''.join(f.readlines()[-lines:]).decode(errors='replace')
        except OSError:
            return ''

    def named(self, name):
        return next(proc for n, proc in self.procs if n == name)

    def stop(self, proc):
        """SIGINT like Ctrl-C, then TERM, then KILL; forgotten once stopped."""
        for sig, wait in ((signal.SIGINT, 5.0), (signal.SIGTERM, 3.0), (signal.SIGKILL, 3.0)):
            if proc.poll() is not None:
                break
            try:
                os.killpg(proc.pid, sig)  # the group of this child only (start_new_session)
            except ProcessLookupError:
                break
            try:
                proc.wait(wait)
            except subprocess.TimeoutExpired:
                pass
        self.procs = [(n, p) for n, p in self.procs if p is not proc]

    def stop_all(self):
        for _, proc in reversed(self.procs):  # newest first (the node before the master)
            self.stop(proc)


class Arrivals:
    """/clock, scan and joint-state arrivals as (monotonic wall s, sim stamp s), recorded by the C++
    listener bullet_sim/topic_arrivals (a Python subscriber would compete with the node for the CPU)
    and read once it has stopped."""

    def __init__(self, path):
        self.clock, self.scans, self.joint_states = [], [], []
        by_kind = {'clock': self.clock, 'scan': self.scans, 'joint_states': self.joint_states}
        with open(path) as f:
            for line in f:
                kind, wall, stamp = line.split()
                by_kind[kind].append((float(wall), float(stamp)))


class ArrivalListener:
    """bullet_sim/topic_arrivals in a process of its own, recording /clock and, when given, a scan
    and a joint-state topic; stop() returns what it recorded as Arrivals."""

    def __init__(self, procs, name, scan_topic=None, joint_states_topic=None):
        self.procs, self.file = procs, os.path.join(procs.log_dir, name + '_arrivals.txt')
        self.proc = procs.start(name + '_listener', ['rosrun', 'bullet_sim', 'topic_arrivals', self.file,
                                                     scan_topic or '-', joint_states_topic or '-'], os.environ)

    def wait_ready(self):
        wait_until(lambda: os.path.exists(self.file + '.ready'), 30, 'a first message on each recorded topic',
                   self.procs)

    def stop(self):
        self.procs.stop(self.proc)  # it writes what it recorded as it exits
        return Arrivals(self.file)


def wall_window(label, seconds):
    """(label, start, end): `seconds` of wall time from now, slept through."""
    start = time.monotonic()
    time.sleep(seconds)
    return label, start, time.monotonic()


def measure(arrivals, start, end, label):
    """The real-time factor and topic rates over the wall-time window [start, end]."""
    clock = [c for c in arrivals.clock if start <= c[0] <= end]
    scans = [s for s in arrivals.scans if start <= s[0] <= end]
    if len(clock) < 2:
        raise RuntimeError('%s: fewer than 2 /clock messages in %.0f s of wall time: was the simulation running?' %
                           (label, end - start))
    wall = clock[-1][0] - clock[0][0]
    sim = clock[-1][1] - clock[0][1]
    rtf = sim / wall if wall > 0 else float('nan')
    # Scans and joint states stamped inside the sim-time span of the window.
    in_span = [s for s in scans if clock[0][1] < s[1] <= clock[-1][1]]
    joint_states = [j for j in arrivals.joint_states if clock[0][1] < j[1] <= clock[-1][1]]
    return {'label': label, 'rtf': rtf, 'wall': wall, 'sim': sim, 'clock_msgs': len(clock),
            'sim_span': (clock[0][1], clock[-1][1]),
            'scans': len(scans), 'scan_hz_sim': len(in_span) / sim if sim > 0 else 0.0,
            'scan_hz_wall': len(scans) / (end - start),
            'joint_states_hz_sim': len(joint_states) / sim if sim > 0 else 0.0}


def report(r):
    print('node real-time factor (%s): %.2f' % (r['label'], r['rtf']))
    print('  %.2f s sim in %.2f s wall, %d /clock msgs (%.0f/s wall); %d scans on %s = %.1f Hz sim time '
          '(%.1f Hz wall)' % (r['sim'], r['wall'], r['clock_msgs'], r['clock_msgs'] / r['wall'], r['scans'], SCAN_TOPIC,
                             r['scan_hz_sim'], r['scan_hz_wall']))
    if r['joint_states_hz_sim']:
        print('  %s at %.1f Hz sim time' % (JOINT_STATES_TOPIC, r['joint_states_hz_sim']))
    sys.stdout.flush()


def wait_until(predicate, timeout, what, procs):
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        if predicate():
            return
        for name, proc in procs.procs:
            if proc.poll() is not None:
                raise RuntimeError('%s exited with status %s while waiting for %s:\n%s' %
                                   (name, proc.returncode, what, procs.log_tail(name)))
        time.sleep(0.1)
    raise RuntimeError('timed out after %.0f s waiting for %s' % (timeout, what))


def pybullet_rate(seconds):
    """PyBullet's steps/s on the same arm (bench_pybullet.py, one timed run)."""
    python = os.environ.get('BENCH_PYTHON', os.path.join(HERE, '..', '.venv', 'bin', 'python'))
    done = subprocess.run([python, os.path.join(HERE, 'bench_pybullet.py'), DEFAULT_URDF, str(seconds), '1'],
                          stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    rate = [float(line.split(':')[1]) for line in done.stdout.splitlines() if line.startswith('pybullet steps/s:')]
    if done.returncode != 0 or not rate:
        raise RuntimeError('bench_pybullet.py failed (status %d; scripts/setup --bench installs PyBullet):\n%s'
                           % (done.returncode, done.stdout[-2000:]))
    return rate[0]


def bring_up(procs, master, name, arrivals_file):
    """Starts the listener; waits for the arm's six controllers to run and for a first message on
    each topic; returns the listener's process."""
    import rospy
    from controller_manager_msgs.srv import ListControllers
    listener = procs.start(name + '_listener', ['rosrun', 'bullet_sim', 'topic_arrivals', arrivals_file, SCAN_TOPIC,
                                                JOINT_STATES_TOPIC], os.environ)
    wait_until(lambda: rosgraph_service_up(master, '/arm5/controller_manager/list_controllers'), 90,
               'the arm\'s controller manager', procs)
    lister = rospy.ServiceProxy('/arm5/controller_manager/list_controllers', ListControllers)
    wait_until(lambda: sum(c.state == 'running' for c in lister().controller) == 6, 60, 'six running controllers',
               procs)
    wait_until(lambda: os.path.exists(arrivals_file + '.ready'), 30, 'a clock, a scan and a joint state', procs)
    time.sleep(1.0)  # let the arm settle and the connections warm up
    return listener


def run(args, procs):
    import rospy
    from std_srvs.srv import Empty
    launch_args = [BENCH_LAUNCH, 'world_name:=' + WORLDS[args.world]]
    master = launch_on_private_master(procs, 'bench_node_rtf', launch_args, node=False)
    arrivals_file = os.path.join(procs.log_dir, 'arrivals.txt')
    listener = bring_up(procs, master, 'rounds', arrivals_file)

    # Windows of wall time to measure, with PyBullet's steps/s measured just before each.
    windows = [('real time', time.monotonic(), None)]
    time.sleep(args.seconds)
    windows[-1] += (time.monotonic(),)
    unthrottle()
    pause = rospy.ServiceProxy('/gazebo/pause_physics', Empty)
    unpause = rospy.ServiceProxy('/gazebo/unpause_physics', Empty)
    # The machine's speed drifts (a shared VM): each round measures PyBullet with the simulation
    # paused, then the node, and compares the two.
    for _ in range(args.rounds):
        rate = None
        if not args.no_pybullet:
            pause()
            rate = pybullet_rate(60)  # about a second of wall time
            unpause()
        time.sleep(0.5)  # past the switch
        windows.append(('unthrottled', time.monotonic(), rate))
        time.sleep(args.seconds)
        windows[-1] += (time.monotonic(),)
    procs.stop(listener)  # it writes what it recorded as it exits
    arrivals = Arrivals(arrivals_file)

    print('world: %s' % args.world)
    ratios = []
    for label, start, rate, end in windows:
        result = measure(arrivals, start, end, label)
        report(result)
        if rate:
            ratios.append(result['rtf'] / 0.001 / rate)
            print('  PyBullet just before: %.0f steps/s; node %.0f steps/s = %.2f x PyBullet'
                  % (rate, result['rtf'] / 0.001, ratios[-1]))
    if ratios:
        print('node / PyBullet steps per second (%s, median of %d rounds): %.2f  (target >= 2.5)'
              % (args.world, len(ratios), sorted(ratios)[len(ratios) // 2]))
    sys.stdout.flush()

    # Where the loop's time goes: the same again with --timing (its clock reads cost the loop about
    # a tenth, so the rounds above run without it), unthrottled for one window.
    procs.stop(procs.named('launch'))
    timed = procs.start('timed_launch', ['roslaunch'] + launch_args + ['extra_gazebo_args:=--timing'], os.environ)
    listener = bring_up(procs, master, 'timed', os.path.join(procs.log_dir, 'timed_arrivals.txt'))
    unthrottle()
    time.sleep(args.seconds)
    procs.stop(listener)
    procs.stop(timed)  # the node prints where its loop's time went as it exits
    log = procs.log_tail('timed_launch', 40)
    if 'bullet_sim loop timing' in log:
        print('bullet_sim loop timing (a separate run with --timing)' + log.split('bullet_sim loop timing', 1)[1])


class _MasterJobs:
    """What sim_batch's start_master needs of a job list, over Processes."""

    def __init__(self, procs):
        self.procs = procs

    def start(self, name, argv, env):
        return self.procs.start(name, argv, env)

    def stop(self):
        self.procs.stop_all()

    def tail(self, name):
        return self.procs.log_tail(name, lines=5)


def launch_on_private_master(procs, name, launch_args, node=True):
    """A roscore of our own on a free port (sim_batch's: the one way this workspace starts a private
    master), then `roslaunch LAUNCH_ARGS` against it, and (if node) this process made a ROS node
    there (service calls need none). Returns the master (rosgraph.Master). The environment is
    changed for good: call once per process."""
    sys.path.insert(0, os.path.join(HERE, '..', 'src', 'sim_batch', 'src'))
    from sim_batch.isolated_run import start_master
    env = dict(os.environ, ROS_IP='127.0.0.1', ROS_HOME=procs.log_dir, ROS_LOG_DIR=os.path.join(procs.log_dir, 'ros_log'))
    env.pop('ROS_HOSTNAME', None)
    port = start_master(_MasterJobs(procs), env)
    env['ROS_MASTER_URI'] = 'http://127.0.0.1:%d' % port
    os.environ.clear()
    os.environ.update(env)
    import rosgraph
    import rospy
    master = rosgraph.Master('/' + name, master_uri=env['ROS_MASTER_URI'])
    procs.start('launch', ['roslaunch'] + list(launch_args), env)
    if node:
        rospy.init_node(name, anonymous=True, disable_signals=True)
    return master


def set_real_time_factor(rtf):
    """The simulator's target real-time factor (0: as fast as it goes); bullet_sim_testing's."""
    sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), 'src',
                                    'bullet_sim_testing', 'src'))
    from bullet_sim_testing.gazebo import set_real_time_factor as set_rtf
    set_rtf(rtf)


def unthrottle():
    """/gazebo/set_physics_properties with max_update_rate 0 (time step and gravity kept)."""
    set_real_time_factor(0.0)


def run_with_processes(name, work):
    """work(procs) with a fresh log folder; every process it started is stopped at the end, also on
    errors, Ctrl-C and SIGTERM (e.g. from a timeout). Returns the exit status: 0, 1 on an error
    (printed, with where the logs are kept) or 130 when interrupted. The logs are deleted after a
    success unless the environment has BENCH_KEEP_LOGS set."""
    signal.signal(signal.SIGTERM, lambda *_: sys.exit(143))
    log_dir = tempfile.mkdtemp(prefix=name + '.')
    procs = Processes(log_dir)
    try:
        work(procs)
        procs.stop_all()
        if os.environ.get('BENCH_KEEP_LOGS'):
            print('%s: logs kept in %s' % (name, log_dir))
        else:
            shutil.rmtree(log_dir, ignore_errors=True)  # kept only when something went wrong
        return 0
    except KeyboardInterrupt:
        print('%s: interrupted' % name, file=sys.stderr)
        return 130
    except Exception as e:  # noqa: BLE001 - reported, then everything is stopped
        print('%s: %s (logs in %s)' % (name, e, log_dir), file=sys.stderr)
        return 1
    finally:
        procs.stop_all()


def each_robot_in_its_own_process(script, robots, extra_args=()):
    """Runs `script --robot R [extra_args]` for each robot in turn; the or of their exit statuses.
    One process per robot because rospy cannot move to another master once initialised."""
    status = 0
    for robot in robots:
        status |= subprocess.call([sys.executable, os.path.abspath(script), '--robot', robot] + list(extra_args))
    return status


def rosgraph_service_up(master, name):
    try:
        master.lookupService(name)
        return True
    except Exception:  # noqa: BLE001 - not registered yet
        return False


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n\n')[0])
    parser.add_argument('--seconds', type=float, default=3.0, help='wall seconds per measurement (default 3)')
    parser.add_argument('--rounds', type=int, default=9,
                        help='unthrottled measurements, each after PyBullet\'s (default 9: the VM\'s speed drifts)')
    parser.add_argument('--world', choices=sorted(WORLDS) + ['both'], default='both')
    parser.add_argument('--no-pybullet', action='store_true', help='skip the PyBullet comparison')
    args = parser.parse_args()
    if args.world == 'both':  # one process per world: rospy cannot move to another master
        return max(subprocess.call([sys.executable, os.path.abspath(__file__)] + sys.argv[1:] + ['--world', world])
                   for world in ('empty', 'no_ground'))
    return run_with_processes('bench_node_rtf', lambda procs: run(args, procs))


if __name__ == '__main__':
    sys.exit(main())
