"""A video clip for webcam's tests: flat grey frames at known levels, in order."""
import cv2
import numpy as np

LEVELS = [0, 60, 120, 180, 240]


def write_video(path, levels=LEVELS, size=(64, 48)):
    """An MJPG clip of flat frames at these grey levels; its path."""
    writer = cv2.VideoWriter(str(path), cv2.VideoWriter_fourcc(*'MJPG'), 10, size)
    if not writer.isOpened():
        raise RuntimeError('OpenCV cannot write an MJPG video at %s' % path)
    for level in levels:
        writer.write(np.full((size[1], size[0], 3), level, np.uint8))
    writer.release()
    return str(path)
