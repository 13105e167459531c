"""Stops a run's processes when the process that started them dies without stopping them (a Ray
worker killed mid-run): without this the run's roscore and nodes would live on, orphaned.

    python3 -m sim_batch.reaper OWNER_PID TOKEN JOBS_FILE

TOKEN is the run's (every process of the run carries it, run_processes.py); JOBS_FILE lists its
jobs' process groups as they start. It leaves its starter at once (a daemon: in a session of its
own, a child of init), because Ray kills a dying worker's children with it; and it runs without
the token. It ends once its owner has stopped the run (the file is gone), or once it has stopped
it itself.
"""
import os
import sys
import time

from sim_batch.run_processes import process_alive, stop_run

POLL_S = 0.5


def jobs(path):
    try:
        with open(path) as f:
            return [int(line) for line in f if line.strip()]
    except (OSError, ValueError):
        return None


def main(owner, token, path):
    while process_alive(owner):
        if jobs(path) is None:
            return  # stopped by its owner
        time.sleep(POLL_S)
    stop_run(jobs(path) or [], token)


if __name__ == "__main__":
    if os.fork() == 0:  # the child carries on; the parent returns to its starter at once
        os.setsid()
        main(int(sys.argv[1]), sys.argv[2], sys.argv[3])
