#!/usr/bin/env python3
"""The World view's benchmark (issue 35): frame rate, pose latency and the simulator's slow-down,
in Debian's headless Chromium on this machine, for the Katana world and the Capstone maze.

  src/sim_studio_tests/bench/bench_studio_world.py [--worlds katana,maze] [--seconds 10] [--moves 50]
                                             [--rounds 10] [--rtf-seconds 4]

Each world runs in a roslaunch of its own (bench/studio_world_bench.launch: the world and the
studio; its own master), measured by a child process of this script:

- Frame rate, the simulator at its own pace (real time): (a) drawing every animation frame (the
  page's capacity: what it shows when everything moves) and (b) as the page draws by default,
  only what changed, while the world moves (the Katana's arm sweeping on its trajectory
  controller; m_robot turning on the spot). Frames counted over --seconds.
- Latency: a static box moved --moves times with /gazebo/set_model_state, alternating between
  two spots 0.5 m apart; the page stamps the wall time of the first frame it draws with the box
  at the new spot (window.studio.world.whenAt), against the wall time just before the call.
- Slow-down: the simulator unthrottled (max_update_rate 0), its real-time factor over
  --rtf-seconds with the browser away from the page (about:blank) and on it (drawing as it does
  by default), alternating --rounds times, with the world at rest and then moving (as above,
  the sweep timed in sim time), then with the page drawing every frame (the worst case). Each page window is compared with the windows either side of it (1 - page / none); the
  median and quartiles of those, since other work on the machine comes and goes.

Targets: >= 30 frames a second, < 100 ms latency, <= 5 % slow-down. The machine is shared: the
load average before and after each world is printed with its figures.
"""
import argparse
import json
import math
import os
import signal
import socket
import statistics
import subprocess
import sys
import threading
import time

HERE = os.path.dirname(os.path.abspath(__file__))
COMMAND = "src/sim_studio_tests/bench/bench_studio_world.py"
EXPECTED = {"katana": ["table", "katana", "can_1", "can_2", "can_3"], "maze": ["Capstone_Map", "m_robot"]}
BOX_SPOT = {"katana": (1.5, -1.5), "maze": (2.5, -1.5)}  # free ground, in view
BOX_SDF = """<?xml version="1.0"?><sdf version="1.6"><model name="bench_box"><static>true</static>
<link name="link"><visual name="v"><geometry><box><size>0.3 0.3 0.3</size></box></geometry></visual>
<collision name="c"><geometry><box><size>0.3 0.3 0.3</size></box></geometry></collision></link></model></sdf>"""


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def load_average():
    return os.getloadavg()[0]


