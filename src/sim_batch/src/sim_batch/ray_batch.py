"""A batch's runs as Ray tasks: by default a new Ray cluster of this machine (no set-up); an
address (or RAY_ADDRESS) sends the same tasks to a real cluster. Ray schedules (each task
reserves the run's num_cpus), retries a task whose worker died (max_retries) and brings the
results back; this module only records them as they come.
"""
import os
import sys
import time

import ray

from sim_batch.isolated_run import run_isolated

# Ray's own log lines on the terminal would bury the progress line; they stay in its log folder.
RAY_INIT = {"include_dashboard": False, "log_to_driver": False, "configure_logging": False}
CANCEL_WAIT_S = 40.0  # a run's stop: its jobs' SIGINT grace (20 s) and the rest


@ray.remote(num_cpus=0)  # never waits for a CPU the runs hold: they wait on it
class Attempts:
    """How many times each run started: Ray retries a task whose worker died, and the record
    says so."""

    def __init__(self):
        self.counts = {}

    def started(self, run_id):
        self.counts[run_id] = self.counts.get(run_id, 0) + 1

    def count(self, run_id):
        return self.counts.get(run_id, 0)

    def runs_started(self):
        return len(self.counts)


def _run_task(run, attempts):
    ray.get(attempts.started.remote(run.run_id))
    record, archive = run_isolated(run)
    record["node"] = ray.get_runtime_context().get_node_id()  # which Ray node ran it
    return record, archive


class Progress:
    """done / failed / running and the time left estimated from the runs finished so far: one
    line rewritten on a terminal, a line per change in a log."""

    def __init__(self, total, stream=sys.stderr):
        self.total, self.stream, self.started = total, stream, time.monotonic()
        self.done = self.failed = 0
        self._last = None
        self._terminal = stream.isatty()

    def show(self, running):
        finished = self.done + self.failed
        counts = "%d/%d runs: %d done, %d failed, %d running" % (finished, self.total, self.done, self.failed, running)
        if counts == self._last and not self._terminal:
            return
        self._last = counts
        elapsed = time.monotonic() - self.started
        left = ", %.0f s left" % (elapsed / finished * (self.total - finished)) if finished else ""
        line = counts + left
        if self._terminal:
            end = "\n" if finished == self.total else ""
            print("\r" + line.ljust(78), end=end, file=self.stream, flush=True)
        else:
            print(line, file=self.stream, flush=True)


def run_batch(runs, results, logs_dir, address=None, retries=1, stream=sys.stderr):
    """Runs what `results` (results.ResultsFile) does not have yet, appending each record as its
    run ends; a failed run's logs go to logs_dir/<run_id>.tar.gz. Returns the records added."""
    todo = [run for run in runs if run.run_id not in results.done()]
    if not todo:
        return []
    # "local": a new cluster of this machine, even when another runs here. Joining one found
    # running (Ray's default) failed in the tests: the attempts actor was cancelled before it ran.
    ray.init(address=address or os.environ.get("RAY_ADDRESS") or "local", **RAY_INIT)
    try:
        attempts = Attempts.remote()
        task = ray.remote(max_retries=retries)(_run_task)
        pending = {task.options(num_cpus=run.num_cpus, name=run.run_id).remote(run, attempts): run for run in todo}
        progress = Progress(len(todo), stream)
        progress.show(0)
        added = []
        while pending:
            ready, _ = ray.wait(list(pending), num_returns=1, timeout=1.0)
            for ref in ready:
                run = pending.pop(ref)
                record = _record(ref, run, logs_dir)
                record["attempts"] = ray.get(attempts.count.remote(run.run_id))
                results.append(record)
                added.append(record)
                if record["state"] == "ok":
                    progress.done += 1
                else:
                    progress.failed += 1
            # running: started and not finished (the rest of `pending` waits for a free CPU)
            progress.show(ray.get(attempts.runs_started.remote()) - progress.done - progress.failed)
        return added
    except KeyboardInterrupt:
        _cancel(pending)
        raise
    finally:
        ray.shutdown()


def _cancel(pending):
    """Ctrl-C: each running run is interrupted where it is (Ray raises KeyboardInterrupt in its
    task), so it stops its processes itself before Ray's workers go; the reapers catch any that
    does not."""
    for ref in pending:
        ray.cancel(ref)
    ray.wait(list(pending), num_returns=len(pending), timeout=CANCEL_WAIT_S)


def _record(ref, run, logs_dir):
    try:
        record, archive = ray.get(ref)
    except ray.exceptions.RayError as e:  # the worker died more often than retries allow, or the task raised
        record, archive = {"run_id": run.run_id, "scenario": run.scenario, "params": run.params, "seed": run.seed,
                           "state": "lost", "error": "%s: %s" % (type(e).__name__, str(e).splitlines()[0])}, None
    if archive:
        os.makedirs(logs_dir, exist_ok=True)
        path = os.path.join(logs_dir, run.run_id.replace("/", "_") + ".tar.gz")
        with open(path, "wb") as f:
            f.write(archive)
        record["logs"] = path
    return record
