"""The multi-run benchmarks' batches (scripts/bench_exploration.py, bench_katana_stacking.py,
bench_navigation.py) are sim_batch batch files: each parses, names one run per start, layout or
seed, and fills the launch arguments and the check's command line for that run. Running them is
the benchmarks' job (minutes each); this checks what they hand to sim_batch."""
import math
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


def stacking_options(**given):
    import argparse
    return argparse.Namespace(**dict(dict(layouts=3, first_seed=5, cans=3, region='band'), **given))


def test_stacking_is_one_run_per_layout_seed():
    import bench_katana_stacking
    runs = runs_of(bench_katana_stacking.scenario(stacking_options()))
    assert [r.seed for r in runs] == [5, 6, 7]
    assert [r.run_id for r in runs] == ['katana_stacking[seed=5]', 'katana_stacking[seed=6]', 'katana_stacking[seed=7]']
    assert sorted(runs[1].launch_args) == ['cans_count:=3', 'cans_range:=0.34,0.42', 'cans_seed:=6']
    assert runs[1].check.endswith('--check 6 --cans 3 --region band')


def test_stacking_over_the_reach_draws_between_the_ranges_the_arm_takes_a_can_at():
    """docs/KATANA.md: taking reaches from 0.32 m (the elbow's limit) to 0.4654 m (the arm
    stretched), here on the benchmark's 5 mm grid."""
    import bench_katana_stacking
    run = runs_of(bench_katana_stacking.scenario(stacking_options(cans=4, region='reach', layouts=1)))[0]
    assert sorted(run.launch_args) == ['cans_count:=4', 'cans_range:=0.315,0.46', 'cans_seed:=5']
    assert run.check.endswith('--check 5 --cans 4 --region reach')


def test_the_tower_is_the_highest_standing_column():
    from geometry_msgs.msg import Pose
    import bench_katana_stacking as bench

    def can(x, y, level, tilt_rad=0.0):
        pose = Pose()
        pose.position.x, pose.position.y, pose.position.z = x, y, bench.TABLE + level * bench.CAN_HEIGHT
        pose.orientation.x, pose.orientation.w = math.sin(tilt_rad / 2), math.cos(tilt_rad / 2)
        return pose
    poses = {'a': can(0.35, 0.0, 0), 'b': can(0.355, 0.005, 1), 'c': can(0.35, -0.005, 2), 'd': can(0.3, 0.2, 0)}
    assert bench.tallest_column(poses) == ['a', 'b', 'c']
    poses['b'] = can(0.35, 0.03, 1)  # 3 cm off the axis: not on the tower; c hangs over nothing
    assert len(bench.tallest_column(poses)) == 1
    poses['b'] = can(0.35, 0.0, 1, tilt_rad=0.3)  # 17 degrees: not standing
    assert len(bench.tallest_column(poses)) == 1


@pytest.mark.parametrize('mapper, args', [('hector', ()), ('gmapping', ('mapper:=gmapping',))])
def test_navigation_is_split_by_seed_each_run_driving_its_goals(mapper, args):
    import bench_navigation
    runs = runs_of(bench_navigation.scenario('pioneer', 10, [2, 3], 10.0, mapper, None, False))
    assert [r.seed for r in runs] == [2, 3] and all(r.launch_args == args for r in runs)
    assert '--goals 10' in runs[0].check and runs[0].check.endswith('--check 2')
    assert runs[0].time_limit == 300.0 + 10 * 120.0


def test_stack_cans_reports_are_read_from_the_rosout_log():
    """The lines as Debian's rosout node writes them: stamp, level, node, [file:line(function)],
    [topics: ...], the message; other nodes' lines are left out."""
    import bench_katana_stacking
    log = [
        '2.632000000 INFO /stack_cans [stack_cans:312(main)] [topics: /rosout, /stack_cans/cans] '
        'stack_cans: 4 cans: (0.200, -0.360), (0.363, -0.193)\n',
        '5.062000000 ERROR /stack_cans [stack_cans:254(CanStacker.stack)] [topics: /rosout] '
        'stack_cans: can at (0.215, 0.233): unreachable, skipped: no grasp [0.04] reaches it\n',
        '5.100000000 INFO /spawn_cans [spawn_cans:40(main)] [topics: /rosout] spawned can_4\n',
    ]
    assert bench_katana_stacking.reports_of('/stack_cans', log) == [
        'stack_cans: 4 cans: (0.200, -0.360), (0.363, -0.193)',
        'stack_cans: can at (0.215, 0.233): unreachable, skipped: no grasp [0.04] reaches it']