# --- one world, in a child process with its own master -----------------------------------------
class World:
    """The launched world and studio, the /gazebo services, and a browser on the page."""

    def __init__(self, name):
        import rospy
        from bullet_sim_testing.gazebo import Gazebo
        from bullet_sim_testing.waiting import wait_until
        self.name = name
        port = free_port()
        os.environ["ROS_MASTER_URI"] = "http://127.0.0.1:%d" % port
        self.launch = subprocess.Popen(["roslaunch", "-p", str(port), os.path.join(HERE, "studio_world_bench.launch"),
                                        "world:=" + name], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                                       start_new_session=True)
        deadline = time.monotonic() + 30
        while subprocess.call(["rosparam", "get", "/run_id"], stdout=subprocess.DEVNULL,
                              stderr=subprocess.DEVNULL) != 0:
            if time.monotonic() > deadline:
                raise SystemExit("roslaunch did not start a master on port %d" % port)
            time.sleep(0.3)
        rospy.init_node("bench_studio_world", disable_signals=True)
        self.gazebo = Gazebo(timeout=60.0)
        if not wait_until(lambda: set(EXPECTED[name]) <= set(self.gazebo.get_world_properties().model_names), 90.0):
            raise SystemExit("%s: the world's models did not appear" % name)
        self.driver = None

    def url(self):
        sys.path.insert(0, os.path.join(HERE, "..", "test", "browser"))
        from studio_browser import studio_url
        return studio_url()

    def open_page(self):
        sys.path.insert(0, os.path.join(HERE, "..", "test", "browser"))
        from studio_browser import open_browser, open_studio, wait_for
        self.driver = open_browser()
        open_studio(self.driver, self.url())
        wait_for(self.driver, "return window.studio.world.visualObjects() > 0 && window.studio.world.meshesLoaded()",
                 30.0, "the world drawn")

    def close_page(self):
        if self.driver is not None:
            self.driver.quit()
            self.driver = None

    def js(self, script):
        return self.driver.execute_script("return " + script)

    def set_target(self, factor):
        from bullet_sim_testing.gazebo import set_real_time_factor
        set_real_time_factor(factor)

    def rtf(self, seconds, cpu=None):
        """Sim seconds per wall second over `seconds`, from the simulator's own clock. With
        `cpu` (a dict), the cores the simulator, the studio and the browser used meanwhile are
        appended to its lists."""
        processes = {"simulator": [node_pid("/gazebo")], "studio": [node_pid("/sim_studio")],
                     "browser": [self.driver.service.process.pid] if self.driver else []}
        used = {k: cpu_seconds(v) for k, v in processes.items()}
        sim0, wall0 = self.gazebo.sim_time(), time.monotonic()
        time.sleep(seconds)
        sim1, wall1 = self.gazebo.sim_time(), time.monotonic()
        if cpu is not None:
            for k, v in processes.items():
                cpu.setdefault(k, []).append((cpu_seconds(v) - used[k]) / (wall1 - wall0))
        return (sim1 - sim0) / (wall1 - wall0)

    def close(self):
        self.close_page()
        try:
            os.killpg(self.launch.pid, signal.SIGINT)
            self.launch.wait(20)
        except (subprocess.TimeoutExpired, ProcessLookupError):
            os.killpg(self.launch.pid, signal.SIGKILL)


HZ = os.sysconf("SC_CLK_TCK")


def cpu_seconds(pids):
    """CPU time (user + system) the processes and their children have used, in seconds."""
    children = {}
    for entry in filter(str.isdigit, os.listdir("/proc")):
        try:
            with open("/proc/%s/stat" % entry) as f:
                children.setdefault(int(f.read().rsplit(")", 1)[1].split()[1]), []).append(int(entry))
        except OSError:
            pass
    total, todo = 0, list(pids)
    while todo:
        pid = todo.pop()
        todo += children.get(pid, [])
        try:
            with open("/proc/%d/stat" % pid) as f:
                fields = f.read().rsplit(")", 1)[1].split()
            total += int(fields[11]) + int(fields[12])
        except OSError:
            pass
    return total / HZ


def node_pid(name):
    import rosgraph
    import xmlrpc.client
    uri = rosgraph.Master("/bench_studio_world").lookupNode(name)
    return xmlrpc.client.ServerProxy(uri).getPid("/bench_studio_world")[2]


def frame_rate(world, seconds):
    """Animation frames drawn per second, and pose frames applied per second."""
    a = world.js("window.studio.world.stats()")
    time.sleep(seconds)
    b = world.js("window.studio.world.stats()")
    wall = (b["at"] - a["at"]) / 1000.0
    return (b["renders"] - a["renders"]) / wall, (b["poseFrames"] - a["poseFrames"]) / wall


