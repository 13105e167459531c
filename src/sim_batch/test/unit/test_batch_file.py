"""batch_file.py: runs from a batch file, sweeps expanded, and a clear error for each bad field."""
import pytest

from sim_batch.batch_file import BatchError, load_batch, parse_batch

SWEEP = """
defaults: {time_limit: 120}
scenarios:
  - name: goal
    launch: pioneer_2dnav pioneer_nav.launch
    args: {rtf: 20, gui: false}
    check: rosrun my_robot check_goal.py --goal 2.2
  - name: vel
    command: python3 run.py --vel ${max_vel_x} --mapper ${mapper} --seed ${seed} --home ${HOME}
    grid: {max_vel_x: [0.3, 0.5], mapper: [gmapping, hector]}
    seeds: 3
    num_cpus: 2
    env: {RATE: "${max_vel_x}"}
"""


def test_a_sweep_is_every_grid_point_times_every_seed_in_file_order():
    runs = parse_batch(SWEEP)
    assert len(runs) == 1 + 2 * 2 * 3
    goal = runs[0]
    assert (goal.run_id, goal.launch, goal.launch_args, goal.seed) == (
        "goal", "pioneer_2dnav pioneer_nav.launch", ("rtf:=20", "gui:=false"), None)
    assert (goal.time_limit, goal.num_cpus) == (120.0, 1.0)  # the defaults
    sweep = runs[1:]
    assert [(r.params["max_vel_x"], r.params["mapper"], r.seed) for r in sweep[:4]] == [
        (0.3, "gmapping", 1), (0.3, "gmapping", 2), (0.3, "gmapping", 3), (0.3, "hector", 1)]
    last = sweep[-1]
    assert last.command == "python3 run.py --vel 0.5 --mapper hector --seed 3 --home ${HOME}"  # HOME: the shell's
    assert last.env == {"RATE": "0.5"}
    assert last.num_cpus == 2.0
    assert last.run_id == 'vel[mapper="hector",max_vel_x=0.5,seed=3]'
    assert len({r.run_id for r in runs}) == len(runs)


def test_the_same_file_gives_the_same_runs():
    assert parse_batch(SWEEP) == parse_batch(SWEEP)


def test_points_and_seed_lists():
    runs = parse_batch("""
scenarios:
  - name: p
    command: run ${a}
    points: [{a: 1}, {a: 7}]
    seeds: [11, 4]
""")
    assert [(r.command, r.seed) for r in runs] == [("run 1", 11), ("run 1", 4), ("run 7", 11), ("run 7", 4)]


@pytest.mark.parametrize("text, says", [
    ("scenarios: []", "a list of at least one scenario"),
    ("[1, 2", "not YAML"),
    ("scenarios: [{name: a, command: x}]\nextra: 1", "unknown top-level field(s) extra"),
    ("scenarios: [{name: a, launch: p f.launch}]", "scenarios[0] (a): expected command, or launch and check"),
    ("scenarios: [{name: a, command: x, check: y}]", "either command, or launch and check"),
    ("scenarios: [{name: a b, command: x}]", "name: expected a word"),
    ("scenarios: [{name: a, command: x, time_limit: ten}]", "scenarios[0] (a): time_limit: expected a number"),
    ("scenarios: [{name: a, command: x, num_cpus: 0}]", "num_cpus: expected a number of CPUs > 0, got 0"),
    ("scenarios: [{name: a, command: x, grid: {v: []}}]", "grid.v: expected a non-empty list"),
    ("scenarios: [{name: a, command: x, grid: {v: [1]}, points: [{v: 1}]}]", "grid (every combination) or points"),
    ("scenarios: [{name: a, command: x, grid: {seed: [1]}}]", "give the seeds with `seeds:`"),
    ("scenarios: [{name: a, command: x, seeds: 0}]", "seeds: expected a count > 0"),
    ("scenarios: [{name: a, command: x, seeds: [1, 1]}]", "repeats a seed"),
    ("scenarios: [{name: a, command: 'run ${seed}'}]", "command uses ${seed}, but the scenario has no seeds"),
    ("scenarios: [{name: a, command: x, args: {v: [1, 2]}}]", "args.v: expected a single value"),
    ("scenarios: [{name: a, command: x, colour: red}]", "unknown field(s) colour"),
    ("scenarios: [{name: a, command: x}, {name: a, command: y}]", "scenarios[1] (a): name: 'a' is used by an earlier"),
])
def test_a_bad_batch_file_says_where_and_what_was_expected(text, says):
    with pytest.raises(BatchError) as error:
        parse_batch(text, "my_batch.yaml")
    assert str(error.value).startswith("my_batch.yaml: ")
    assert says in str(error.value)


def test_a_missing_file_is_named(tmp_path):
    with pytest.raises(BatchError, match="nothing.yaml: cannot read it"):
        load_batch(str(tmp_path / "nothing.yaml"))
