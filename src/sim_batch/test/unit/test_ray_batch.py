"""`sim_batch run` end to end with real Ray and real roscores: records appended, a rerun skipping
them, a failed run's logs, a worker killed mid-run retried and recorded (on the tests' two-node
cluster, conftest.py), and Ctrl-C leaving nothing behind while keeping what finished (on the
local cluster `sim_batch run` makes by default)."""
import json
import os
import signal
import subprocess
import time

from process_probe import alive, carrying_a_run_token, pids

RUN = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scripts", "run")


def sim_batch(*args, **kwargs):
    return subprocess.run([RUN] + list(args), capture_output=True, text=True, timeout=180, **kwargs)


def records(path):
    with open(path) as f:
        return [json.loads(line) for line in f]


def test_a_batch_runs_records_each_run_and_a_rerun_skips_them(tmp_path, ray_cluster):
    batch = tmp_path / "batch.yaml"
    batch.write_text("""
scenarios:
  - name: square
    command: 'echo "{\\"square\\": $((${x} * ${x})), \\"seed\\": ${seed}}"'
    grid: {x: [2, 3]}
    seeds: 2
    time_limit: 60
  - name: broken
    command: 'echo oops; exit 4'
    time_limit: 60
""")
    out = tmp_path / "results.jsonl"
    first = sim_batch(str(batch), "--out", str(out), "--address", ray_cluster)
    assert first.returncode == 1, first.stderr  # one run failed
    got = {r["run_id"]: r for r in records(out)}
    assert sorted(got) == ["broken", "square[x=2,seed=1]", "square[x=2,seed=2]", "square[x=3,seed=1]",
                           "square[x=3,seed=2]"]
    for x in (2, 3):
        for seed in (1, 2):
            r = got["square[x=%d,seed=%d]" % (x, seed)]
            assert (r["state"], r["result"], r["params"], r["seed"], r["attempts"]) == (
                "ok", {"square": x * x, "seed": seed}, {"x": x}, seed, 1)
            assert r["host"] and r["cpu_model"] and 0 < r["wall_s"] < 60
    broken = got["broken"]
    assert broken["state"] == "failed" and "status 4" in broken["error"]
    assert os.path.getsize(broken["logs"]) > 0 and broken["logs"].startswith(str(out) + ".logs")
    assert "broken failed" in first.stderr

    again = sim_batch(str(batch), "--out", str(out), "--address", ray_cluster)
    assert again.returncode == 0, again.stderr
    assert "5 already in" in again.stderr
    assert len(records(out)) == 5


def test_a_worker_killed_mid_run_is_retried_and_recorded(tmp_path, ray_cluster):
    flag = tmp_path / "killed_once"
    batch = tmp_path / "batch.yaml"
    # the run's shell is the worker's child: its first attempt kills the worker (kill -9 $PPID)
    batch.write_text("""
scenarios:
  - name: fragile
    command: 'if [ ! -e %s ]; then touch %s; kill -9 $PPID; sleep 30; fi; echo "{\\"survived\\": true}"'
    time_limit: 60
""" % (flag, flag))
    out = tmp_path / "results.jsonl"
    done = sim_batch(str(batch), "--out", str(out), "--address", ray_cluster)
    assert done.returncode == 0, done.stderr
    [r] = records(out)
    assert (r["state"], r["result"], r["attempts"]) == ("ok", {"survived": True}, 2)
    deadline = time.monotonic() + 30  # the killed attempt's master and rosout: its reaper stops them
    while carrying_a_run_token() and time.monotonic() < deadline:
        time.sleep(0.2)
    assert not carrying_a_run_token(), "the killed attempt's processes live on"

    flag.unlink()
    out.unlink()
    done = sim_batch(str(batch), "--out", str(out), "--retries", "0", "--address", ray_cluster)
    [r] = records(out)
    assert r["state"] == "lost" and "Worker" in r["error"] and r["attempts"] == 1
    assert done.returncode == 1


def ctrl_c_as_in_a_terminal():
    """SIGINT's default action and unblocked, as a shell gives its foreground command, whatever
    the test run inherited (started in the background, `cmd &` in a script, it ignores SIGINT)."""
    signal.signal(signal.SIGINT, signal.SIG_DFL)
    signal.pthread_sigmask(signal.SIG_UNBLOCK, {signal.SIGINT})


def test_ctrl_c_stops_the_batch_leaves_no_process_and_keeps_what_finished(tmp_path):
    marker = "sleep 300.31"  # the long runs' processes, for pgrep
    batch = tmp_path / "batch.yaml"
    batch.write_text("""
scenarios:
  - name: quick
    command: 'echo "{\\"quick\\": 1}"'
  - name: long
    command: 'sleep 300.31; true'
    seeds: 2
""")
    out = tmp_path / "results.jsonl"
    raylets_before = pids("raylet")  # the tests' shared cluster's
    # as a terminal runs it: its own process group, which Ctrl-C signals whole
    batch_run = subprocess.Popen([RUN, str(batch), "--out", str(out)], stdout=subprocess.PIPE,
                                 stderr=subprocess.PIPE, text=True, start_new_session=True,
                                 preexec_fn=ctrl_c_as_in_a_terminal)
    deadline = time.monotonic() + 120
    while not (out.exists() and "quick" in out.read_text() and alive(marker)) and time.monotonic() < deadline:
        time.sleep(0.2)
    assert alive(marker), "the long runs did not start"
    os.killpg(batch_run.pid, signal.SIGINT)
    _, stderr = batch_run.communicate(timeout=60)
    assert batch_run.returncode == 130, stderr
    assert "keeps every finished run" in stderr
    deadline = time.monotonic() + 30
    while (alive(marker) or carrying_a_run_token()) and time.monotonic() < deadline:
        time.sleep(0.2)
    assert not alive(marker), "a run's process outlived Ctrl-C"
    assert not carrying_a_run_token(), "a run's process (its master, rosout, ...) outlived Ctrl-C"
    assert not pids("raylet") - raylets_before, "the batch's local Ray cluster outlived Ctrl-C"
    assert [r["run_id"] for r in records(out)] == ["quick"]
