#!/usr/bin/python3
"""Real-time factor of the whole bullet_sim_node with /clock and a 720-beam 40 Hz laser (issue 2).

  bench_node_rtf.py [URDF] [--seconds S]

Starts its own roscore on a free port (ROS_MASTER_URI=http://127.0.0.1:PORT, so it never
touches a running ROS system), then `rosrun bullet_sim bullet_sim_node` (the empty world:
ground plane + sun, 1 ms steps, real_time_factor 1), spawns the benchmark arm with
`rosrun bullet_sim spawn_model -urdf -file URDF -model arm5`, and subscribes to /arm5/scan
(so the laser really casts its rays: it only does with a subscriber) and /clock. It then
measures, over S seconds of wall time each (default 10):

  1. real time:    the world as loaded (real_time_factor 1)                -> expect ~1.0
  2. unthrottled:  /gazebo/set_physics_properties with max_update_rate 0
                   (time_step 0.001 and gravity kept)                       -> as fast as it runs

and prints the achieved factor (sim time advanced / wall time, from the /clock messages) and
the scan rate received (scans per second of sim time, expected 40, and per wall second).
The arm is passive in the node (no controller plugin): it folds under gravity onto its joint
limits and the ground plane within the first second, before measuring starts.

Every process it starts is stopped at the end, also on errors and Ctrl-C.
Run with Debian's /usr/bin/python3 and the workspace sourced (scripts/env.sh).
Output (parsed by scripts/bench):
  node real-time factor (real time): X
  node real-time factor (unthrottled): Y
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
SCAN_TOPIC = '/arm5/scan'


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

    def on_clock(self, msg):  # rosgraph_msgs/Clock: time clock = uint32 secs, uint32 nsecs
        secs, nsecs = struct.unpack_from('<II', msg._buff, 0)
        with self.lock:
            self.clock.append((time.monotonic(), secs + 1e-9 * nsecs))

    def on_scan(self, msg):  # sensor_msgs/LaserScan: Header first: uint32 seq, time stamp
        secs, nsecs = struct.unpack_from('<II', msg._buff, 4)
        with self.lock:
            self.scans.append((time.monotonic(), secs + 1e-9 * nsecs))

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
    return {'label': label, 'rtf': rtf, 'wall': wall, 'sim': sim, 'clock_msgs': len(clock),
            'scans': len(scans), 'scan_hz_sim': scan_hz_sim, 'scan_hz_wall': scan_hz_wall}


def report(r):
    print('node real-time factor (%s): %.2f' % (r['label'], r['rtf']))
    print('  %.2f s sim in %.2f s wall, %d /clock msgs (%.0f/s wall); %d scans on %s = %.1f Hz sim time '
          '(%.1f Hz wall)' % (r['sim'], r['wall'], r['clock_msgs'], r['clock_msgs'] / r['wall'], r['scans'], SCAN_TOPIC,
                             r['scan_hz_sim'], r['scan_hz_wall']))
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


def run(args, procs):
    port = free_port()
    env = dict(os.environ)
    env['ROS_MASTER_URI'] = 'http://127.0.0.1:%d' % port
    # Everything is local: loopback only (ROS_HOSTNAME would take precedence over ROS_IP).
    env['ROS_IP'] = '127.0.0.1'
    env.pop('ROS_HOSTNAME', None)
    env['ROS_HOME'] = procs.log_dir  # logs of this run stay in its temporary folder
    env['ROS_LOG_DIR'] = os.path.join(procs.log_dir, 'ros_log')
    os.environ.clear()
    os.environ.update(env)  # for rospy in this process

    import rosgraph
    procs.start('roscore', ['roscore', '-p', str(port)], env)
    master = rosgraph.Master('/bench_node_rtf', master_uri=env['ROS_MASTER_URI'])

    def master_up():
        try:
            master.getPid()
            return True
        except Exception:  # noqa: BLE001 - not up yet
            return False
    wait_until(master_up, 30, 'roscore on port %d' % port, procs)

    # Our node starts before the simulator sets /use_sim_time, so rospy keeps wall time and adds
    # no /clock subscriber of its own: the only readers are the two below.
    import rospy
    from gazebo_msgs.srv import GetPhysicsProperties, SetPhysicsProperties
    rospy.init_node('bench_node_rtf', anonymous=True, disable_signals=True)

    procs.start('bullet_sim_node', ['rosrun', 'bullet_sim', 'bullet_sim_node'], env)
    rec = Recorder()
    rospy.Subscriber('/clock', rospy.AnyMsg, rec.on_clock, queue_size=1000, tcp_nodelay=True)
    wait_until(lambda: rosgraph_service_up(master, '/gazebo/spawn_urdf_model'), 60,
               'service /gazebo/spawn_urdf_model of bullet_sim_node', procs)

    spawn = subprocess.run(['rosrun', 'bullet_sim', 'spawn_model', '-urdf', '-file', args.urdf, '-model', 'arm5'],
                           env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, timeout=60)
    if spawn.returncode != 0:
        raise RuntimeError('spawn_model failed (status %d):\n%s' % (spawn.returncode, spawn.stdout.decode(errors='replace')))
    rospy.Subscriber(SCAN_TOPIC, rospy.AnyMsg, rec.on_scan, queue_size=1000, tcp_nodelay=True)
    wait_until(lambda: len(rec.scans) > 0, 30, 'the first scan on %s' % SCAN_TOPIC, procs)
    time.sleep(1.0)  # let the arm settle and the connections warm up

    results = [measure(rec, args.seconds, 'real time')]
    report(results[-1])

    get_props = rospy.ServiceProxy('/gazebo/get_physics_properties', GetPhysicsProperties)
    set_props = rospy.ServiceProxy('/gazebo/set_physics_properties', SetPhysicsProperties)
    current = get_props()
    reply = set_props(time_step=0.001, max_update_rate=0.0, gravity=current.gravity, ode_config=current.ode_config)
    if not reply.success:
        raise RuntimeError('set_physics_properties refused max_update_rate 0: ' + reply.status_message)
    time.sleep(1.0)  # past the switch
    results.append(measure(rec, args.seconds, 'unthrottled'))
    report(results[-1])
    rospy.signal_shutdown('done')
    return results


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
    parser.add_argument('urdf', nargs='?', default=DEFAULT_URDF, help='the arm (default: bench/arm5.urdf)')
    parser.add_argument('--seconds', type=float, default=10.0, help='wall seconds per measurement (default 10)')
    args = parser.parse_args()
    args.urdf = os.path.abspath(args.urdf)
    if not os.path.isfile(args.urdf):
        print('bench_node_rtf: no such URDF: %s' % args.urdf, file=sys.stderr)
        return 2

    return run_with_processes('bench_node_rtf', lambda procs: run(args, procs))


if __name__ == '__main__':
    sys.exit(main())
