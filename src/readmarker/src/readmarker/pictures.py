"""The board's two pictures, drawn here so that the project owns them: a dog (picture 1, framed by
markers 1-4, as in the lecture's slides) and a cat (picture 2, markers 5-8). Flat cartoon faces on a
light background: the background keeps the markers, which stand a few pixels off the picture's
corners, from merging with a dark part of it."""
import cv2
import numpy as np

from readmarker.board import draw_board

SIZE = (240, 200)  # px, width x height, as the board lays them out

BLACK = (30, 30, 30)
WHITE = (250, 250, 250)
PINK = (170, 150, 240)


def _canvas(background):
    return np.full((SIZE[1], SIZE[0], 3), background, np.uint8)


def _eyes(image, centres, radius, iris, slit=False):
    for x, y in centres:
        cv2.circle(image, (x, y), radius, WHITE, -1, cv2.LINE_AA)
        cv2.circle(image, (x, y), radius - 4, iris, -1, cv2.LINE_AA)
        if slit:
            cv2.ellipse(image, (x, y), (3, radius - 5), 0, 0, 360, BLACK, -1, cv2.LINE_AA)
        else:
            cv2.circle(image, (x, y), radius // 2, BLACK, -1, cv2.LINE_AA)
        cv2.circle(image, (x - radius // 3, y - radius // 3), 3, WHITE, -1, cv2.LINE_AA)


def dog():
    """A brown dog's face with drooping ears and its tongue out (BGR)."""
    image = _canvas((235, 215, 190))
    fur, dark = (70, 120, 175), (40, 70, 110)
    for side in (-1, 1):  # ears, hanging down beside the head
        cv2.ellipse(image, (120 + side * 70, 105), (28, 62), side * -15, 0, 360, dark, -1, cv2.LINE_AA)
    cv2.ellipse(image, (120, 100), (66, 74), 0, 0, 360, fur, -1, cv2.LINE_AA)
    cv2.ellipse(image, (120, 135), (42, 32), 0, 0, 360, (180, 210, 235), -1, cv2.LINE_AA)  # muzzle
    _eyes(image, [(95, 82), (145, 82)], 13, (40, 60, 90))
    cv2.ellipse(image, (120, 118), (15, 10), 0, 0, 360, BLACK, -1, cv2.LINE_AA)  # nose
    cv2.line(image, (120, 128), (120, 142), BLACK, 2, cv2.LINE_AA)
    cv2.ellipse(image, (109, 142), (11, 8), 0, 0, 180, BLACK, 2, cv2.LINE_AA)
    cv2.ellipse(image, (131, 142), (11, 8), 0, 0, 180, BLACK, 2, cv2.LINE_AA)
    cv2.ellipse(image, (120, 155), (9, 12), 0, 0, 180, (110, 110, 230), -1, cv2.LINE_AA)  # tongue
    return image


def cat():
    """A grey tabby cat's face with pointed ears, green slit eyes and whiskers (BGR)."""
    image = _canvas((200, 240, 245))
    fur, stripe = (150, 150, 160), (90, 90, 100)
    for side in (-1, 1):
        outer = np.int32([[120 + side * 70, 95], [120 + side * 62, 18], [120 + side * 20, 45]])
        inner = np.int32([[120 + side * 60, 78], [120 + side * 57, 34], [120 + side * 30, 52]])
        cv2.fillPoly(image, [outer], fur, cv2.LINE_AA)
        cv2.fillPoly(image, [inner], PINK, cv2.LINE_AA)
    cv2.ellipse(image, (120, 110), (74, 66), 0, 0, 360, fur, -1, cv2.LINE_AA)
    for dx in (-14, 0, 14):  # forehead stripes
        cv2.line(image, (120 + dx, 50), (120 + dx, 72), stripe, 5, cv2.LINE_AA)
    _eyes(image, [(92, 100), (148, 100)], 15, (60, 170, 70), slit=True)
    nose = np.int32([[111, 126], [129, 126], [120, 136]])
    cv2.fillPoly(image, [nose], PINK, cv2.LINE_AA)
    cv2.ellipse(image, (112, 140), (8, 6), 0, 0, 180, BLACK, 2, cv2.LINE_AA)
    cv2.ellipse(image, (128, 140), (8, 6), 0, 0, 180, BLACK, 2, cv2.LINE_AA)
    for side in (-1, 1):
        for dy in (-6, 2, 10):
            cv2.line(image, (120 + side * 24, 134 + dy // 2), (120 + side * 95, 126 + dy * 2), BLACK, 1, cv2.LINE_AA)
    return image


def pets_board(marker=80):
    """Our dog and cat framed by their markers, as draw_board returns them (the image and each
    picture's framed region). boards/board.png, which the simulated worlds show, is pets_board()."""
    return draw_board([dog(), cat()], marker=marker)
