"""One run, isolated, on the machine this is called on (a Ray worker): its own ROS master on a
free port, its own ROS_HOME, ROS_LOG_DIR and TMPDIR, its processes started as jobs and stopped
as a user stops them, all of them, when the run ends or reaches its time limit
(run_processes.py). No rospy here: one worker runs many runs one after another, each on its own
master, and rospy binds a process to one master.

A run is either `launch` + `check` (the launch started, then the check run beside it; the
check's last JSON line is the result and its end ends the run) or `command` (the whole run; its
last JSON line is the result).
"""
import io
import json
import os
import resource
import shlex
import shutil
import socket
import subprocess
import sys
import tarfile
import tempfile
import time
import uuid
import xmlrpc.client

from sim_batch.run_processes import RunProcesses

PORT_ATTEMPTS = 5          # a port found free can be taken before roscore binds it
MASTER_WAIT_S = 20.0       # roscore's start, on a loaded machine
CLOCK_WAIT_S = 3.0
LAUNCH_WAIT_S = 60.0       # for the launch's first node (its parameters are set before it)


def run_isolated(run, scratch_dir=None):
    """Runs `run` (scenario.Run) and returns its record (a dict for the results file) and, for a
    run that did not end "ok", a .tar.gz of its logs (bytes; else None)."""
    started, cpu_before = time.monotonic(), children_cpu_s()
    folder = tempfile.mkdtemp(prefix="sim_batch_", dir=scratch_dir)
    record = {"run_id": run.run_id, "scenario": run.scenario, "params": run.params, "seed": run.seed,
              "host": socket.gethostname(), "cpu_model": cpu_model(), "sim_s": None, "result": None,
              "error": None}
    token = uuid.uuid4().hex
    jobs = RunProcesses(folder, token)
    try:
        env = isolated_env(run, folder, token)
        port = start_master(jobs, env)
        env["ROS_MASTER_URI"] = record["master"] = "http://127.0.0.1:%d" % port
        deadline = started + run.time_limit
        if run.command is not None:
            main = jobs.start("command", ["bash", "-c", run.command], env)
        else:
            launch = jobs.start("launch", ["roslaunch", "--wait"] + shlex.split(run.launch) + list(run.launch_args), env)
            wait_for_launch(port, launch, deadline)
            main = jobs.start("check", ["bash", "-c", run.check], env)
        try:
            main.wait(timeout=max(0.0, deadline - time.monotonic()))
        except subprocess.TimeoutExpired:
            record.update(state="timeout", error="killed at its time limit, %.0f s" % run.time_limit)
        else:
            record["exit_code"] = main.returncode
            record["result"] = last_json_line(jobs.output(main.name))
            if main.returncode != 0:
                record.update(state="failed", error="%s exited with status %d" % (main.name, main.returncode))
            elif record["result"] is None:
                record.update(state="failed", error="%s printed no JSON line (its last line of JSON is the result)"
                              % main.name)
            else:
                record["state"] = "ok"
        reported = (record["result"] or {}).get("sim_time")
        if isinstance(reported, (int, float)):  # the check's own word
            record["sim_s"] = reported
        elif record["state"] != "timeout":
            record["sim_s"] = sim_time(env, port)
    except MasterError as e:
        record.update(state="failed", error=str(e))
    finally:
        jobs.stop()
        record["wall_s"] = round(time.monotonic() - started, 3)
        record["cpu_s"] = round(children_cpu_s() - cpu_before, 3)
        archive = logs_archive(folder) if record.get("state") != "ok" else None
        shutil.rmtree(folder, ignore_errors=True)
    return record, archive


def children_cpu_s():
    """CPU seconds (user + system) of this process's ended and waited-for descendants: a run's
    master, launch (with every node roslaunch waited for) and check, once they have stopped. A
    worker runs one run at a time, so the difference over a run is that run's."""
    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    return usage.ru_utime + usage.ru_stime


class MasterError(RuntimeError):
    pass


def start_master(jobs, env):
    """roscore on a free port: the port (tried again on another if it was taken meanwhile)."""
    for attempt in range(1, PORT_ATTEMPTS + 1):
        port = free_port()
        master = jobs.start("roscore", ["roscore", "-p", str(port)], env)
        deadline = time.monotonic() + MASTER_WAIT_S
        while time.monotonic() < deadline:
            if master_answers(port):
                return port
            if master.poll() is not None:
                break  # the port was taken, or roscore could not start: another port
            time.sleep(0.05)
        jobs.stop()
    raise MasterError("no ROS master would start (%d ports tried); roscore said: %s"
                      % (PORT_ATTEMPTS, jobs.tail("roscore")))


