"""What one run is: one scenario of a batch file at one point of its sweep, with one seed.
Pure: no ROS, no Ray."""
import json
from dataclasses import dataclass, field
from typing import Optional


@dataclass(frozen=True)
class Run:
    scenario: str                  # the scenario's name in the batch file
    params: dict = field(default_factory=dict)  # the sweep point, {name: value}
    seed: Optional[int] = None
    launch: Optional[str] = None   # "pkg file.launch" or a path to a launch file
    launch_args: tuple = ()        # ("name:=value", ...), placeholders filled in
    check: Optional[str] = None    # a shell command that prints one JSON line, run beside the launch
    command: Optional[str] = None  # instead of launch and check: the whole run, printing the JSON line
    time_limit: float = 600.0      # wall seconds, then the run is killed whole
    num_cpus: float = 1.0          # what Ray reserves for it
    env: dict = field(default_factory=dict)  # extra environment variables

    @property
    def run_id(self):
        """Stable across reruns of the same batch file: the scenario, its point and its seed,
        e.g. `sweep[max_vel_x=0.5,seed=3]`. Results are matched to runs by it."""
        parts = ["%s=%s" % (k, json.dumps(self.params[k], sort_keys=True)) for k in sorted(self.params)]
        if self.seed is not None:
            parts.append("seed=%d" % self.seed)
        return "%s[%s]" % (self.scenario, ",".join(parts)) if parts else self.scenario
