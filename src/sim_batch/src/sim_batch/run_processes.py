"""A run's processes: the jobs it starts (master, launch, check), each a process group of its
own as a terminal makes one per command line, and everything those start, wherever it goes:
roslaunch starts each node in a session of its own, out of every group here. Every process of a
run carries the run's token in its environment (SIM_BATCH_RUN_TOKEN, inherited through
roslaunch), and that is how the last of them are found.

Stopped as a user stops them, newest first: Ctrl-C (SIGINT) to each job's group and time for it
to end (the check; roslaunch, which stops its nodes; the master last, so that nothing loses its
master while it shuts down); then SIGTERM and SIGKILL to every process that still carries the
token. A SIGINT sent to every process at once lost a race in roscore now and then, and it sat
out the whole grace period.
"""
import os
import signal
import subprocess
import sys
import time

TOKEN_VARIABLE = "SIM_BATCH_RUN_TOKEN"
STOP_GRACE_S = 20.0  # for a job to end after its SIGINT (roslaunch escalates by itself after 15 s)
TERM_GRACE_S = 2.0


class RunProcesses:
    def __init__(self, folder, token):
        self.folder = folder
        self.token = token
        self.processes = []
        self._reaper_started = False
        self._jobs_file = os.path.join(folder, "jobs")

    def start(self, name, argv, env):
        """A job; its output goes to logs/<name>.log. `env` must carry the run's token."""
        assert env.get(TOKEN_VARIABLE) == self.token
        with open(self.log_path(name), "ab") as out:
            # plain_signals: SIGINT unblocked and default (a Ray worker runs tasks with it blocked)
            process = subprocess.Popen([sys.executable, "-m", "sim_batch.plain_signals"] + argv, env=env,
                                       cwd=env["TMPDIR"], stdin=subprocess.DEVNULL, stdout=out,
                                       stderr=subprocess.STDOUT, process_group=0)
        process.name = name
        self.processes.append(process)
        with open(self._jobs_file, "a") as f:
            f.write("%d\n" % process.pid)
        if not self._reaper_started:  # the run's keeper, should this process die without stop()
            keeper_env = {k: v for k, v in env.items() if k != TOKEN_VARIABLE}  # it must not kill itself
            subprocess.run([sys.executable, "-m", "sim_batch.reaper", str(os.getpid()), self.token, self._jobs_file],
                           env=keeper_env, stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL,
                           stderr=subprocess.DEVNULL, check=True)  # returns at once: the reaper is a daemon
            self._reaper_started = True
        return process

    def log_path(self, name):
        return os.path.join(self.folder, "logs", name + ".log")

    def output(self, name):
        with open(self.log_path(name), "rb") as f:
            return f.read().decode("utf-8", "replace")

    def tail(self, name, lines=5):
        try:
            text = self.output(name)
        except OSError:
            return "nothing"
        return " | ".join(text.strip().splitlines()[-lines:]) or "nothing"

    def stop(self):
        stop_run([p.pid for p in self.processes], self.token, self.processes)
        self.processes = []
        self._reaper_started = False  # it sees the jobs file gone and ends
        try:
            os.remove(self._jobs_file)
        except OSError:
            pass


def stop_run(jobs, token, processes=()):
    """Each job's group SIGINT in turn, newest first, until its leader ends; then SIGTERM and
    SIGKILL to every process carrying `token` (nodes roslaunch left, a shell's background jobs,
    which ignore SIGINT)."""
    ours = {p.pid: p for p in processes}
    for pgid in reversed(jobs):
        try:
            os.killpg(pgid, signal.SIGINT)
        except ProcessLookupError:
            continue
        deadline = time.monotonic() + STOP_GRACE_S
        while time.monotonic() < deadline and leader_alive(pgid, ours.get(pgid)):
            time.sleep(0.05)
    for sig, grace in ((signal.SIGTERM, TERM_GRACE_S), (signal.SIGKILL, 5.0)):
        left = carrying(token)
        for pid in left:
            try:
                os.kill(pid, sig)
            except ProcessLookupError:
                pass
        deadline = time.monotonic() + grace
        while left and time.monotonic() < deadline:
            time.sleep(0.05)
            for p in processes:
                p.poll()  # reap our own
            left = carrying(token)
    for p in processes:
        try:
            p.wait(timeout=1.0)
        except subprocess.TimeoutExpired:
            pass


def leader_alive(pgid, process):
    if process is not None:
        return process.poll() is None  # our child: poll() also reaps it
    return process_alive(pgid)


def process_alive(pid):
    """Running and not a zombie (a killed process its parent has not reaped yet is dead here)."""
    try:
        with open("/proc/%d/stat" % pid) as f:
            return f.read().rsplit(")", 1)[1].split()[0] != "Z"
    except OSError:
        return False


def carrying(token):
    """Live processes whose environment holds the run's token (this process aside)."""
    needle = ("%s=%s" % (TOKEN_VARIABLE, token)).encode()
    found = []
    for entry in os.listdir("/proc"):
        if not entry.isdigit() or int(entry) == os.getpid():
            continue
        try:
            with open("/proc/%s/environ" % entry, "rb") as f:
                if needle not in f.read().split(b"\0"):
                    continue
        except OSError:
            continue
        if process_alive(int(entry)):
            found.append(int(entry))
    return found
