"""Synthetic views of the marker board for readmarker's tests and benchmark: code-drawn pictures,
the board they make, and camera views of it through a known homography with noise and blur."""
import cv2
import numpy as np

from readmarker.board import CROP_SIZE, draw_board


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


def framed_crop(board, region):
    """What a picture's markers frame on a board (the picture in its thin white border), at the crop's size."""
    x0, y0, x1, y1 = region
    return cv2.resize(board[y0:y1, x0:x1], (CROP_SIZE, CROP_SIZE), interpolation=cv2.INTER_AREA)


def expected(k):
    """Picture k's crop from BOARD."""
    return framed_crop(BOARD, FRAMED[k])
