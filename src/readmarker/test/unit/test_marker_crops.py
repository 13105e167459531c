"""readmarker's crops on synthetic views of the board: a known homography, noise and blur."""
import cv2
import numpy as np
import pytest

from readmarker.board import CROP_SIZE, draw_board, marker_image
from readmarker.crop import MarkerReader, ncc


def picture(seed, size=(240, 200)):
    """A picture with structure at several scales (a stand-in for the lecture's dog and cat)."""
    rng = np.random.default_rng(seed)
    h, w = size[1], size[0]
    y, x = np.mgrid[0:h, 0:w]
    image = np.zeros((h, w, 3), np.uint8)
    for c in range(3):
        fx, fy, phase = rng.uniform(0.01, 0.05, 2).tolist() + [rng.uniform(0, 6)]
        image[..., c] = (127 + 100 * np.sin(fx * x + phase) * np.cos(fy * y)).astype(np.uint8)
    for _ in range(6):
        centre = (int(rng.integers(20, w - 20)), int(rng.integers(20, h - 20)))
        cv2.circle(image, centre, int(rng.integers(8, 40)), tuple(int(v) for v in rng.integers(0, 255, 3)), -1)
    return image


def camera_view(board, homography, size=(800, 800), noise=4.0, blur=3, seed=0):
    view = cv2.warpPerspective(board, homography, size, flags=cv2.INTER_LINEAR, borderValue=(90, 90, 90))
    if blur:
        view = cv2.GaussianBlur(view, (blur, blur), 0)
    rng = np.random.default_rng(seed)
    return np.clip(view + rng.normal(0, noise, view.shape), 0, 255).astype(np.uint8)


def looking_at(board, tilt=0.0, scale=0.97, shift=(12, 150)):
    """A homography from the board to an 800 x 800 image: scaled, shifted, with perspective."""
    h, w = board.shape[:2]
    src = np.float32([[0, 0], [w, 0], [w, h], [0, h]])
    s = 760.0 * scale / w
    x0, y0 = shift
    dst = np.float32([[x0, y0 + tilt * h * s], [x0 + w * s, y0], [x0 + w * s, y0 + h * s],
                      [x0, y0 + h * s * (1 - tilt)]])
    return cv2.getPerspectiveTransform(src, dst)


PICTURES = [picture(1), picture(2)]
MARKER = 60
BOARD, FRAMED = draw_board(PICTURES, marker=MARKER, margin=20, between=60)


def expected(k):
    """What picture k's markers frame on the board (the picture in its thin white border), at the crop's size."""
    x0, y0, x1, y1 = FRAMED[k]
    return cv2.resize(BOARD[y0:y1, x0:x1], (CROP_SIZE, CROP_SIZE), interpolation=cv2.INTER_AREA)


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
