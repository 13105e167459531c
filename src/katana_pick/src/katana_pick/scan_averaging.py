"""One scan from several of a still scene: the per-beam mean, so that can detection sees a
sensor with sqrt(n) times less noise (set CanDetectionOptions.range_noise to match).

The mean, not the median: the simulator's laser, like Gazebo's, rounds its noisy ranges to its
resolution (0.01 m), and the noise dithers that rounding away only in the mean.
"""
import math
from typing import List, Sequence


def average_scans(scans: Sequence[Sequence[float]], range_min, range_max) -> List[float]:
    """Per beam, the mean of the scans' readings within [range_min, range_max] if more than half
    of the scans have one; else +inf (no object there), or NaN if no scan has a valid reading."""
    if not scans:
        return []
    beams = len(scans[0])
    if any(len(s) != beams for s in scans):
        raise ValueError('scans of %s beams: expected scans of one sensor' % sorted({len(s) for s in scans}))
    averaged = []
    for i in range(beams):
        readings = [s[i] for s in scans]
        hits = [r for r in readings if range_min <= r <= range_max]
        if 2 * len(hits) > len(readings):
            averaged.append(math.fsum(hits) / len(hits))
        elif all(math.isnan(r) for r in readings):
            averaged.append(math.nan)
        else:
            averaged.append(math.inf)
    return averaged
