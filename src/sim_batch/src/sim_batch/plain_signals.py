"""Runs a command with SIGINT and SIGTERM unblocked and at their defaults:

    python3 -m sim_batch.plain_signals COMMAND [ARG ...]

A Ray worker runs its tasks with SIGINT blocked, and a blocked signal stays blocked across fork
and exec: a roscore or roslaunch started from a task would never see the SIGINT that stops it
cleanly (it would wait out the grace period and be killed). isolated_run starts every process of
a run through this.
"""
import os
import signal
import sys

if __name__ == "__main__":
    signal.pthread_sigmask(signal.SIG_UNBLOCK, {signal.SIGINT, signal.SIGTERM})
    for sig in (signal.SIGINT, signal.SIGTERM):
        signal.signal(sig, signal.SIG_DFL)
    os.execvp(sys.argv[1], sys.argv[1:])
