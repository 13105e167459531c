"""webcam's frame sources and calibration files, without ROS."""
import cv2
import numpy as np
import pytest

from clips import LEVELS, write_video
from webcam.camera_info import CalibrationError, load_camera_info, resolve_url, uncalibrated
from webcam.frame_source import FrameSource, SourceError


def test_a_video_file_plays_in_order_and_loops(tmp_path):
    source = FrameSource(file=write_video(tmp_path / 'clip.avi'))
    seen = [int(round(source.read().mean())) for _ in range(12)]
    # JPEG keeps flat grey levels within a step or two.
    assert seen == pytest.approx(LEVELS + LEVELS + LEVELS[:2], abs=3)
    assert source.looped == 2


def test_an_image_file_repeats_and_is_resized_when_asked(tmp_path):
    path = str(tmp_path / 'still.png')
    image = np.zeros((40, 60, 3), np.uint8)
    image[:, :30] = (255, 0, 0)  # blue left half, in BGR
    cv2.imwrite(path, image)
    source = FrameSource(file=path, width=120, height=80)
    first, second = source.read(), source.read()
    assert first.shape == (80, 120, 3)
    assert np.array_equal(first, second)
    assert tuple(first[40, 10]) == (255, 0, 0) and tuple(first[40, 110]) == (0, 0, 0)


@pytest.mark.parametrize('kwargs, says', [
    (dict(device_id=57), 'no camera at /dev/video57'),
    (dict(device_path='/dev/nothing_here'), 'no camera at /dev/nothing_here'),
    (dict(file='/tmp/no_such_clip.mp4'), "file '/tmp/no_such_clip.mp4' does not exist"),
])
def test_a_missing_source_is_named_with_what_to_try(kwargs, says):
    with pytest.raises(SourceError) as error:
        FrameSource(**kwargs)
    assert says in str(error.value)
    if 'file' not in kwargs:
        assert '~file' in str(error.value)


def test_a_file_that_is_no_image_is_refused(tmp_path):
    path = tmp_path / 'broken.png'
    path.write_bytes(b'not a png')
    with pytest.raises(SourceError, match='not an image'):
        FrameSource(file=str(path))


CALIBRATION = """image_width: 640
image_height: 480
camera_name: webcam
camera_matrix: {rows: 3, cols: 3, data: [500.0, 0.0, 320.0, 0.0, 500.0, 240.0, 0.0, 0.0, 1.0]}
distortion_model: plumb_bob
distortion_coefficients: {rows: 1, cols: 5, data: [0.1, -0.2, 0.0, 0.0, 0.0]}
rectification_matrix: {rows: 3, cols: 3, data: [1, 0, 0, 0, 1, 0, 0, 0, 1]}
projection_matrix: {rows: 3, cols: 4, data: [500.0, 0.0, 320.0, 0.0, 0.0, 500.0, 240.0, 0.0, 0.0, 0.0, 1.0, 0.0]}
"""


def test_a_calibration_file_becomes_camera_info(tmp_path):
    path = tmp_path / 'webcam.yaml'
    path.write_text(CALIBRATION)
    info = load_camera_info(resolve_url('file://' + str(path)))
    assert (info.width, info.height, info.distortion_model) == (640, 480, 'plumb_bob')
    assert list(info.K) == [500.0, 0.0, 320.0, 0.0, 500.0, 240.0, 0.0, 0.0, 1.0]
    assert list(info.D) == [0.1, -0.2, 0.0, 0.0, 0.0]
    assert list(info.P)[:3] == [500.0, 0.0, 320.0]
    assert resolve_url('package://webcam/calib/a.yaml', find_package=lambda p: '/opt/' + p) == '/opt/webcam/calib/a.yaml'
    blank = uncalibrated(64, 48)
    assert (blank.width, blank.height, list(blank.K)) == (64, 48, [0.0] * 9)


def test_a_bad_calibration_names_the_file_and_the_field(tmp_path):
    path = tmp_path / 'bad.yaml'
    path.write_text(CALIBRATION.replace('0.0, 0.0, 1.0]}\ndistortion_model', '0.0]}\ndistortion_model'))
    with pytest.raises(CalibrationError) as error:
        load_camera_info(str(path))
    assert str(path) in str(error.value) and 'camera_matrix: expected 9 values, got 7' in str(error.value)
    with pytest.raises(CalibrationError, match='expected a file:// or package:// URL'):
        resolve_url('http://example.com/cal.yaml')
