"""Cans in a planar laser scan, the tutorial's way improved.

The tutorial takes each run of consecutive in-range beams as one object and aims at the middle
of its first and last beams, which is the can's near face, not its axis, and merges objects that
no out-of-range beam separates. Here a run is also split where the range jumps by more than a
can's surface and the sensor's noise explain; a run is a can only if its width fits a can's
silhouette and its ranges bulge towards the sensor like a can's (a flat face is not a can); and a
circle of the can's known radius is fitted to the points, so the centre is the can's axis. A run
as wide as two cans is cut where two cans fit it best (touching cans).

One scan's noise (0.01 m on a 0.033 m can) limits what it can tell: about 1 % of cans within the
arm's reach look flat, and a flat face as wide as one or two cans passes for cans in 5 - 30 % of
scans. The mean of a few scans of the still scene (scan_averaging) removes both.

Ranges follow REP 117: NaN is an invalid reading (skipped: it neither ends a run nor is a point),
+-inf and anything outside [range_min, range_max] is no object there (it ends a run). Points are
in the scan's frame: x along angle 0, y along angle +pi/2.
"""
import math
from dataclasses import dataclass
from typing import List, Sequence

import numpy as np

from katana_pick.circle_fit import along_beam, fit_circle_known_radius


@dataclass(frozen=True)
class CanDetectionOptions:
    can_radius: float = 0.033      # m; the tutorial's cans
    range_noise: float = 0.01      # m, the sensor's standard deviation (the tutorial's Hokuyo)
    # A jump larger than this many standard deviations of the difference of two noisy ranges
    # (sqrt(2) * range_noise) is not noise; on top of it, a can's own surface may add up to
    # sqrt(2 R r dtheta) between neighbouring beams where it turns away from the sensor. A can
    # near the arm spans up to 100 beams: at 3 sigmas one scan in four would break a can in
    # two, at 4.5 one in a thousand; two objects closer than about 0.07 m in depth stay one run.
    jump_sigmas: float = 4.5
    min_beams: int = 4
    # Accepted width of a run, in can diameters (plus one beam's spacing at each edge): the
    # visible part of a can is 0.8 - 1.0 diameters wide beyond 0.2 m; less is a can mostly
    # hidden, whose centre a short arc does not fix.
    min_width: float = 0.6
    max_width: float = 1.3
    max_rms_sigmas: float = 2.5    # fit residual allowed, in range_noise
    # A can's ranges bulge towards the sensor in the middle; a run bulging less than this share
    # of a can's bulge is a flat face. Below halfway, to miss fewer cans: on synthetic scans
    # with the sensor's noise, 0.35 misses 1 % of cans at 0.5 m and 5 % at 1 m, and takes 6 % of
    # flat faces exactly as wide as a can for cans (0.5: 4 %, 10 % and 2 %).
    min_bulge: float = 0.35


@dataclass(frozen=True)
class Can:
    x: float                 # the can's axis, in the scan's frame (m)
    y: float
    beams: int               # beams on the can
    rms: float               # circle fit residual (m)
    first_beam: int
    last_beam: int

    @property
    def range(self):
        return math.hypot(self.x, self.y)

    @property
    def bearing(self):
        return math.atan2(self.y, self.x)


def jump_threshold(range_, beams_apart, angle_increment, options: CanDetectionOptions):
    """Largest range change between two beams on the same can, beams_apart beams apart."""
    noise = options.jump_sigmas * math.sqrt(2.0) * options.range_noise
    surface = math.sqrt(2.0 * options.can_radius * range_ * beams_apart * abs(angle_increment))
    return noise + surface


def split_runs(ranges: Sequence[float], angle_increment, range_min, range_max,
               options: CanDetectionOptions) -> List[np.ndarray]:
    """Beam indices of each run of in-range beams, split at out-of-range beams and range jumps."""
    runs, current = [], []
    for i, r in enumerate(ranges):
        if math.isnan(r):
            continue
        # The sensor clamps noisy readings into [range_min, range_max]; those are real returns.
        if not range_min <= r <= range_max:
            if current:
                runs.append(current)
            current = []
            continue
        if current:
            last = current[-1]
            if abs(r - ranges[last]) > jump_threshold(min(r, ranges[last]), i - last, angle_increment, options):
                runs.append(current)
                current = []
        current.append(i)
    if current:
        runs.append(current)
    return [np.array(run) for run in runs]


def _width(ranges, angles):
    """Width across the line of sight of the beams' span (m)."""
    return float(np.mean(ranges)) * abs(angles[-1] - angles[0])


def _points(indices, ranges, angles):
    r, a = ranges[indices], angles[indices]
    return np.column_stack((r * np.cos(a), r * np.sin(a)))


def _fit(points, radius, guess=None):
    """Circle fit of a can to points: (centre, residuals across it, residuals along the beams)."""
    if guess is None:
        # Start behind the arc as seen from the sensor: the fit keeps to that side.
        mid = points.mean(axis=0)
        guess = mid + radius * mid / np.linalg.norm(mid)
    centre, residuals = fit_circle_known_radius(points, radius, guess)
    offsets = points - centre
    return centre, residuals, along_beam(residuals, offsets / np.linalg.norm(offsets, axis=1)[:, None], points)


