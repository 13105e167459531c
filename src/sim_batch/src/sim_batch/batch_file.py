"""Reads a batch file (YAML) into runs, with an error that names the file, the scenario and the
field for anything that does not fit. Pure: no ROS, no Ray. The format is docs/BATCH.md's:

    defaults:                       # optional: every scenario's, unless it says otherwise
      time_limit: 600               # wall seconds
      num_cpus: 1
    scenarios:
      - name: goal_2m
        launch: pioneer_2dnav pioneer_nav.launch     # "package file.launch", or a path
        args: {rtf: 20}                              # launch arguments, name:=value
        check: rosrun my_robot check_goal.py         # prints one JSON line; the launch runs meanwhile
      - name: max_vel
        command: python3 my_run.py --vel ${max_vel_x} --seed ${seed}   # instead of launch + check
        grid: {max_vel_x: [0.3, 0.5]}                # every combination; or points: [{...}, ...]
        seeds: 5                                     # seeds 1..5, or a list [3, 7]

`${name}` in `launch`, `args`, `check`, `command` and `env` values is the run's parameter or
`${seed}`; any other `${NAME}` is left for the shell (an environment variable).
"""
import itertools
import string

import yaml

from sim_batch.scenario import Run

SCENARIO_FIELDS = {"name", "launch", "args", "check", "command", "time_limit", "num_cpus", "env", "grid", "points",
                   "seeds"}
DEFAULT_FIELDS = {"time_limit", "num_cpus", "env"}
DEFAULTS = {"time_limit": 600.0, "num_cpus": 1.0, "env": {}}


class BatchError(ValueError):
    pass


def load_batch(path):
    """Every run of the batch file at `path`, in file order (sweep points in order, seeds inner)."""
    try:
        with open(path) as f:
            text = f.read()
    except OSError as e:
        raise BatchError("%s: cannot read it: %s" % (path, e.strerror or e))
    return parse_batch(text, path)


def parse_batch(text, path="<batch>"):
    try:
        document = yaml.safe_load(text)
    except yaml.YAMLError as e:
        raise BatchError("%s: not YAML: %s" % (path, e))
    if not isinstance(document, dict) or not isinstance(document.get("scenarios"), list) or not document["scenarios"]:
        raise BatchError("%s: expected a mapping with `scenarios:`, a list of at least one scenario" % path)
    unknown = set(document) - {"defaults", "scenarios"}
    if unknown:
        raise BatchError("%s: unknown top-level field(s) %s (expected defaults, scenarios)" % (path, ", ".join(sorted(unknown))))
    defaults = dict(DEFAULTS)
    given = document.get("defaults") or {}
    if not isinstance(given, dict) or set(given) - DEFAULT_FIELDS:
        raise BatchError("%s: defaults: expected a mapping of %s" % (path, ", ".join(sorted(DEFAULT_FIELDS))))
    defaults.update(given)
    runs, names = [], set()
    for index, scenario in enumerate(document["scenarios"]):
        where = "%s: scenarios[%d]" % (path, index)
        if isinstance(scenario, dict) and isinstance(scenario.get("name"), str):
            where += " (%s)" % scenario["name"]
        new = _scenario_runs(scenario, defaults, where)
        if new[0].scenario in names:
            raise BatchError("%s: name: %r is used by an earlier scenario; names must differ" % (where, new[0].scenario))
        names.add(new[0].scenario)
        runs += new
    return runs


