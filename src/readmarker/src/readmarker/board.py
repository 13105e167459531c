"""The lecture's marker board, without ROS: ArUco markers (DICT_6X6_250) framing two pictures,
ids 1-4 round picture 1 and 5-8 round picture 2, each set clockwise from the top left (top left,
top right, bottom right, bottom left). A picture's crop is the quadrilateral of its markers' inner
corners: the corner of each marker that faces the picture. The markers stand a few pixels off the
picture's corners: one touching a dark part of the picture merges with it, and the detector loses
it."""
import cv2
import numpy as np

from readmarker import aruco_api

DICTIONARY = cv2.aruco.DICT_6X6_250
PICTURE_IDS = ((1, 2, 3, 4), (5, 6, 7, 8))
# Which of a marker's corners (OpenCV's order: top left, top right, bottom right, bottom left of
# the marker) faces the picture, for the markers at the picture's top left, top right, bottom
# right and bottom left.
INNER_CORNER = (2, 3, 0, 1)
CROP_SIZE = 255  # px, the lecture's crops


def dictionary():
    return cv2.aruco.getPredefinedDictionary(DICTIONARY)


def marker_image(marker_id, size=200):
    """One marker, size x size px, black on white (what the `aruco` tool writes)."""
    return aruco_api.marker_image(dictionary(), marker_id, size)


def draw_board(pictures, marker=80, gap=8, margin=40, between=80):
    """A board image (BGR) with the two pictures side by side, each framed by its four markers
    `gap` px off the picture's corners, and the region each pair of markers frames (the picture
    and the gap round it): [(x0, y0, x1, y1)] in board pixels."""
    heights = [p.shape[0] for p in pictures]
    widths = [p.shape[1] for p in pictures]
    height = 2 * margin + 2 * (marker + gap) + max(heights)
    width = 2 * margin + sum(w + 2 * (marker + gap) for w in widths) + between * (len(pictures) - 1)
    board = np.full((height, width, 3), 255, np.uint8)
    places = []
    x = margin
    for picture, ids in zip(pictures, PICTURE_IDS):
        h, w = picture.shape[:2]
        px, py = x + marker + gap, margin + marker + gap
        board[py:py + h, px:px + w] = picture if picture.ndim == 3 else cv2.cvtColor(picture, cv2.COLOR_GRAY2BGR)
        corners = [(px - gap - marker, py - gap - marker), (px + w + gap, py - gap - marker),
                   (px + w + gap, py + h + gap), (px - gap - marker, py + h + gap)]
        for marker_id, (mx, my) in zip(ids, corners):
            board[my:my + marker, mx:mx + marker] = cv2.cvtColor(marker_image(marker_id, marker), cv2.COLOR_GRAY2BGR)
        places.append((px - gap, py - gap, px + w + gap, py + h + gap))
        x += w + 2 * (marker + gap) + between
    return board, places
