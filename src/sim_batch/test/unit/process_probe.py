"""What the tests look for among the machine's processes (test helper, not a test)."""
import os
import subprocess


def pids(pattern):
    """Processes whose command line holds `pattern` (pgrep leaves itself out; no shell around it)."""
    found = subprocess.run(["pgrep", "-f", pattern], capture_output=True, text=True).stdout.split()
    return {int(p) for p in found}


def alive(pattern):
    return bool(pids(pattern))


def carrying_a_run_token():
    """Any process of any run: each carries its run's SIM_BATCH_RUN_TOKEN in its environment."""
    for pid in filter(str.isdigit, os.listdir("/proc")):
        try:
            with open("/proc/%s/environ" % pid, "rb") as f:
                if b"SIM_BATCH_RUN_TOKEN=" in f.read():
                    return True
        except OSError:
            pass
    return False
