"""The multi-run benchmarks' batches (scripts/bench_exploration.py, bench_katana_stacking.py,
bench_navigation.py) are sim_batch batch files: each parses, names one run per start, layout or
seed, and fills the launch arguments and the check's command line for that run. Running them is
the benchmarks' job (minutes each); this checks what they hand to sim_batch."""
import os
import sys

import pytest
import yaml

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, 'scripts'))
sys.path.insert(0, os.path.join(ROOT, 'src', 'sim_batch', 'src'))

from sim_batch.batch_file import parse_batch  # noqa: E402


def runs_of(scenario):
    return parse_batch(yaml.safe_dump({'scenarios': [scenario]}), 'bench')


def test_exploration_is_one_run_per_start_with_the_start_in_the_launch_and_the_check():
    import bench_exploration
    runs = runs_of(bench_exploration.scenario('m_robot', 'find_frontier', 4, 7, 30.0, 'hector'))
    starts = bench_exploration.draw_starts(bench_exploration.ROBOTS['m_robot'], 4, 7)
    assert [(r.params['x'], r.params['y'], r.params['yaw']) for r in runs] == starts
    assert [r.params['start'] for r in runs] == [1, 2, 3, 4] and {r.params['starts_seed'] for r in runs} == {7}
    first = runs[0]
    assert first.launch == 'find_frontier explore_maze.launch'
    assert 'x:=%s' % starts[0][0] in first.launch_args and 'explorer:=find_frontier' in first.launch_args
    assert first.check.endswith('--check %s %s %s' % starts[0]) and '--rtf 30.0' in first.check
    # the same seed draws the same starts; another seed others
    assert bench_exploration.draw_starts(bench_exploration.ROBOTS['m_robot'], 4, 8) != starts


def test_the_pioneers_exploration_passes_its_mapper_to_the_launch():
    import bench_exploration
    run = runs_of(bench_exploration.scenario('pioneer', 'explore', 1, 1, 22.0, 'gmapping'))[0]
    assert run.launch == 'pioneer_2dnav explore.launch' and 'mapper:=gmapping' in run.launch_args


def test_stacking_is_one_run_per_layout_seed():
    import bench_katana_stacking
    runs = runs_of(bench_katana_stacking.scenario(3, 5))
    assert [r.seed for r in runs] == [5, 6, 7]
    assert [r.run_id for r in runs] == ['katana_stacking[seed=5]', 'katana_stacking[seed=6]', 'katana_stacking[seed=7]']
    assert runs[1].launch_args == ('cans_seed:=6',) and runs[1].check.endswith('--check 6')


@pytest.mark.parametrize('mapper, args', [('hector', ()), ('gmapping', ('mapper:=gmapping',))])
def test_navigation_is_split_by_seed_each_run_driving_its_goals(mapper, args):
    import bench_navigation
    runs = runs_of(bench_navigation.scenario('pioneer', 10, [2, 3], 10.0, mapper, None, False))
    assert [r.seed for r in runs] == [2, 3] and all(r.launch_args == args for r in runs)
    assert '--goals 10' in runs[0].check and runs[0].check.endswith('--check 2')
    assert runs[0].time_limit == 300.0 + 10 * 120.0
