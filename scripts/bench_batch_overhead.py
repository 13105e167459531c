#!/usr/bin/python3
"""sim_batch's cost per run against the same run by hand (issue 36).

  /usr/bin/python3 scripts/bench_batch_overhead.py [--runs 6]     (after . scripts/env.sh)

The scenario is docs/BATCH.md's example: m_robot_world.launch and drive_check.py (m_robot driven
2 s of sim time), one heading.
- By hand, as a user runs it in two terminals: `roslaunch m_robot_gazebo m_robot_world.launch`
  (it starts its own master), the check once the launch's nodes are up, then Ctrl-C to the
  launch. Timed from the roslaunch's start to its exit; --runs times.
- sim_batch: the same run --runs times in one batch, one at a time (num_cpus 2 on this 2-core
  machine, as by hand), timed from `sim_batch run`'s start to its exit. Ray's start-up and
  shut-down, paid once per batch, are timed apart with a batch of one trivial run.
Per run: (batch - Ray's start-up) / runs - by hand.
"""
import argparse
import json
import os
import signal
import statistics
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
RUN = os.path.join(ROOT, "src", "sim_batch", "scripts", "run")
CHECK = "rosrun sim_batch drive_check.py --model m_robot --speed 0.2 --seconds 2"
SCENARIO = """
scenarios:
  - name: drive
    launch: m_robot_gazebo m_robot_world.launch
    args: {yaw: 1.5708}
    check: %s
    seeds: %d
    num_cpus: 2
    time_limit: 120
"""
TRIVIAL = """
scenarios:
  - name: trivial
    command: 'echo "{}"'
    num_cpus: 2
"""


def by_hand():
    from sim_batch.isolated_run import free_port, wait_for_launch
    port = free_port()
    env = dict(os.environ, ROS_MASTER_URI="http://127.0.0.1:%d" % port)
    start = time.monotonic()
    launch = subprocess.Popen(["roslaunch", "-p", str(port), "m_robot_gazebo", "m_robot_world.launch", "yaw:=1.5708"],
                              env=env, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, start_new_session=True)
    try:
        wait_for_launch(port, launch, start + 120)
        check = subprocess.run(["bash", "-c", CHECK], env=env, capture_output=True, text=True, timeout=120)
        assert '"distance"' in check.stdout, check.stdout + check.stderr
    finally:
        os.killpg(launch.pid, signal.SIGINT)  # Ctrl-C in its terminal
        launch.wait(60)
    return time.monotonic() - start


def batch(text, folder):
    path = os.path.join(folder, "batch.yaml")
    out = os.path.join(folder, "results.jsonl")
    for name in (path, out):
        if os.path.exists(name):
            os.remove(name)
    with open(path, "w") as f:
        f.write(text)
    start = time.monotonic()
    done = subprocess.run([RUN, path, "--out", out], capture_output=True, text=True, timeout=900)
    wall = time.monotonic() - start
    records = [json.loads(line) for line in open(out)]
    assert done.returncode == 0 and all(r["state"] == "ok" for r in records), done.stderr
    return wall, records


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=6)
    args = parser.parse_args()
    print("load average %.1f; %d runs each way" % (os.getloadavg()[0], args.runs), flush=True)
    hand = [by_hand() for _ in range(args.runs)]
    print("by hand, per run: median %.2f s (%s)" % (statistics.median(hand), ", ".join("%.2f" % h for h in hand)),
          flush=True)
    with tempfile.TemporaryDirectory() as folder:
        trivial_wall, [trivial] = batch(TRIVIAL, folder)
        ray_cost = trivial_wall - trivial["wall_s"]
        print("Ray's start-up and shut-down, once per batch: %.2f s" % ray_cost, flush=True)
        wall, records = batch(SCENARIO % (CHECK, args.runs), folder)
    inside = statistics.median(r["wall_s"] for r in records)
    per_run = (wall - ray_cost) / args.runs
    print("sim_batch, per run: %.2f s in the batch (a run's own wall_s: median %.2f s)" % (per_run, inside))
    print("overhead per run: %.2f s (target < 2 s); load average %.1f" % (per_run - statistics.median(hand),
                                                                          os.getloadavg()[0]))
    print("reproduce: /usr/bin/python3 scripts/bench_batch_overhead.py --runs %d" % args.runs)


if __name__ == "__main__":
    sys.exit(main())