def isolated_env(run, folder, token):
    env = dict(os.environ)
    for sub in ("ros_home", "ros_log", "tmp", "logs"):
        os.makedirs(os.path.join(folder, sub), exist_ok=True)
    env.update(ROS_HOME=os.path.join(folder, "ros_home"), ROS_LOG_DIR=os.path.join(folder, "ros_log"),
               TMPDIR=os.path.join(folder, "tmp"), SIM_BATCH_RUN_ID=run.run_id, SIM_BATCH_RUN_TOKEN=token,
               SIM_BATCH_PARAMS=json.dumps(run.params, sort_keys=True))
    env.pop("ROS_IP", None)
    env["ROS_HOSTNAME"] = "127.0.0.1"  # the run's nodes talk on loopback only: no run sees another's
    if run.seed is not None:
        env["SIM_BATCH_SEED"] = str(run.seed)
    env.update({k: v for k, v in run.env.items() if k != "SIM_BATCH_RUN_TOKEN"})
    return env


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def master_answers(port):
    """roscore is up: its master answers and its /rosout runs. Only then has roslaunch finished
    starting; a SIGINT before that was now and then lost, and roscore ran on until killed."""
    try:
        proxy = xmlrpc.client.ServerProxy("http://127.0.0.1:%d" % port)
        return proxy.lookupNode("/sim_batch", "/rosout")[0] == 1
    except (OSError, xmlrpc.client.Error):
        return False


def wait_for_launch(port, launch, deadline):
    """Until a node of the launch has registered with the master: roslaunch sets every parameter
    (/use_sim_time among them) before it starts a node, and a check started sooner would read a
    master without them (rospy would run on the wall clock). Gives up at LAUNCH_WAIT_S, at the
    deadline, or when roslaunch has ended."""
    until = min(deadline, time.monotonic() + LAUNCH_WAIT_S)
    proxy = xmlrpc.client.ServerProxy("http://127.0.0.1:%d" % port)
    while time.monotonic() < until and launch.poll() is None:
        try:
            code, _, state = proxy.getSystemState("/sim_batch")
        except (OSError, xmlrpc.client.Error):
            state, code = None, 0
        if code == 1 and any(node != "/rosout" for kind in state for _, nodes in kind for node in nodes):
            return
        time.sleep(0.05)


def sim_time(env, port):
    """The sim time at the end, from /clock, when the run used sim time; else None."""
    try:
        proxy = xmlrpc.client.ServerProxy("http://127.0.0.1:%d" % port)
        code, _, use_sim_time = proxy.getParam("/sim_batch", "/use_sim_time")
    except (OSError, xmlrpc.client.Error):
        return None
    if code != 1 or not use_sim_time:
        return None
    try:
        out = subprocess.run(["rostopic", "echo", "-n", "1", "/clock/clock"], env=env, capture_output=True,
                             text=True, timeout=CLOCK_WAIT_S).stdout
    except subprocess.TimeoutExpired:
        return None
    secs = nsecs = None
    for line in out.splitlines():
        key, _, value = line.partition(":")
        if key.strip() == "secs":
            secs = int(value)
        elif key.strip() == "nsecs":
            nsecs = int(value)
    return None if secs is None or nsecs is None else secs + nsecs * 1e-9


def last_json_line(text):
    """The last line of `text` that is a JSON object, or None."""
    for line in reversed(text.splitlines()):
        line = line.strip()
        if line.startswith("{"):
            try:
                value = json.loads(line)
            except ValueError:
                continue
            if isinstance(value, dict):
                return value
    return None


def cpu_model():
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name"):
                    return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return "unknown"


def logs_archive(folder):
    """The run's logs (the processes' output and ROS's log folder) as .tar.gz bytes."""
    buffer = io.BytesIO()
    with tarfile.open(fileobj=buffer, mode="w:gz") as tar:
        for sub in ("logs", "ros_log"):
            path = os.path.join(folder, sub)
            if os.path.isdir(path):
                tar.add(path, arcname=sub)
    return buffer.getvalue()
