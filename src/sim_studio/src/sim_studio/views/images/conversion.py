"""sensor_msgs/Image and CompressedImage to something a browser shows, as image_view shows them.
numpy and OpenCV only, no ROS master.

Colour and mono encodings are shown as they are (RGB reordered for OpenCV, which works in BGR).
Depth, as image_view does by default: 32FC1 in metres and 16UC1 in millimetres are scaled from 0
to 10 m onto black to white (farther is white, saturating), NaN is black; `dynamic` scales from
the image's own smallest to largest finite value instead (image_view's do_dynamic_scaling).
mono16 is scaled from its full range.
"""
import cv2
import numpy

DEPTH_MAX = {"32FC1": 10.0, "16UC1": 10000.0}  # image_view's defaults: 10 m

# encoding -> (numpy type, channels, conversion to BGR or None for mono/BGR as is)
_ENCODINGS = {
    "rgb8": ("u1", 3, cv2.COLOR_RGB2BGR), "bgr8": ("u1", 3, None), "rgba8": ("u1", 4, cv2.COLOR_RGBA2BGR),
    "bgra8": ("u1", 4, cv2.COLOR_BGRA2BGR), "mono8": ("u1", 1, None), "8UC1": ("u1", 1, None),
    "8UC3": ("u1", 3, None), "8UC4": ("u1", 4, cv2.COLOR_BGRA2BGR), "mono16": ("u2", 1, None),
    "16UC1": ("u2", 1, None), "32FC1": ("f4", 1, None),
    "rgb16": ("u2", 3, cv2.COLOR_RGB2BGR), "bgr16": ("u2", 3, None),
}


class ImageError(ValueError):
    """An image that cannot be shown; the text says why."""


def image_to_bgr(msg, dynamic=False):
    """An 8-bit BGR (or mono) array of a sensor_msgs/Image."""
    if msg.encoding not in _ENCODINGS:
        raise ImageError("encoding %r is not shown here (shown: %s)" % (msg.encoding, ", ".join(sorted(_ENCODINGS))))
    kind, channels, to_bgr = _ENCODINGS[msg.encoding]
    dtype = numpy.dtype(kind).newbyteorder(">" if msg.is_bigendian else "<")
    row_bytes = msg.width * channels * dtype.itemsize
    if msg.width == 0 or msg.height == 0:
        raise ImageError("the image is empty (%dx%d)" % (msg.width, msg.height))
    if msg.step < row_bytes or len(msg.data) < msg.step * msg.height:
        raise ImageError("%dx%d %s needs rows of %d bytes (step %d) and %d bytes of data, got %d"
                         % (msg.width, msg.height, msg.encoding, row_bytes, msg.step, msg.step * msg.height,
                            len(msg.data)))
    rows = numpy.frombuffer(msg.data, dtype=numpy.uint8, count=msg.step * msg.height).reshape(msg.height, msg.step)
    pixels = rows[:, :row_bytes].copy().view(dtype).reshape(msg.height, msg.width, channels)
    if channels == 1:
        pixels = pixels[:, :, 0]
    if msg.encoding in DEPTH_MAX:
        return scale_depth(pixels, msg.encoding, dynamic)
    if dtype.itemsize == 2:  # mono16, rgb16: the full range onto 8 bits
        pixels = (pixels.astype(numpy.float32) / 257.0).round().astype(numpy.uint8)
    if to_bgr is not None:
        pixels = cv2.cvtColor(numpy.ascontiguousarray(pixels), to_bgr)
    return pixels


def scale_depth(depth, encoding, dynamic=False):
    """Depth to 8-bit grey: 0 to image_view's 10 m (or the finite range when dynamic), NaN black."""
    values = depth.astype(numpy.float64)
    finite = numpy.isfinite(values)
    if dynamic:
        low, high = (values[finite].min(), values[finite].max()) if finite.any() else (0.0, 0.0)
        if high == low:  # image_view shows a flat image as mid grey
            return numpy.full(depth.shape, 128, numpy.uint8)
    else:
        low, high = 0.0, DEPTH_MAX[encoding]
    scaled = numpy.where(finite, (values - low) * (255.0 / (high - low)), 0.0)
    return numpy.clip(numpy.round(scaled), 0, 255).astype(numpy.uint8)


def compressed_to_bgr(msg):
    """The decoded picture of a sensor_msgs/CompressedImage (JPEG or PNG)."""
    if "compressedDepth" in msg.format:
        raise ImageError("compressedDepth images are not shown here; view the raw depth topic")
    image = cv2.imdecode(numpy.frombuffer(msg.data, numpy.uint8), cv2.IMREAD_UNCHANGED)
    if image is None:
        raise ImageError("cannot decode the %s data (%d bytes)" % (msg.format or "compressed", len(msg.data)))
    if image.dtype == numpy.uint16:
        image = (image.astype(numpy.float32) / 257.0).round().astype(numpy.uint8)
    if image.ndim == 3 and image.shape[2] == 4:
        image = cv2.cvtColor(image, cv2.COLOR_BGRA2BGR)
    return image


def encode_jpeg(image, quality=85):
    ok, data = cv2.imencode(".jpg", image, [cv2.IMWRITE_JPEG_QUALITY, quality])
    if not ok:
        raise ImageError("OpenCV could not encode a %s image as JPEG" % (image.shape,))
    return data.tobytes()
