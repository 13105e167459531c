"""Images as image_view shows them: encodings, row padding, depth scaled 0 to 10 m, JPEG."""
import cv2
import numpy
import pytest
from sensor_msgs.msg import CompressedImage, Image

from sim_studio.views.images.conversion import (ImageError, compressed_to_bgr, encode_jpeg, image_to_bgr,
                                               scale_depth)


def image(encoding, pixels, padding=0):
    height, width = pixels.shape[:2]
    raw = pixels.tobytes()
    row = len(raw) // height
    data = b"".join(raw[r * row:(r + 1) * row] + bytes(padding) for r in range(height))
    return Image(height=height, width=width, encoding=encoding, step=row + padding, data=data)


def test_rgb8_becomes_bgr_and_padding_is_skipped():
    pixels = numpy.zeros((2, 3, 3), numpy.uint8)
    pixels[0, 0] = (255, 0, 0)
    shown = image_to_bgr(image("rgb8", pixels, padding=7))
    assert shown.shape == (2, 3, 3) and tuple(shown[0, 0]) == (0, 0, 255)


def test_bgr8_mono8_and_mono16():
    pixels = numpy.arange(6, dtype=numpy.uint8).reshape(2, 3)
    assert (image_to_bgr(image("mono8", pixels)) == pixels).all()
    wide = numpy.array([[0, 65535]], numpy.uint16)
    assert image_to_bgr(image("mono16", wide)).tolist() == [[0, 255]]
    big_endian = image("mono16", wide.byteswap())
    big_endian.is_bigendian = 1
    assert image_to_bgr(big_endian).tolist() == [[0, 255]]


def test_depth_in_metres_and_millimetres_as_image_view_scales_it():
    metres = numpy.array([[0.0, 2.5, 10.0, 20.0, numpy.nan]], numpy.float32)
    assert image_to_bgr(image("32FC1", metres)).tolist() == [[0, 64, 255, 255, 0]]
    millimetres = numpy.array([[0, 2500, 10000, 60000]], numpy.uint16)
    assert image_to_bgr(image("16UC1", millimetres)).tolist() == [[0, 64, 255, 255]]


def test_dynamic_scaling_uses_the_finite_range():
    metres = numpy.array([[1.0, 2.0, numpy.nan, 3.0]], numpy.float32)
    assert scale_depth(metres, "32FC1", dynamic=True).tolist() == [[0, 128, 0, 255]]
    assert scale_depth(numpy.full((1, 2), 4.0), "32FC1", dynamic=True).tolist() == [[128, 128]]


def test_bad_images_say_why():
    with pytest.raises(ImageError, match="encoding 'bayer_rggb8' is not shown"):
        image_to_bgr(Image(height=1, width=1, encoding="bayer_rggb8", step=1, data=b"\0"))
    with pytest.raises(ImageError, match="needs rows of 6 bytes"):
        image_to_bgr(Image(height=2, width=2, encoding="rgb8", step=6, data=bytes(6)))
    with pytest.raises(ImageError, match="empty"):
        image_to_bgr(Image(height=0, width=0, encoding="rgb8", step=0, data=b""))


def test_compressed_and_jpeg_round_trip():
    pixels = numpy.zeros((16, 16, 3), numpy.uint8)
    pixels[:, :8] = (0, 0, 255)  # red in BGR
    png = CompressedImage(format="png", data=cv2.imencode(".png", pixels)[1].tobytes())
    assert (compressed_to_bgr(png) == pixels).all()
    decoded = cv2.imdecode(numpy.frombuffer(encode_jpeg(pixels), numpy.uint8), cv2.IMREAD_COLOR)
    assert abs(int(decoded[8, 2, 2]) - 255) < 10 and decoded.shape == (16, 16, 3)
    with pytest.raises(ImageError, match="cannot decode"):
        compressed_to_bgr(CompressedImage(format="jpeg", data=b"not a jpeg"))
