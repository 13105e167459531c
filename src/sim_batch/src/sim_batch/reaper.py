"""Stops a run's jobs when the process that started them dies without stopping them (a Ray
worker killed mid-run): without this the run's roscore and nodes would live on, orphaned.

    python3 -m sim_batch.reaper OWNER_PID GROUPS_FILE

GROUPS_FILE lists the jobs' process groups, one a line, as run_processes starts them. Started in
a session of its own (out of the jobs' groups); it ends once its owner has stopped the jobs (the
file is gone), or once it has stopped them itself.
"""
import sys
import time

from sim_batch.run_processes import group_alive, process_alive, stop_groups

POLL_S = 0.5


def groups(path):
    try:
        with open(path) as f:
            return [int(line) for line in f if line.strip()]
    except (OSError, ValueError):
        return None


def main(owner, path):
    while process_alive(owner):
        listed = groups(path)
        if listed is None or (listed and not any(group_alive(g) for g in listed)):
            return  # stopped by its owner
        time.sleep(POLL_S)
    stop_groups(groups(path) or [])


if __name__ == "__main__":
    main(int(sys.argv[1]), sys.argv[2])
