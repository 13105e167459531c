"""Where webcam_node's frames come from, without ROS: a V4L2 device (by number or path) or a
file (a video, looped, or a still image, repeated), resized on request."""
import os

import cv2

IMAGE_EXTENSIONS = ('.png', '.jpg', '.jpeg', '.bmp', '.tif', '.tiff', '.pgm', '.ppm')


class SourceError(RuntimeError):
    """The source cannot be opened or read: names it and says what to try."""


class FrameSource:
    def __init__(self, device_id=0, device_path='', file='', width=0, height=0):
        self.width, self.height = int(width), int(height)
        self.still = None
        self.capture = None
        self.is_file = bool(file)
        if file:
            self.name = file
            if not os.path.isfile(file):
                raise SourceError("file '%s' does not exist" % file)
            if file.lower().endswith(IMAGE_EXTENSIONS):
                self.still = cv2.imread(file, cv2.IMREAD_COLOR)
                if self.still is None:
                    raise SourceError("file '%s' is not an image OpenCV can read" % file)
            else:
                self.capture = cv2.VideoCapture(file)
                if not self.capture.isOpened():
                    raise SourceError("file '%s' is not a video OpenCV can read" % file)
        else:
            self.name = device_path or '/dev/video%d' % int(device_id)
            if not os.path.exists(self.name):
                raise SourceError("no camera at %s (set ~device_id or ~device_path to a V4L2 device, or ~file to a "
                                  "video or an image to publish instead)" % self.name)
            self.capture = cv2.VideoCapture(self.name, cv2.CAP_V4L2)
            if not self.capture.isOpened():
                raise SourceError("cannot open the camera at %s (in use, or not a V4L2 capture device); ~file "
                                  "publishes a video or an image instead" % self.name)
            if self.width > 0 and self.height > 0:
                self.capture.set(cv2.CAP_PROP_FRAME_WIDTH, self.width)
                self.capture.set(cv2.CAP_PROP_FRAME_HEIGHT, self.height)
        self.looped = 0  # times a video file went back to its start

    def read(self):
        """The next frame (BGR, resized to width x height when both are set), or raises SourceError."""
        if self.still is not None:
            frame = self.still
        else:
            ok, frame = self.capture.read()
            if not ok and self.is_file:
                self.capture.set(cv2.CAP_PROP_POS_FRAMES, 0)  # a file: loop
                self.looped += 1
                ok, frame = self.capture.read()
            if not ok or frame is None:
                raise SourceError('%s gave no frame' % self.name)
        if self.width > 0 and self.height > 0 and frame.shape[:2] != (self.height, self.width):
            frame = cv2.resize(frame, (self.width, self.height), interpolation=cv2.INTER_AREA)
        return frame

    def close(self):
        if self.capture is not None:
            self.capture.release()
