"""Finding the two pictures on a marker board in a camera image and un-warping them (the lecture's
readmarker, without ROS). A picture is available only when each of its four markers is seen once
and the quadrilateral of their inner corners is a plausible view of a rectangle; otherwise it is
reported unavailable with the reason, never warped from a guess."""
from dataclasses import dataclass, field
from typing import List, Optional

import cv2
import numpy as np

from readmarker.aruco_api import detect_markers, detector_parameters
from readmarker.board import CROP_SIZE, INNER_CORNER, PICTURE_IDS, dictionary

# A view so oblique that the quadrilateral's shortest side is under this fraction of its longest
# (about 80 degrees off the board's normal) un-warps into a smear: refused.
MIN_SIDE_RATIO = 0.15
MIN_SIDE_PX = 8.0


@dataclass
class Crop:
    available: bool
    image: Optional[np.ndarray] = None  # CROP_SIZE x CROP_SIZE, the input's channels
    reason: str = ''                    # why not available
    corners: Optional[np.ndarray] = None  # 4 x 2 inner corners in the image, clockwise from top left


@dataclass
class Detection:
    crops: List[Crop] = field(default_factory=list)
    ids: List[int] = field(default_factory=list)  # every marker id seen


class MarkerReader:
    def __init__(self, size=CROP_SIZE):
        self.size = size
        self.dictionary = dictionary()
        # The detector's default thresholds the image with three window sizes (3, 13 and 23 px),
        # which is nearly all its cost. One 13 px window finds every marker of an ordinary view in
        # a third of the time, so the full scan runs only for a picture that pass left incomplete.
        self.full_scan = detector_parameters()
        self.full_scan.cornerRefinementMethod = cv2.aruco.CORNER_REFINE_SUBPIX
        self.quick_scan = detector_parameters()
        self.quick_scan.cornerRefinementMethod = cv2.aruco.CORNER_REFINE_SUBPIX
        self.quick_scan.adaptiveThreshWinSizeMin = self.quick_scan.adaptiveThreshWinSizeMax = 13
        self.full_scans = 0  # how often the quick pass was not enough
        self.target = np.float32([[0, 0], [size - 1, 0], [size - 1, size - 1], [0, size - 1]])

    def read(self, image):
        """Both pictures from a BGR or grey image."""
        grey = image if image.ndim == 2 else cv2.cvtColor(image, cv2.COLOR_BGR2GRAY)
        corners, seen = self._detect(grey, self.quick_scan)
        found = [inner_corners(corners, seen, picture_ids) for picture_ids in PICTURE_IDS]
        if any(quad is None for quad, _ in found):
            # The passes' candidates differ a little either way, so a picture whole in the quick
            # pass keeps that pass's markers.
            self.full_scans += 1
            corners, seen = self._detect(grey, self.full_scan)
            found = [(quad, reason) if quad is not None else inner_corners(corners, seen, picture_ids)
                     for (quad, reason), picture_ids in zip(found, PICTURE_IDS)]
        return Detection(crops=[self._crop(image, quad, reason) for quad, reason in found], ids=seen)

    def _detect(self, grey, parameters):
        corners, ids = detect_markers(grey, self.dictionary, parameters)
        return corners, [] if ids is None else [int(i) for i in ids.flatten()]

    def _crop(self, image, quad, reason):
        if quad is None:
            return Crop(False, reason=reason)
        problem = implausible(quad)
        if problem:
            return Crop(False, reason=problem, corners=quad)
        homography = cv2.getPerspectiveTransform(quad, self.target)
        warped = cv2.warpPerspective(image, homography, (self.size, self.size), flags=cv2.INTER_LINEAR)
        return Crop(True, warped, corners=quad)


def inner_corners(corners, seen, picture_ids):
    """The picture's quadrilateral (its markers' inner corners) from one detection, or None and why."""
    doubled = [i for i in picture_ids if seen.count(i) > 1]
    if doubled:
        return None, 'marker%s %s seen more than once' % ('s' if len(doubled) > 1 else '', ', '.join(map(str, doubled)))
    missing = [i for i in picture_ids if i not in seen]
    if missing:
        return None, 'marker%s %s not seen' % ('s' if len(missing) > 1 else '', ', '.join(map(str, missing)))
    return np.float32([corners[seen.index(i)].reshape(4, 2)[INNER_CORNER[k]] for k, i in enumerate(picture_ids)]), ''


def implausible(quad):
    """Why a quadrilateral (clockwise from top left) is not a usable view of a rectangle, or ''."""
    sides = [np.linalg.norm(quad[(k + 1) % 4] - quad[k]) for k in range(4)]
    if min(sides) < MIN_SIDE_PX:
        return 'the picture is too small in the image (a side of %.1f px)' % min(sides)
    if min(sides) < MIN_SIDE_RATIO * max(sides):
        return 'the board is seen too obliquely (sides %.0f to %.0f px)' % (min(sides), max(sides))
    # Convex and in the markers' order: every turn the same way.
    turns = [np.cross(quad[(k + 1) % 4] - quad[k], quad[(k + 2) % 4] - quad[(k + 1) % 4]) for k in range(4)]
    if not (all(t > 0 for t in turns) or all(t < 0 for t in turns)):
        return 'the markers are not in their places round the picture (their corners cross)'
    return ''


def ncc(a, b):
    """Normalised cross-correlation of two images of one size (grey or colour), -1..1."""
    a = a.astype(np.float64).ravel() - a.mean()
    b = b.astype(np.float64).ravel() - b.mean()
    denominator = np.sqrt((a * a).sum() * (b * b).sum())
    return float((a * b).sum() / denominator) if denominator > 0 else 0.0
