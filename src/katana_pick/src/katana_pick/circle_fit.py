"""Least-squares fit of a circle of known radius (a can's cross-section) to laser points, with
the residuals weighted as the sensor's range noise makes them.
"""
import numpy as np


def fit_circle_known_radius(points, radius, centre_guess, iterations=20, tolerance=1e-9):
    """Centre (2,) of the circle of the given radius that fits points (n x 2, seen from the
    origin) best in the ranges: least squares of the residuals along the beams (see along_beam),
    by iteratively reweighted Gauss-Newton from centre_guess; and the residuals across the circle.

    The radius is known, so even a short arc fixes the centre; the guess decides on which side of
    the arc the centre lies (a circle of the same radius on the near side fits as well), so it
    should be behind the points as seen from the sensor.
    """
    points = np.asarray(points, dtype=float)
    centre = np.asarray(centre_guess, dtype=float).copy()
    for _ in range(iterations):
        offsets = points - centre
        distances = np.maximum(np.hypot(offsets[:, 0], offsets[:, 1]), 1e-12)
        normals = offsets / distances[:, None]
        residuals = distances - radius
        # Weighting by along_beam's factor squared makes this least squares along the beams.
        weights = np.sqrt(along_beam(np.ones(len(points)), normals, points))
        jacobian = -normals * weights[:, None]       # d residual / d centre, weighted
        # Normal equations: a 2 x 2 system, well conditioned for an arc of a few degrees or more.
        step = np.linalg.solve(jacobian.T @ jacobian, jacobian.T @ (-residuals * weights))
        centre += step
        if np.hypot(*step) < tolerance:
            break
    offsets = points - centre
    return centre, np.hypot(offsets[:, 0], offsets[:, 1]) - radius


def along_beam(residuals, normals, points, most=1.0 / 0.3):
    """Residuals measured along the beams rather than across the surface: a range error d shows
    as d cos(phi) across a surface that the beam meets at phi from its normal, so fits are only
    weighed fairly on residual / cos(phi); capped at most times, for beams that graze the surface.
    points are seen from the origin; normals (n x 2) are the surface's unit normals at them."""
    beams = points / np.linalg.norm(points, axis=1)[:, None]
    cosines = np.abs(np.sum(beams * normals, axis=1))
    return residuals / np.maximum(cosines, 1.0 / most)
