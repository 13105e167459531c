"""CPU time per process of one bring-up, for the benchmarks' `--cpu` (Linux /proc, no ROS).

  sampler = ProcessCpu(marker)     # every process whose command line contains `marker`, and this one
  ...                              # the work being measured
  print(sampler.report())          # 'gazebo 67.7 %, move_base 47.4 %, ... (total 182.6 % of 2 cores)'

The benchmarks start their nodes with `__log:=<their own log folder>`, so that folder marks them
(and the roscore, whose log folder is the same) apart from anything else on the machine. A process
is named by its ROS node name (`__name:=`), else by its executable.
"""
import os

TICKS = os.sysconf('SC_CLK_TCK')


def _uptime():
    """Seconds since boot: the wall clock the CPU times are measured against."""
    with open('/proc/uptime') as f:
        return float(f.read().split()[0])


def _cpu_seconds(pid):
    """User + system CPU seconds of `pid` (its threads included), or None when it is gone."""
    try:
        with open('/proc/%s/stat' % pid) as f:
            fields = f.read().rsplit(')', 1)[1].split()
    except OSError:
        return None
    return (int(fields[11]) + int(fields[12])) / TICKS  # utime, stime


def _command_line(pid):
    try:
        with open('/proc/%s/cmdline' % pid, 'rb') as f:
            return f.read().decode(errors='replace').split('\0')
    except OSError:
        return []


def _name(args):
    for a in args:
        if a.startswith('__name:='):
            return a[len('__name:='):]
    if not args:
        return '?'
    # An interpreter's script is the more telling name (rosmaster, joint_state_publisher, ...).
    exe = os.path.basename(args[0])
    if exe.startswith('python') and len(args) > 1:
        return os.path.basename(args[1])
    return exe


class ProcessCpu:
    def __init__(self, marker):
        self.marker = marker
        self.start = self._snapshot()
        self.wall_start = _uptime()

    def _snapshot(self):
        taken = {}
        for pid in os.listdir('/proc'):
            if not pid.isdigit():
                continue
            args = _command_line(pid)
            if int(pid) != os.getpid() and not any(self.marker in a for a in args):
                continue
            seconds = _cpu_seconds(pid)
            if seconds is not None:
                taken[pid] = (_name(args), seconds)
        return taken

    def shares(self):
        """[(name, percent of one core)] since construction, largest first."""
        wall = max(_uptime() - self.wall_start, 1e-9)
        end = self._snapshot()
        rows = [(name, 100.0 * (seconds - self.start.get(pid, (name, 0.0))[1]) / wall)
                for pid, (name, seconds) in end.items()]
        return sorted(rows, key=lambda r: -r[1])

    def report(self):
        rows = self.shares()
        total = sum(p for _, p in rows)
        return '%s (total %.1f %% of %d cores)' % (
            ', '.join('%s %.1f %%' % (n, p) for n, p in rows if p >= 0.5), total, os.cpu_count() or 1)

