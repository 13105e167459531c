"""Synthetic laser scans for the can detection tests: rays of the tutorial's Hokuyo (720 beams
over +-1.570796 rad, 0.10 - 30 m) cast at circles (cans) and segments (walls), with its gaussian
noise (0.01 m) and range resolution (0.01 m), and REP 117's +inf where nothing is hit."""
import math
from dataclasses import dataclass, field
from typing import List, Tuple

import numpy as np

ANGLE_MIN, ANGLE_MAX, SAMPLES = -1.570796, 1.570796, 720
ANGLE_INCREMENT = (ANGLE_MAX - ANGLE_MIN) / (SAMPLES - 1)
RANGE_MIN, RANGE_MAX = 0.10, 30.0
CAN_RADIUS = 0.033


@dataclass
class Scene:
    circles: List[Tuple[float, float, float]] = field(default_factory=list)   # (x, y, radius)
    segments: List[Tuple[float, float, float, float]] = field(default_factory=list)  # (x0, y0, x1, y1)


def ray_hits(scene: Scene, angles: np.ndarray) -> np.ndarray:
    """Distance along each ray from the origin to the nearest surface, inf where none."""
    dx, dy = np.cos(angles), np.sin(angles)
    best = np.full(len(angles), np.inf)
    for cx, cy, r in scene.circles:
        along = cx * dx + cy * dy
        miss2 = cx * cx + cy * cy - along * along
        with np.errstate(invalid='ignore'):
            t = along - np.sqrt(r * r - miss2)
        hit = (miss2 <= r * r) & (t > 0)
        best = np.where(hit & (t < best), t, best)
    for x0, y0, x1, y1 in scene.segments:
        ex, ey = x1 - x0, y1 - y0
        # Solve t d = p + s e for t (along the ray) and s (along the segment).
        denominator = -dx * ey + dy * ex
        with np.errstate(divide='ignore', invalid='ignore'):
            t = (-x0 * ey + y0 * ex) / denominator
            s = (dx * y0 - dy * x0) / denominator
        hit = (np.abs(denominator) > 1e-12) & (t > 0) & (s >= 0) & (s <= 1)
        best = np.where(hit & (t < best), t, best)
    return best


def scan(scene: Scene, rng=None, noise=0.01, resolution=0.01):
    """Ranges (list of floats) of one scan of the scene, as the simulator's laser reports them:
    +inf beyond range_max, -inf nearer than range_min, else noise, rounding, then clamping."""
    r = ray_hits(scene, ANGLE_MIN + np.arange(SAMPLES) * ANGLE_INCREMENT)
    measured = r.copy()
    if rng is not None and noise > 0:
        measured = measured + rng.normal(0.0, noise, SAMPLES)
    if resolution > 0:
        measured = np.round(measured / resolution) * resolution
    measured = np.clip(measured, RANGE_MIN, RANGE_MAX)
    measured[r >= RANGE_MAX] = np.inf
    measured[r <= RANGE_MIN] = -np.inf
    return measured.tolist()


def can_at(range_, bearing, radius=CAN_RADIUS):
    return (range_ * math.cos(bearing), range_ * math.sin(bearing), radius)