class Motion:
    """Keeps the world moving while the on-demand frame rate is measured."""

    def __init__(self, world):
        import rospy
        self.world, self.stop_flag = world, threading.Event()
        if world.name == "maze":
            from geometry_msgs.msg import Twist
            self.publisher = rospy.Publisher("/cmd_vel", Twist, queue_size=1)
            self.thread = threading.Thread(target=self._turn, daemon=True)
        else:
            from trajectory_msgs.msg import JointTrajectory
            self.publisher = rospy.Publisher("/katana_arm_controller/command", JointTrajectory, queue_size=1)
            self.thread = threading.Thread(target=self._sweep, daemon=True)

    def __enter__(self):
        time.sleep(0.5)  # the subscriber connects
        self.thread.start()
        return self

    def __exit__(self, *exc):
        self.stop_flag.set()
        self.thread.join()

    def _turn(self):
        from geometry_msgs.msg import Twist
        turning = Twist()
        turning.angular.z = 1.0
        while not self.stop_flag.wait(0.1):
            self.publisher.publish(turning)
        self.publisher.publish(Twist())

    def _sweep(self):
        import rospy
        from sensor_msgs.msg import JointState
        from trajectory_msgs.msg import JointTrajectory, JointTrajectoryPoint
        joints = rospy.get_param("/katana_arm_controller/joints")
        state = rospy.wait_for_message("/joint_states", JointState, timeout=10.0)
        held = [state.position[state.name.index(j)] if j in state.name else 0.0 for j in joints]
        sign = 1.0
        while not self.stop_flag.is_set():
            goal = JointTrajectory(joint_names=joints)
            target = list(held)
            target[0] = sign * 1.2  # the pan joint sweeps the arm around its base
            goal.points = [JointTrajectoryPoint(positions=target, time_from_start=rospy.Duration(2.0))]
            self.publisher.publish(goal)
            sign = -sign
            until = rospy.get_time() + 2.2  # sim time: the sweep keeps the arm moving at any pace
            while rospy.get_time() < until and not self.stop_flag.wait(0.01):
                pass


def latency(world, moves):
    """Wall milliseconds from a set_model_state call to the page's first frame showing it."""
    from gazebo_msgs.msg import ModelState
    from geometry_msgs.msg import Pose
    x0, y0 = BOX_SPOT[world.name]
    pose = Pose()
    pose.position.x, pose.position.y, pose.position.z = x0, y0, 0.15
    pose.orientation.w = 1.0
    reply = world.gazebo.spawn_sdf_model(model_name="bench_box", model_xml=BOX_SDF, robot_namespace="",
                                         initial_pose=pose, reference_frame="world")
    assert reply.success, reply.status_message
    deadline = time.monotonic() + 10
    while world.js("window.studio.world.linkPosition('bench_box::link')") is None:
        assert time.monotonic() < deadline, "the page did not draw the benchmark's box"
        time.sleep(0.05)
    samples, arrivals, calls = [], [], []
    for i in range(moves):
        pose.position.x = x0 + (0.5 if i % 2 == 0 else 0.0)
        world.js("(window.benchArrived = null, window.studio.world.whenAt('bench_box::link', %f, %f, 0.0005)"
                 ".then((t) => { window.benchArrived = t; }), true)" % (pose.position.x, pose.position.y))
        sent = time.time() * 1000.0
        reply = world.gazebo.set_model_state(model_state=ModelState(model_name="bench_box", pose=pose,
                                                                    reference_frame="world"))
        calls.append(time.time() * 1000.0 - sent)
        assert reply.success, reply.status_message
        # One call that waits in the page: polling through the driver would load the machine it measures.
        arrived = world.driver.execute_async_script(
            "const done = arguments[arguments.length - 1];"
            "const check = () => (window.benchArrived !== null ? done(window.benchArrived) : setTimeout(check, 1));"
            "setTimeout(() => done(null), 2000); check();")
        assert arrived is not None, "move %d never reached the page" % i
        samples.append(arrived["drawn"] - sent)
        arrivals.append(arrived["arrived"] - sent)
        time.sleep(0.05 + 0.05 * (i % 3))  # not in step with the page's frames
    world.gazebo.delete_model(model_name="bench_box")
    return samples, arrivals, calls


def percentile(values, share):
    ordered = sorted(values)
    return ordered[min(len(ordered) - 1, int(math.ceil(share * len(ordered))) - 1)]


