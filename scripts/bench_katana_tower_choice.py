#!/usr/bin/env python3
"""How many cans of a random layout the stacking plan puts on one tower: katana_pick's tower and
order choice (tower_choice.choose_stack, planning over the arm's whole reach) against the
tutorial's (the middle can by bearing, the nearest first) in the same run, on the same plans
(plan_can from the arm stretched out, every other can standing), and the time the choice takes.
Planning only: no simulation.

Usage: /usr/bin/python3 scripts/bench_katana_tower_choice.py [--cans N] [--layouts L] [--first-seed S]
"""
import argparse
import os
import sys
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', 'src', 'katana_arm_gazebo', 'src'))
from katana_arm_gazebo.can_layouts import random_layout  # noqa: E402
from katana_pick.arm_geometry import KatanaGeometry  # noqa: E402
from katana_pick.stacking import choose_tower, pick_order  # noqa: E402
from katana_pick.tower_choice import choose_stack, fits_by_plan, placed  # noqa: E402


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument('--cans', type=int, default=4)
    parser.add_argument('--layouts', type=int, default=12)
    parser.add_argument('--first-seed', type=int, default=0)
    args = parser.parse_args()
    geometry, start = KatanaGeometry(), (0.0,) * 5
    full = tutorial_full = 0
    seconds = []
    for seed in range(args.first_seed, args.first_seed + args.layouts):
        cans = random_layout(args.cans, seed)
        fits = fits_by_plan(geometry, start, cans)
        began = time.perf_counter()
        tower, order = choose_stack(cans, fits)
        seconds.append(time.perf_counter() - began)
        chosen = placed(order, tower, fits)
        tutorial = placed(pick_order(cans, choose_tower(cans)), choose_tower(cans), fits)
        full += chosen == args.cans - 1
        tutorial_full += tutorial == args.cans - 1
        print('seed %3d: %d of %d on the tower (tutorial: %d), chosen in %.1f s'
              % (seed, chosen, args.cans - 1, tutorial, seconds[-1]), flush=True)
    print('full towers: %d of %d layouts (the tutorial\'s tower and order: %d); choice %.1f s mean, %.1f s max'
          % (full, args.layouts, tutorial_full, sum(seconds) / len(seconds), max(seconds)))
    print('command: /usr/bin/python3 scripts/bench_katana_tower_choice.py --cans %d --layouts %d --first-seed %d'
          % (args.cans, args.layouts, args.first_seed))


if __name__ == '__main__':
    main()
