#!/usr/bin/env python3
"""IK solves per second for the Katana 450 6M90A: katana_pick's triangle IK against PyKDL's
numerical solvers (ChainIkSolverPos_NR_JL and ChainIkSolverPos_LMA) on the same chain
(katana_description's URDF, katana_base_link to katana_gripper_tool_frame), the same targets and
the same seeds, in the same run.

Targets come from random configurations within the joint limits, so every one is reachable.
The triangle IK is given the tool position and the gripper's pitch (its task: the roll is free);
KDL's solvers are given the whole tool frame of the same configuration (they cannot be told to
leave the roll free). A solve succeeds when the solver says so and the solution, within the joint
limits, puts the tool frame within 1 mm of the target with the pitch within 1e-3 rad.

Usage: /usr/bin/python3 scripts/bench_katana_ik.py [--targets N] [--seed S]
"""
import argparse
import math
import os
import random
import shutil
import subprocess
import sys
import time

import PyKDL

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, 'src', 'katana_pick', 'src'))
from katana_pick.arm_geometry import BASE_LINK, TOOL_FRAME, geometry_from_urdf, within_limits  # noqa: E402
from katana_pick.katana_ik import IkError, gripper_pitch, solve  # noqa: E402
from katana_pick.kdl_chain import kdl_chain  # noqa: E402

XACRO_FILE = os.path.join(ROOT, 'src', 'katana_description', 'urdf', 'katana_450_6m90a.urdf.xacro')


def katana_urdf():
    xacro = shutil.which('xacro') or os.path.join(ROOT, '.venv', 'bin', 'xacro')
    return subprocess.run([xacro, XACRO_FILE], capture_output=True, text=True, check=True).stdout


def joint_array(values):
    array = PyKDL.JntArray(len(values))
    for i, v in enumerate(values):
        array[i] = v
    return array


def into_limits(q, geometry):
    """q with each angle shifted by whole turns into its limits where that is possible (KDL's LMA
    ignores limits and may land a turn away)."""
    shifted = []
    for v, lim in zip(q, geometry.limits):
        centre = 0.5 * (lim.lower + lim.upper)
        shifted.append(centre + math.remainder(v - centre, 2 * math.pi))
    return shifted


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument('--targets', type=int, default=2000)
    parser.add_argument('--seed', type=int, default=1)
    args = parser.parse_args()

    urdf = katana_urdf()
    geometry = geometry_from_urdf(urdf)
    chain, _ = kdl_chain(urdf, BASE_LINK, TOOL_FRAME)
    fk = PyKDL.ChainFkSolverPos_recursive(chain)

    def tool(q):
        frame = PyKDL.Frame()
        fk.JntToCart(joint_array(q), frame)
        return frame

    def reached(q, target_frame):
        """Within limits, the position within 1 mm and the pitch within 1e-3 rad of the target."""
        if not within_limits(geometry, q, tolerance=1e-6):
            return False, math.inf
        frame = tool(q)
        error = (frame.p - target_frame.p).Norm()
        pitch = gripper_pitch(frame.p[0], frame.p[1], list(frame.M.UnitX()))
        wanted = gripper_pitch(target_frame.p[0], target_frame.p[1], list(target_frame.M.UnitX()))
        return error < 1e-3 and abs(math.remainder(pitch - wanted, 2 * math.pi)) < 1e-3, error

    rng = random.Random(args.seed)
    configurations = [[rng.uniform(l.lower, l.upper) for l in geometry.limits] for _ in range(args.targets)]
    seeds = [[rng.uniform(l.lower, l.upper) for l in geometry.limits] for _ in range(args.targets)]
    frames = [tool(q) for q in configurations]
    pitches = [gripper_pitch(f.p[0], f.p[1], list(f.M.UnitX())) for f in frames]

    results = []

    # The triangle IK.
    solutions = []
    start = time.perf_counter()
    for frame, pitch, seed in zip(frames, pitches, seeds):
        try:
            solutions.append(solve(geometry, frame.p[0], frame.p[1], frame.p[2], pitch, seed=seed))
        except IkError:
            solutions.append(None)
    elapsed = time.perf_counter() - start
    results.append(('katana_pick triangle IK (position + pitch)', elapsed, solutions))

    # KDL's Newton-Raphson with joint limits, and Levenberg-Marquardt (limits checked afterwards).
    q_min = joint_array([l.lower for l in geometry.limits])
    q_max = joint_array([l.upper for l in geometry.limits])
    velocity = PyKDL.ChainIkSolverVel_pinv(chain)
    solvers = [('PyKDL ChainIkSolverPos_NR_JL (frame; 100 iterations, eps 1e-6)',
                PyKDL.ChainIkSolverPos_NR_JL(chain, q_min, q_max, fk, velocity, 100, 1e-6), False),
               ('PyKDL ChainIkSolverPos_LMA (frame; defaults)', PyKDL.ChainIkSolverPos_LMA(chain), True)]
    for name, solver, shift in solvers:
        solutions = []
        out = PyKDL.JntArray(chain.getNrOfJoints())
        start = time.perf_counter()
        for frame, seed in zip(frames, seeds):
            status = solver.CartToJnt(joint_array(seed), frame, out)
            solutions.append([out[i] for i in range(out.rows())] if status >= 0 else None)
        elapsed = time.perf_counter() - start
        if shift:
            solutions = [into_limits(q, geometry) if q is not None else None for q in solutions]
        results.append((name, elapsed, solutions))

    print('Katana 450 6M90A IK: %d reachable targets from random configurations within the limits, '
          'random seeds (seed %d)' % (args.targets, args.seed))
    print('%-66s %12s %9s %14s' % ('solver', 'solves/s', 'success', 'max error'))
    for name, elapsed, solutions in results:
        checks = [reached(q, f) if q is not None else (False, math.inf) for q, f in zip(solutions, frames)]
        successes = sum(ok for ok, _ in checks)
        worst = max((e for ok, e in checks if ok), default=math.nan)
        print('%-66s %12.0f %8.1f%% %12.2g m' % (name, len(frames) / elapsed, 100.0 * successes / len(frames), worst))
    print()
    print('reproduce (from the repository root): . scripts/env.sh && '
          '/usr/bin/python3 scripts/bench_katana_ik.py --targets %d --seed %d' % (args.targets, args.seed))


if __name__ == '__main__':
    main()