def slowdown_runs(world, seconds, rounds):
    """The unthrottled real-time factor with the page away (the browser on about:blank) and with
    it shown, alternating `rounds` times so that the machine's other load falls on both, first
    with the world at rest and then moving (Motion); then with the page drawing every frame.
    The slow-down pairs each page window with the mean of the windows around it."""
    result = alternate(world, seconds, rounds)
    with Motion(world):
        time.sleep(1.0)
        moving = alternate(world, seconds, rounds)
    result.update({key + "_moving": value for key, value in moving.items()})
    world.driver.get("about:blank")
    time.sleep(2.0)
    none = world.rtf(seconds)
    from studio_browser import open_studio
    open_studio(world.driver, world.url())
    time.sleep(2.0)
    world.js("(window.studio.world.setContinuous(true), true)")
    time.sleep(1.0)
    every_frame = world.rtf(seconds)
    result.update(rtf_page_every_frame=every_frame, slowdown_every_frame=1.0 - every_frame / none)
    return result


def alternate(world, seconds, rounds):
    none, page, drawn = [], [], []
    cpu_none, cpu_page = {}, {}
    url = world.url()
    from studio_browser import open_studio
    for _ in range(rounds):
        world.driver.get("about:blank")
        time.sleep(2.0)
        none.append(world.rtf(seconds, cpu_none))
        open_studio(world.driver, url)
        world.js("window.studio.world.visualObjects() > 0")
        time.sleep(2.0)
        before = world.js("window.studio.world.stats()")
        page.append(world.rtf(seconds, cpu_page))
        after = world.js("window.studio.world.stats()")
        drawn.append((after["renders"] - before["renders"]) / ((after["at"] - before["at"]) / 1000.0))
    world.driver.get("about:blank")
    time.sleep(2.0)
    none.append(world.rtf(seconds))
    ratios = [p / ((none[i] + none[i + 1]) / 2) for i, p in enumerate(page)]
    return {"rtf_none": none, "rtf_page": page, "page_frames": drawn,
            "slowdown": 1.0 - statistics.median(ratios), "slowdown_q1": 1.0 - percentile(ratios, 0.75),
            "slowdown_q3": 1.0 - percentile(ratios, 0.25),
            "cpu_none": {k: statistics.median(v) for k, v in cpu_none.items()},
            "cpu_page": {k: statistics.median(v) for k, v in cpu_page.items()}}


def measure(name, seconds, moves, rounds, rtf_seconds):
    world = World(name)
    result = {"world": name, "load_before": load_average()}
    try:
        world.set_target(1.0)
        world.open_page()
        time.sleep(2.0)
        world.js("(window.studio.world.setContinuous(true), true)")
        time.sleep(1.0)
        result["fps_every_frame"], _ = frame_rate(world, seconds)
        world.js("(window.studio.world.setContinuous(false), true)")
        with Motion(world):
            time.sleep(1.0)
            result["fps_moving"], result["pose_frames_moving"] = frame_rate(world, seconds)
        time.sleep(1.0)
        samples, arrivals, calls = latency(world, moves)
        result.update(latency_median=statistics.median(samples), latency_p95=percentile(samples, 0.95),
                      latency_max=max(samples), arrival_median=statistics.median(arrivals),
                      arrival_p95=percentile(arrivals, 0.95), call_median=statistics.median(calls),
                      call_p95=percentile(calls, 0.95), moves=len(samples))

        world.set_target(0.0)  # unthrottled
        result.update(slowdown_runs(world, rtf_seconds, rounds))
    finally:
        world.close()
    result["load_after"] = load_average()
    return result


# --- the parent: one child per world, then the table ------------------------------------------
def report_slowdown(r, suffix, label):
    """The alternating windows' figures, at rest (suffix "") or moving ("_moving")."""
    none, page, cpu_none, cpu_page = (r["rtf_none" + suffix], r["rtf_page" + suffix], r["cpu_none" + suffix],
                                      r["cpu_page" + suffix])
    print("  %s: unthrottled RTF, no page %s" % (label, ", ".join("%.1f" % v for v in none)))
    print("  %s: unthrottled RTF, page    %s  (page frames/s %s)" % (
        label, ", ".join("%.1f" % v for v in page), ", ".join("%.1f" % v for v in r["page_frames" + suffix])))
    print("  %s: slow-down with one page: median %.1f %% (quartiles %.1f, %.1f %%; target <= 5 %%)"
          % (label, 100 * r["slowdown" + suffix], 100 * r["slowdown_q1" + suffix], 100 * r["slowdown_q3" + suffix]))
    print("  %s: cores used, no page / page: simulator %.2f / %.2f, studio %.3f / %.3f, browser %.3f / %.3f"
          % (label, cpu_none["simulator"], cpu_page["simulator"], cpu_none["studio"], cpu_page["studio"],
             cpu_none["browser"], cpu_page["browser"]))


