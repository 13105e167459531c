#!/usr/bin/env python3
"""readmarker's cost per frame: marker detection and both warps (MarkerReader.read) on an 800 x 800
view of the board (the unit tests' synthetic board: noise, blur, perspective), on one core.

  /usr/bin/python3 scripts/bench_readmarker.py [--frames 200]     (after . scripts/env.sh)
"""
import argparse
import os
import sys
import time

import cv2

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, os.pardir, 'src', 'readmarker', 'test', 'unit'))
import board_views as views  # noqa: E402
from readmarker.crop import MarkerReader  # noqa: E402


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n\n')[0])
    parser.add_argument('--frames', type=int, default=200)
    args = parser.parse_args()
    cv2.setNumThreads(1)
    reader = MarkerReader()
    frames = [views.camera_view(views.BOARD, views.looking_at(views.BOARD, tilt), seed=k)
              for k, tilt in enumerate((0.0, 0.1, 0.2, 0.3))]
    times = []
    found = 0
    for k in range(args.frames):
        start = time.perf_counter()
        detection = reader.read(frames[k % len(frames)])
        times.append(1e3 * (time.perf_counter() - start))
        found += sum(c.available for c in detection.crops)
    times.sort()
    print('command: scripts/bench_readmarker.py --frames %d' % args.frames)
    print('readmarker: %d frames of 800 x 800, detection + two warps: mean %.2f ms, median %.2f ms, worst %.2f ms; '
          '%d of %d pictures found; the full three-window scan ran on %d frames' % (
              len(times), sum(times) / len(times), times[len(times) // 2], times[-1], found, 2 * len(times),
              reader.full_scans))


if __name__ == '__main__':
    main()
