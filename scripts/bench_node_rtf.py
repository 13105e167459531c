#!/usr/bin/python3
"""Real-time factor of the whole bullet_sim_node against PyBullet's step rate, in one run (issue 10).

  bench_node_rtf.py [--seconds S] [--rounds N] [--world empty|no_ground|both] [--no-pybullet]

For each world, starts its own roscore on a free port (so it never touches a running ROS system)
and brings up src/bullet_sim/bench/arm5_node_bench.launch: gazebo_ros's empty_world.launch (/clock
at its pub_clock_frequency of 100 Hz of sim time) with either the empty world (a ground plane) or
bench/no_ground.world (nothing: as physics_bench and PyBullet have it), the benchmark arm of
physics_bench and bench_pybullet.py (5 joints, a 720-beam 40 Hz laser) with ros_control running the
same PD law on every joint at every 1 ms step, and /arm5/joint_states at 50 Hz. It subscribes to
/clock, /arm5/scan and /arm5/joint_states (the laser only casts its rays while someone listens), and
measures over S wall seconds (default 8):

  1. real time:    the world as loaded (real_time_factor 1)                 -> expect 1.0
  2. N rounds (default 3) of: PyBullet on the same arm (bench_pybullet.py, one run of 10 s of sim
     time, with the simulation paused), then the node unthrottled (max_update_rate 0). The
     machine's speed drifts, so each round compares the two measured back to back, and the median
     ratio is reported. The node's steps/s is its factor times 1000 (1 ms steps).

then stops the node, which prints where its loop's time went (--timing). PyBullet comes from
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
import socket
import struct
import subprocess
import sys
import tempfile
import threading
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

    def stop_all(self):
        # Newest first (the node before the master); SIGINT like Ctrl-C, then TERM, then KILL.
        for name, proc in reversed(self.procs):
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
        self.procs = []


def free_port():
    with socket.socket(socket.AF_INET, socket.SOCK_STREAM) as s:
        s.bind(('127.0.0.1', 0))
        return s.getsockname()[1]


class Recorder:
    """/clock and scan arrivals as (wall time, stamp), read straight from the serialized bytes."""

    def __init__(self):
        self.lock = threading.Lock()
        self.clock = []  # (monotonic wall s, sim s)
        self.scans = []  # (monotonic wall s, header stamp s)
        self.joint_states = []  # (monotonic wall s, header stamp s)

    def on_clock(self, msg):  # rosgraph_msgs/Clock: time clock = uint32 secs, uint32 nsecs
        secs, nsecs = struct.unpack_from('<II', msg._buff, 0)
        with self.lock:
            self.clock.append((time.monotonic(), secs + 1e-9 * nsecs))

    def on_scan(self, msg):  # sensor_msgs/LaserScan: Header first: uint32 seq, time stamp
        secs, nsecs = struct.unpack_from('<II', msg._buff, 4)
        with self.lock:
            self.scans.append((time.monotonic(), secs + 1e-9 * nsecs))

    def on_joint_states(self, msg):  # sensor_msgs/JointState: Header first
        secs, nsecs = struct.unpack_from('<II', msg._buff, 4)
        with self.lock:
            self.joint_states.append((time.monotonic(), secs + 1e-9 * nsecs))

    def window(self, start, end):
        with self.lock:
            clock = [c for c in self.clock if start <= c[0] <= end]
            scans = [s for s in self.scans if start <= s[0] <= end]
        return clock, scans


def measure(recorder, seconds, label):
    start = time.monotonic()
    time.sleep(seconds)
    end = time.monotonic()
    clock, scans = recorder.window(start, end)
    if len(clock) < 2:
        raise RuntimeError('%s: fewer than 2 /clock messages in %.0f s of wall time: is the simulation running?' %
                           (label, seconds))
    wall = clock[-1][0] - clock[0][0]
    sim = clock[-1][1] - clock[0][1]
    rtf = sim / wall if wall > 0 else float('nan')
    # Scans stamped inside the sim-time span of the window.
    in_span = [s for s in scans if clock[0][1] < s[1] <= clock[-1][1]]
    scan_hz_sim = len(in_span) / sim if sim > 0 else 0.0
    scan_hz_wall = len(scans) / (end - start)
    with recorder.lock:
        joint_states = [j for j in recorder.joint_states if clock[0][1] < j[1] <= clock[-1][1]]
    return {'label': label, 'rtf': rtf, 'wall': wall, 'sim': sim, 'clock_msgs': len(clock),
            'scans': len(scans), 'scan_hz_sim': scan_hz_sim, 'scan_hz_wall': scan_hz_wall,
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


def run(args, procs):
    import rospy
    from controller_manager_msgs.srv import ListControllers
    from std_srvs.srv import Empty
    master = launch_on_private_master(procs, 'bench_node_rtf', [BENCH_LAUNCH, 'world_name:=' + WORLDS[args.world],
                                                                'extra_gazebo_args:=--timing'])
    rec = Recorder()
    rospy.Subscriber('/clock', rospy.AnyMsg, rec.on_clock, queue_size=1000, tcp_nodelay=True)
    rospy.Subscriber(SCAN_TOPIC, rospy.AnyMsg, rec.on_scan, queue_size=1000, tcp_nodelay=True)
    rospy.Subscriber(JOINT_STATES_TOPIC, rospy.AnyMsg, rec.on_joint_states, queue_size=1000, tcp_nodelay=True)
    wait_until(lambda: rosgraph_service_up(master, '/arm5/controller_manager/list_controllers'), 90,
               'the arm\'s controller manager', procs)
    lister = rospy.ServiceProxy('/arm5/controller_manager/list_controllers', ListControllers)
    wait_until(lambda: sum(c.state == 'running' for c in lister().controller) == 6, 60, 'six running controllers',
               procs)
    wait_until(lambda: len(rec.scans) > 0 and len(rec.joint_states) > 0, 30, 'a scan and a joint state', procs)
    time.sleep(1.0)  # let the arm settle and the connections warm up

    print('world: %s' % args.world)
    report(measure(rec, args.seconds, 'real time'))
    unthrottle()
    pause = rospy.ServiceProxy('/gazebo/pause_physics', Empty)
    unpause = rospy.ServiceProxy('/gazebo/unpause_physics', Empty)
    # The machine's speed drifts (a shared VM): each round measures PyBullet with the simulation
    # paused, then the node, and compares the two.
    ratios = []
    for _ in range(args.rounds):
        rate = None
        if not args.no_pybullet:
            pause()
            rate = pybullet_rate(10)
            unpause()
        time.sleep(0.5)  # past the switch
        result = measure(rec, args.seconds, 'unthrottled')
        report(result)
        if rate:
            ratios.append(result['rtf'] / 0.001 / rate)
            print('  PyBullet just before: %.0f steps/s; node %.0f steps/s = %.2f x PyBullet'
                  % (rate, result['rtf'] / 0.001, ratios[-1]))
    if ratios:
        print('node / PyBullet steps per second (%s, median of %d rounds): %.2f  (target >= 2.5)'
              % (args.world, len(ratios), sorted(ratios)[len(ratios) // 2]))
    rospy.signal_shutdown('done')
    procs.stop_all()  # the node prints where its loop's time went as it exits
    log = procs.log_tail('launch', 40)
    if 'bullet_sim loop timing' in log:
        print('bullet_sim loop timing' + log.split('bullet_sim loop timing', 1)[1])


def launch_on_private_master(procs, name, launch_args):
    """A roscore of our own on a free port, then `roslaunch LAUNCH_ARGS` against it, and this process
    made a ROS node there. Returns the master (rosgraph.Master). The environment is changed for good:
    call once per process."""
    port = free_port()
    env = dict(os.environ, ROS_MASTER_URI='http://127.0.0.1:%d' % port, ROS_IP='127.0.0.1',
               ROS_HOME=procs.log_dir, ROS_LOG_DIR=os.path.join(procs.log_dir, 'ros_log'))
    env.pop('ROS_HOSTNAME', None)
    os.environ.clear()
    os.environ.update(env)
    import rosgraph
    import rospy
    procs.start('roscore', ['roscore', '-p', str(port)], env)
    master = rosgraph.Master('/' + name, master_uri=env['ROS_MASTER_URI'])
    wait_until(lambda: rosgraph_service_up(master, '/rosout/get_loggers'), 30, 'roscore', procs)
    procs.start('launch', ['roslaunch'] + list(launch_args), env)
    rospy.init_node(name, anonymous=True, disable_signals=True)
    return master


def unthrottle():
    """/gazebo/set_physics_properties with max_update_rate 0 (time step and gravity kept)."""
    import rospy
    from gazebo_msgs.srv import GetPhysicsProperties, SetPhysicsProperties
    props = rospy.ServiceProxy('/gazebo/get_physics_properties', GetPhysicsProperties)()
    rospy.ServiceProxy('/gazebo/set_physics_properties', SetPhysicsProperties)(
        time_step=props.time_step, max_update_rate=0.0, gravity=props.gravity, ode_config=props.ode_config)


def run_with_processes(name, work):
    """work(procs) with a fresh log folder; every process it started is stopped at the end, also on
    errors, Ctrl-C and SIGTERM (e.g. from a timeout). Returns the exit status: 0, 1 on an error
    (printed, with where the logs are kept) or 130 when interrupted."""
    signal.signal(signal.SIGTERM, lambda *_: sys.exit(143))
    log_dir = tempfile.mkdtemp(prefix=name + '.')
    procs = Processes(log_dir)
    try:
        work(procs)
        procs.stop_all()
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
    parser.add_argument('--seconds', type=float, default=8.0, help='wall seconds per measurement (default 8)')
    parser.add_argument('--rounds', type=int, default=3, help='unthrottled measurements, each after PyBullet\'s')
    parser.add_argument('--world', choices=sorted(WORLDS) + ['both'], default='both')
    parser.add_argument('--no-pybullet', action='store_true', help='skip the PyBullet comparison')
    args = parser.parse_args()
    if args.world == 'both':  # one process per world: rospy cannot move to another master
        return max(subprocess.call([sys.executable, os.path.abspath(__file__)] + sys.argv[1:] + ['--world', world])
                   for world in ('empty', 'no_ground'))
    return run_with_processes('bench_node_rtf', lambda procs: run(args, procs))


if __name__ == '__main__':
    sys.exit(main())
