"""How the workspace's multi-run benchmarks run their runs: as one sim_batch batch (docs/BATCH.md),
each run on a ROS master of its own, on this machine or on a Ray cluster (--address). A benchmark
writes its batch, sim_batch runs it and appends one record per run to a results file, and the
benchmark builds its table from those records. The batch file is kept beside the results, so the
same command with the same --out goes on where an interrupted one stopped.
"""
import os
import subprocess
import sys
import tempfile
import time

import yaml

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
RUN = os.path.join(ROOT, 'src', 'sim_batch', 'scripts', 'run')
VENV_PYTHON = os.path.join(ROOT, '.venv', 'bin', 'python3')  # Ray is installed there (scripts/setup)


def add_arguments(parser):
    """The batch options every benchmark takes."""
    parser.add_argument('--out', help='results file (JSON lines; default: a new one in /tmp); an existing one is '
                                      'resumed: the runs it has are not run again')
    parser.add_argument('--address', help='a Ray cluster to run on (default: RAY_ADDRESS, else this machine)')
    parser.add_argument('--cpus-per-run', type=float,
                        help='CPUs each run reserves (default: the benchmark\'s, which runs one at a time on 2 cores)')


def check_command(script, *args):
    """The shell command sim_batch runs as a run's check: this benchmark's script in check mode,
    with Debian's Python. The script is found under the worker's own workspace ($ROOT, which
    scripts/env.sh sets; the docker/ image's is /workspace), else under this one's."""
    path = '"${ROOT:-%s}/scripts/%s"' % (ROOT, os.path.basename(script))
    return ' '.join(['/usr/bin/python3', path] + [str(a) for a in args])


def run(scenario, args, default_cpus, name):
    """Runs one scenario (a batch file's scenario, as a dict) through sim_batch with the options
    of add_arguments; returns (records of its runs in the scenario's order, the results file).
    Runs that did not end ok are in the list with their state and error."""
    scenario = dict(scenario, num_cpus=args.cpus_per_run or default_cpus)
    out = args.out or os.path.join(tempfile.mkdtemp(prefix=name + '.'), 'results.jsonl')
    batch_path = out + '.batch.yaml'
    with open(batch_path, 'w') as f:
        yaml.safe_dump({'scenarios': [scenario]}, f, sort_keys=False)
    python = VENV_PYTHON if os.path.exists(VENV_PYTHON) else sys.executable
    command = [python, RUN, batch_path, '--out', out] + (['--address', args.address] if args.address else [])
    print('batch: %s (results: %s)' % (' '.join(command), out), flush=True)
    subprocess.call(command)  # non-zero when a run failed: the records say which
    sys.path.insert(0, os.path.join(ROOT, 'src', 'sim_batch', 'src'))
    from sim_batch.batch_file import load_batch
    from sim_batch.results import read_results
    order = [r.run_id for r in load_batch(batch_path)]
    records = {record['run_id']: record for record in read_results(out)[0]}  # a run again: its last record
    return [records.get(run_id, {'run_id': run_id, 'state': 'missing', 'error': 'not in %s' % out})
            for run_id in order], out


def wait_until(predicate, timeout, what):
    """In a check: waits for predicate(); ends the check (a failed run, saying what was missing)
    after `timeout` wall seconds."""
    deadline = time.monotonic() + timeout
    while not predicate():
        if time.monotonic() > deadline:
            sys.exit('%s: no %s in %.0f s' % (os.path.basename(sys.argv[0]), what, timeout))
        time.sleep(0.1)


def result_of(record):
    """The run's own JSON line, or None when it did not end ok."""
    return record.get('result') if record.get('state') == 'ok' else None


def describe_failure(record):
    return '%s%s%s' % (record.get('state'), ': ' + str(record.get('error')) if record.get('error') else '',
                       ' (logs: %s)' % record['logs'] if record.get('logs') else '')