def _pair_split(indices, ranges, angles, angle_increment, options: CanDetectionOptions):
    """Where to cut a run as wide as two cans so that two cans fit it best (least squares along
    the beams): the crevice between touching cans is too narrow to find in one noisy scan, but
    the two arcs beside it are not."""
    beam_width = float(np.mean(ranges[indices])) * abs(angle_increment)
    diameter = 2.0 * options.can_radius
    # Each part 0.75 - 1 diameters wide, as the visible part of a can is.
    shortest = max(options.min_beams, int(0.75 * diameter / beam_width),
                   len(indices) - int(diameter / beam_width) - 1)
    costs, guesses = [], [None, None]
    for k in range(shortest, len(indices) - shortest + 1):
        cost = 0.0
        for side, part in enumerate((indices[:k], indices[k:])):
            # Moving the cut by a beam barely moves the centres: start from the last ones.
            centre, _, misfit = _fit(_points(part, ranges, angles), options.can_radius, guesses[side])
            guesses[side] = centre
            cost += float(np.sum(misfit ** 2))
        costs.append((cost, k))
    return min(costs)[1] if costs else None


# A can's ranges, r = D - sqrt(R^2 - u^2) across its width u in [-R, R], have the least-squares
# parabola r = a + (0.736 / R) u^2 (0.736 = cov(-sqrt(1 - s^2), s^2) / var(s^2) = (pi/48) / (4/45),
# s uniform in [-1, 1]); a flat face's is nearly straight (curvature 1 / (2 r) seen square-on).
_CAN_BULGE = (math.pi / 48.0) / (4.0 / 45.0)


def _bulge(ranges, angles):
    """Curvature (1/m) of the least-squares parabola through the ranges across the run.

    Fitted in the ranges, where the sensor's noise is, it tells an arc from a flat face as well
    as one scan can: with 0.01 m noise, a can 0.4 m away (about 40 beams) and a flat face as wide
    differ by about four standard deviations of this estimate.
    """
    u = float(np.mean(ranges)) * (angles - np.mean(angles))
    design = np.column_stack((np.ones_like(u), u, u * u))
    coefficients, *_ = np.linalg.lstsq(design, ranges, rcond=None)
    return float(coefficients[2])


def _can_in(indices, ranges, angles, angle_increment, options: CanDetectionOptions, split):
    """The can on these beams, or None; split: the run was cut at a crevice, whose place the
    noise blurs by a few beams."""
    r, a = ranges[indices], angles[indices]
    points = _points(indices, ranges, angles)
    radius = options.can_radius
    centre, residuals, _ = _fit(points, radius)
    rms = float(np.sqrt(np.mean(residuals ** 2)))
    if rms > options.max_rms_sigmas * options.range_noise:
        return None
    distance = float(np.linalg.norm(centre))
    if distance <= float(np.mean(r)):
        return None  # the centre in front of the points: the surface bends the wrong way
    # A whole can hides exactly 2 asin(R / distance) of the scan; the run's first and last beams
    # lie inside that, at most a beam short at each edge, and the fitted distance may be a few
    # millimetres off. A narrower run is a flat face or a can partly hidden (whose short arc
    # would not fix the centre well); a wider one is not a can.
    silhouette = 2.0 * math.asin(min(1.0, radius / distance))
    span = abs(a[-1] - a[0])
    slack = (4.0 if split else 0.0) * abs(angle_increment)
    step = abs(angle_increment)
    if not silhouette - 3.5 * step - slack <= span <= silhouette + 2.0 * step + slack:
        return None
    if _bulge(r, a) < options.min_bulge * _CAN_BULGE / radius:
        return None  # too flat for a can
    return Can(float(centre[0]), float(centre[1]), len(indices), rms, int(indices[0]), int(indices[-1]))


def _cans_in_run(indices, ranges, angles, angle_increment, options: CanDetectionOptions, split=False):
    """The cans on one run of beams: none, one, or two touching ones."""
    if len(indices) < options.min_beams:
        return []
    diameter = 2.0 * options.can_radius
    width = _width(ranges[indices], angles[indices])
    edges = 2.0 * float(np.mean(ranges[indices])) * abs(angle_increment)
    if width > options.max_width * diameter + edges:
        if split or width > 2.0 * (options.max_width * diameter + edges):
            return []  # a wall or a box, not one or two cans
        k = _pair_split(indices, ranges, angles, angle_increment, options)
        if k is None:
            return []
        return (_cans_in_run(indices[:k], ranges, angles, angle_increment, options, split=True)
                + _cans_in_run(indices[k:], ranges, angles, angle_increment, options, split=True))
    if width < options.min_width * diameter:
        return []
    can = _can_in(indices, ranges, angles, angle_increment, options, split)
    return [can] if can else []


def detect_cans(angle_min, angle_increment, ranges: Sequence[float], range_min, range_max,
                options: CanDetectionOptions = CanDetectionOptions()) -> List[Can]:
    """Cans seen in a scan (a sensor_msgs/LaserScan's numbers), by increasing bearing."""
    r = np.asarray(ranges, dtype=float)
    angles = angle_min + angle_increment * np.arange(len(r))
    cans = []
    for run in split_runs(r.tolist(), angle_increment, range_min, range_max, options):
        cans.extend(_cans_in_run(run, r, angles, angle_increment, options))
    return sorted(cans, key=lambda c: c.bearing)
