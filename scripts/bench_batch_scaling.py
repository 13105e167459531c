#!/usr/bin/python3
"""sim_batch's scaling (issue 36): the 10-start m_robot exploration benchmark as one batch, run
three ways on this machine, one after another:

  1. sequential: one run at a time (each reserves 2 CPUs of this 2-core machine);
  2. parallel: two runs at once (each reserves 1 CPU);
  3. a two-node Ray cluster on this machine (`ray start --head --num-cpus 1` and a second node
     `ray start --address ... --num-cpus 1`), the batch sent to it with --address.

  /usr/bin/python3 scripts/bench_batch_scaling.py [--starts 10] [--seed 1]   (after . scripts/env.sh)

For each: the batch's wall time, runs per minute, the runs' success and coverage (the benchmark's
own line), and the runs' CPU use (sim_batch's cpu_s over wall_s). From the CPU a run uses, what a
16-core machine would run at once and its runs per minute, if runs kept their sequential speed.
"""
import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
RAY = os.path.join(ROOT, '.venv', 'bin', 'ray')
BENCH = [sys.executable, os.path.join(HERE, 'bench_exploration.py'), '--robot', 'm_robot', '--explorer', 'find_frontier']


def run_bench(label, extra, starts, seed, folder):
    out = os.path.join(folder, label + '.jsonl')
    command = BENCH + ['--starts', str(starts), '--seed', str(seed), '--out', out] + extra
    start = time.monotonic()
    text = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True).stdout
    wall = time.monotonic() - start
    summary = next((line for line in text.splitlines() if line.startswith('exploration (')), '(no summary)')
    with open(out) as f:
        records = [json.loads(line) for line in f if line.strip()]
    cores = [r['cpu_s'] / r['wall_s'] for r in records if r.get('wall_s')]
    nodes = len({r.get('node') for r in records})
    print('%-10s %6.1f s wall, %.2f runs/min, per run %.1f s wall, %.2f cores (median), %d Ray node(s)\n'
          '           %s' % (label, wall, 60 * len(records) / wall, statistics.median(r['wall_s'] for r in records),
                             statistics.median(cores), nodes, summary), flush=True)
    return wall, records


def two_node_cluster(folder):
    """Starts a head and a second node on this machine, one CPU each; returns the address. Ray
    2.60's head turns token authentication on (its token in ~/.ray/auth_token, made if missing);
    the second node and the driver send it when RAY_AUTH_MODE=token (on two machines: the same
    token file copied to each)."""
    port = 6390
    os.environ['RAY_AUTH_MODE'] = 'token'  # this process's children: the nodes, then the batch's driver
    subprocess.check_call([RAY, 'get-auth-token', '--generate'], stdout=subprocess.DEVNULL)
    env = dict(os.environ, RAY_TMPDIR=folder)
    subprocess.check_call([RAY, 'start', '--head', '--port=%d' % port, '--num-cpus=1', '--include-dashboard=false'],
                          env=env, stdout=subprocess.DEVNULL)
    subprocess.check_call([RAY, 'start', '--address=127.0.0.1:%d' % port, '--num-cpus=1'], env=env,
                          stdout=subprocess.DEVNULL)
    return '127.0.0.1:%d' % port


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n\n')[0])
    parser.add_argument('--starts', type=int, default=10)
    parser.add_argument('--seed', type=int, default=1)
    args = parser.parse_args()
    folder = tempfile.mkdtemp(prefix='bench_batch_scaling.')
    print('command: /usr/bin/python3 scripts/bench_batch_scaling.py --starts %d --seed %d' % (args.starts, args.seed))
    sequential, records = run_bench('sequential', [], args.starts, args.seed, folder)
    parallel, _ = run_bench('parallel', ['--cpus-per-run', '1'], args.starts, args.seed, folder)
    try:
        address = two_node_cluster(folder)
        cluster, _ = run_bench('cluster', ['--cpus-per-run', '1', '--address', address], args.starts, args.seed, folder)
    finally:
        subprocess.call([RAY, 'stop', '--force'], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    cores = statistics.median(r['cpu_s'] / r['wall_s'] for r in records)
    per_run = statistics.median(r['wall_s'] for r in records)
    at_once = int(16 // cores)
    print('speed-up over sequential: parallel %.2fx, two-node cluster %.2fx' % (sequential / parallel, sequential / cluster))
    print('a 16-core machine: a run uses %.2f cores (sequential), so %d at once, about %.0f runs/min '
          '(sequential here: %.1f)' % (cores, at_once, 60 * at_once / per_run, 60 * len(records) / sequential))
    return 0


if __name__ == '__main__':
    sys.exit(main())
