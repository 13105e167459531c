"""A run's processes: each started as a job of its own (its own process group, as a terminal
makes one per command line), stopped as a user would stop them, newest first: Ctrl-C (SIGINT to
the job's group: the check, then roslaunch, which stops its nodes, then the master last, so that
nothing loses its master while it shuts down), then SIGTERM and SIGKILL for whatever is left.

Sending SIGINT to every process at once loses a race in roscore now and then (rosmaster gone
before roslaunch's own shutdown asks it something): it then sat out the whole grace period.
"""
import os
import signal
import subprocess
import sys
import time

STOP_GRACE_S = 20.0  # for a job to end after its SIGINT (roslaunch escalates by itself after 15 s)
TERM_GRACE_S = 2.0


class RunProcesses:
    def __init__(self, folder):
        self.folder = folder
        self.processes = []
        self._reaper = None
        self._groups_file = os.path.join(folder, "process_groups")

    def start(self, name, argv, env):
        """A job; its output goes to logs/<name>.log."""
        with open(self.log_path(name), "ab") as out:
            # plain_signals: SIGINT unblocked and default (a Ray worker runs tasks with it blocked)
            process = subprocess.Popen([sys.executable, "-m", "sim_batch.plain_signals"] + argv, env=env,
                                       cwd=env["TMPDIR"], stdin=subprocess.DEVNULL, stdout=out,
                                       stderr=subprocess.STDOUT, process_group=0)
        process.name = name
        self.processes.append(process)
        with open(self._groups_file, "a") as f:
            f.write("%d\n" % process.pid)
        if self._reaper is None:  # the jobs' keeper, should this process die without stop()
            self._reaper = subprocess.Popen(
                [sys.executable, "-m", "sim_batch.reaper", str(os.getpid()), self._groups_file], env=env,
                stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, start_new_session=True)
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
        stop_groups([p.pid for p in self.processes], self.processes)
        self.processes = []
        self._reaper = None  # it sees the file gone and ends
        try:
            os.remove(self._groups_file)
        except OSError:
            pass


def stop_groups(pgids, processes=()):
    """Each group SIGINT in turn, newest first, until its leader ends; then SIGTERM and SIGKILL to
    every group for what is left (e.g. a shell's background jobs, which ignore SIGINT)."""
    leaders = {p.pid: p for p in processes}
    for pgid in reversed(pgids):
        if not signal_group(pgid, signal.SIGINT):
            continue
        deadline = time.monotonic() + STOP_GRACE_S
        while time.monotonic() < deadline and leader_alive(pgid, leaders.get(pgid)):
            time.sleep(0.05)
    for sig, grace in ((signal.SIGTERM, TERM_GRACE_S), (signal.SIGKILL, 5.0)):
        alive = [g for g in pgids if group_alive(g) and signal_group(g, sig)]
        deadline = time.monotonic() + grace
        while alive and time.monotonic() < deadline:
            time.sleep(0.05)
            alive = [g for g in alive if group_alive(g)]
    for p in processes:
        try:
            p.wait(timeout=1.0)
        except subprocess.TimeoutExpired:
            pass


def signal_group(pgid, sig):
    try:
        os.killpg(pgid, sig)
        return True
    except ProcessLookupError:
        return False


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


def group_alive(pgid):
    """A live (not zombie) process in the group."""
    for entry in os.listdir("/proc"):
        if entry.isdigit():
            try:
                with open("/proc/%s/stat" % entry) as f:
                    fields = f.read().rsplit(")", 1)[1].split()
            except OSError:
                continue
            if int(fields[2]) == pgid and fields[0] != "Z":
                return True
    return False
