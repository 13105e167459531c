"""readmarker's crops on synthetic views of the board: a known homography, noise and blur."""
import cv2
import numpy as np
import pytest

from board_views import BOARD, FRAMED, MARKER, camera_view, expected, looking_at
from readmarker.board import CROP_SIZE, marker_image
from readmarker.crop import MarkerReader, ncc


# Each picture about 200 px wide in the 800 x 800 view, its far side up to 30 % shorter than its near side.
@pytest.mark.parametrize('tilt', [0.0, 0.15, 0.3])
def test_both_pictures_come_back_from_a_noisy_blurred_perspective_view(tilt):
    view = camera_view(BOARD, looking_at(BOARD, tilt))
    detection = MarkerReader().read(view)
    assert sorted(detection.ids) == list(range(1, 9))
    for k, crop in enumerate(detection.crops):
        assert crop.available, crop.reason
        assert crop.image.shape == (CROP_SIZE, CROP_SIZE, 3)
        assert ncc(crop.image, expected(k)) >= 0.95
        # ... and not the other picture.
        assert ncc(crop.image, expected(1 - k)) < 0.5


def test_grey_input_gives_grey_crops():
    view = cv2.cvtColor(camera_view(BOARD, looking_at(BOARD, 0.1)), cv2.COLOR_BGR2GRAY)
    crops = MarkerReader().read(view).crops
    assert all(c.available and c.image.shape == (CROP_SIZE, CROP_SIZE) for c in crops)
    assert ncc(crops[0].image, cv2.cvtColor(expected(0), cv2.COLOR_BGR2GRAY)) >= 0.95


def test_a_hidden_marker_makes_its_picture_unavailable_and_leaves_the_other():
    board = BOARD.copy()
    x0, y0, x1, y1 = FRAMED[1]
    board[y1:y1 + MARKER, x1:x1 + MARKER] = 255  # marker 7, at picture 2's bottom right
    detection = MarkerReader().read(camera_view(board, looking_at(board, 0.1)))
    assert detection.crops[0].available
    assert not detection.crops[1].available and detection.crops[1].image is None
    assert detection.crops[1].reason == 'marker 7 not seen'


def test_a_duplicated_id_makes_its_picture_unavailable():
    board = BOARD.copy()
    x0, y0, x1, y1 = FRAMED[0]
    board[y0 - MARKER:y0, x1:x1 + MARKER] = cv2.cvtColor(marker_image(1, MARKER), cv2.COLOR_GRAY2BGR)  # 1 where 2 was
    detection = MarkerReader().read(camera_view(board, looking_at(board)))
    assert not detection.crops[0].available
    assert detection.crops[0].reason == 'marker 1 seen more than once'
    assert detection.crops[1].available


def test_a_grazing_view_is_refused_rather_than_smeared():
    h, w = BOARD.shape[:2]
    src = np.float32([[0, 0], [w, 0], [w, h], [0, h]])
    # The board's right half runs nearly edge-on away from the camera.
    dst = np.float32([[20, 200], [780, 385], [780, 395], [20, 600]])
    detection = MarkerReader().read(camera_view(BOARD, cv2.getPerspectiveTransform(src, dst), noise=0, blur=0))
    for crop in detection.crops:
        assert not crop.available
        assert crop.image is None and crop.reason


def test_no_board_at_all():
    detection = MarkerReader().read(np.full((480, 640, 3), 128, np.uint8))
    assert detection.ids == []
    assert [c.reason for c in detection.crops] == ['markers 1, 2, 3, 4 not seen', 'markers 5, 6, 7, 8 not seen']


def test_the_full_three_window_scan_runs_only_when_the_quick_pass_leaves_a_picture_incomplete():
    reader = MarkerReader()
    reader.read(camera_view(BOARD, looking_at(BOARD, 0.1)))
    assert reader.full_scans == 0
    # Small, blurred and noisy: one 13 px thresholding window misses a marker of each picture,
    # the three windows together find picture 2 whole.
    view = camera_view(BOARD, looking_at(BOARD, 0.2, scale=0.425), blur=5, noise=8)
    detection = reader.read(view)
    assert reader.full_scans == 1
    assert not detection.crops[0].available
    assert detection.crops[1].available, detection.crops[1].reason
    assert ncc(detection.crops[1].image, expected(1)) >= 0.9