def _scenario_runs(scenario, defaults, where):
    if not isinstance(scenario, dict):
        raise BatchError("%s: expected a mapping (name, launch + check or command, ...)" % where)
    unknown = set(scenario) - SCENARIO_FIELDS
    if unknown:
        raise BatchError("%s: unknown field(s) %s (expected: %s)" % (where, ", ".join(sorted(unknown)),
                                                                    ", ".join(sorted(SCENARIO_FIELDS))))
    s = dict(defaults, **scenario)
    name = s.get("name")
    if not isinstance(name, str) or not name or any(c in name for c in "[]/ "):
        raise BatchError("%s: name: expected a word without spaces, / or brackets, got %r" % (where, name))
    if s.get("command") is not None and (s.get("launch") is not None or s.get("check") is not None):
        raise BatchError("%s: give either command, or launch and check, not both" % where)
    if s.get("command") is None and (s.get("launch") is None or s.get("check") is None):
        raise BatchError("%s: expected command, or launch and check (the check prints the result)" % where)
    for key in ("launch", "check", "command"):
        if s.get(key) is not None and (not isinstance(s[key], str) or not s[key].strip()):
            raise BatchError("%s: %s: expected a non-empty string, got %r" % (where, key, s[key]))
    time_limit = _positive(s["time_limit"], where, "time_limit", "a number of seconds > 0")
    num_cpus = _positive(s["num_cpus"], where, "num_cpus", "a number of CPUs > 0")
    args = _mapping(s.get("args") or {}, where, "args")
    env = _mapping(s.get("env") or {}, where, "env")
    points = _points(s, where)
    seeds = _seeds(s.get("seeds"), where)
    runs = []
    for point in points:
        for seed in seeds:
            values = dict(point, **({} if seed is None else {"seed": seed}))
            fill = lambda text, field: _fill(text, values, where, field)  # noqa: E731
            runs.append(Run(
                scenario=name, params=point, seed=seed,
                launch=fill(s.get("launch"), "launch"),
                launch_args=tuple("%s:=%s" % (k, fill(_text(v), "args.%s" % k)) for k, v in args.items()),
                check=fill(s.get("check"), "check"), command=fill(s.get("command"), "command"),
                time_limit=time_limit, num_cpus=num_cpus,
                env={k: fill(_text(v), "env.%s" % k) for k, v in env.items()}))
    return runs


def _points(s, where):
    grid, points = s.get("grid"), s.get("points")
    if grid is not None and points is not None:
        raise BatchError("%s: give grid (every combination) or points (a list), not both" % where)
    if grid is not None:
        grid = _mapping(grid, where, "grid")
        for key, values in grid.items():
            if not isinstance(values, list) or not values:
                raise BatchError("%s: grid.%s: expected a non-empty list of values, got %r" % (where, key, values))
        names = list(grid)
        result = [dict(zip(names, combination)) for combination in itertools.product(*(grid[n] for n in names))]
    elif points is not None:
        if not isinstance(points, list) or not points or not all(isinstance(p, dict) for p in points):
            raise BatchError("%s: points: expected a non-empty list of mappings {name: value}" % where)
        result = [dict(p) for p in points]
    else:
        return [{}]
    for point in result:
        for key, value in point.items():
            if key == "seed":
                raise BatchError("%s: `seed` is not a parameter here; give the seeds with `seeds:`" % where)
            if not isinstance(key, str) or not key.isidentifier():
                raise BatchError("%s: parameter name %r: expected a name (letters, digits, _)" % (where, key))
            if not isinstance(value, (str, int, float, bool)):
                raise BatchError("%s: parameter %s: expected a number, a string or a boolean, got %r"
                                 % (where, key, value))
    return result


def _seeds(seeds, where):
    if seeds is None:
        return [None]
    if isinstance(seeds, bool):
        raise BatchError("%s: seeds: expected a count or a list of integers, got %r" % (where, seeds))
    if isinstance(seeds, int) and seeds > 0:
        return list(range(1, seeds + 1))
    if isinstance(seeds, list) and seeds and all(isinstance(x, int) and not isinstance(x, bool) for x in seeds):
        if len(set(seeds)) != len(seeds):
            raise BatchError("%s: seeds: %r repeats a seed" % (where, seeds))
        return seeds
    raise BatchError("%s: seeds: expected a count > 0 or a list of integers, got %r" % (where, seeds))


def _fill(text, values, where, field):
    if text is None:
        return None
    template = string.Template(text)
    try:
        filled = template.safe_substitute({k: _text(v) for k, v in values.items()})
    except ValueError as e:  # a malformed ${...}
        raise BatchError("%s: %s: %s" % (where, field, e))
    if "seed" not in values and "seed" in _placeholders(template):
        raise BatchError("%s: %s uses ${seed}, but the scenario has no seeds (add seeds: N)" % (where, field))
    return filled


def _placeholders(template):
    return {m.group("named") or m.group("braced") for m in template.pattern.finditer(template.template)}


def _text(value):
    if isinstance(value, bool):
        return "true" if value else "false"  # as roslaunch and YAML write them
    return str(value)


def _positive(value, where, field, expected):
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not value > 0:
        raise BatchError("%s: %s: expected %s, got %r" % (where, field, expected, value))
    return float(value)


def _mapping(value, where, field):
    if not isinstance(value, dict) or not all(isinstance(k, str) for k in value):
        raise BatchError("%s: %s: expected a mapping {name: value}, got %r" % (where, field, value))
    for key, item in value.items():
        if isinstance(item, (dict, list)) and field != "grid":
            raise BatchError("%s: %s.%s: expected a single value, got %r" % (where, field, key, item))
    return value