def report(results, argv):
    print("\nStudio World view, headless Chromium (SwiftShader), %d cores, %s" % (os.cpu_count(), time.strftime("%Y-%m-%d")))
    for r in results:
        print("\n%s  (load average %.1f before, %.1f after)" % (r["world"], r["load_before"], r["load_after"]))
        print("  frames/s, drawing every frame:        %5.1f   (target >= 30)" % r["fps_every_frame"])
        print("  frames/s, default, world moving:      %5.1f   (pose frames/s %.1f)" % (r["fps_moving"],
                                                                                          r["pose_frames_moving"]))
        print("  set_model_state -> drawn, ms:         median %.1f, p95 %.1f, max %.1f over %d moves (target < 100)"
              % (r["latency_median"], r["latency_p95"], r["latency_max"], r["moves"]))
        print("    of which: the call returns          median %.1f, p95 %.1f" % (r["call_median"], r["call_p95"]))
        print("              the poses reach the page  median %.1f, p95 %.1f" % (r["arrival_median"], r["arrival_p95"]))
        report_slowdown(r, "", "world at rest")
        report_slowdown(r, "_moving", "world moving")
        print("  unthrottled RTF, page drawing always: %.1f  -> slow-down %.1f %%"
              % (r["rtf_page_every_frame"], 100 * r["slowdown_every_frame"]))
    print("\nreproduce: %s %s" % (COMMAND, " ".join(argv)))


def measure_in_children(script, worlds, arguments):
    """Each of the comma-separated `worlds` measured by `script --one WORLD ARGUMENTS` in a child
    process of its own (its own roslaunch and master): the children's RESULT dicts, in order."""
    results = []
    for name in worlds.split(","):
        if name not in EXPECTED:
            raise SystemExit("--worlds: expected katana and/or maze, got %r" % name)
        print("measuring %s ..." % name, flush=True)
        child = subprocess.run([sys.executable, script, "--one", name] + arguments, stdout=subprocess.PIPE, text=True)
        lines = [line for line in child.stdout.splitlines() if line.startswith("RESULT ")]
        if child.returncode != 0 or not lines:
            raise SystemExit("%s: the measurement failed (exit %d):\n%s" % (name, child.returncode, child.stdout))
        results.append(json.loads(lines[-1][len("RESULT "):]))
    return results


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--worlds", default="katana,maze", help="comma-separated: katana, maze")
    parser.add_argument("--seconds", type=float, default=10.0, help="each frame-rate and RTF window (wall s)")
    parser.add_argument("--moves", type=int, default=50, help="set_model_state moves timed")
    parser.add_argument("--rounds", type=int, default=10, help="slow-down: alternations of no page / one page")
    parser.add_argument("--rtf-seconds", type=float, default=4.0, help="slow-down: each window (wall s)")
    parser.add_argument("--one", help=argparse.SUPPRESS)  # the child's job: measure this world
    args = parser.parse_args()
    if args.one:
        print("RESULT " + json.dumps(measure(args.one, args.seconds, args.moves, args.rounds, args.rtf_seconds)),
              flush=True)
        return
    results = measure_in_children(os.path.abspath(__file__), args.worlds,
                                  ["--seconds", str(args.seconds), "--moves", str(args.moves),
                                   "--rounds", str(args.rounds), "--rtf-seconds", str(args.rtf_seconds)])
    report(results, sys.argv[1:])


if __name__ == "__main__":
    main()
