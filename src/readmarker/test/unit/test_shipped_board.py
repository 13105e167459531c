"""The board the simulated worlds show (boards/board.png, our dog and cat) is what the aruco tool
draws, the board model's default aspect is the image's, and readmarker reads it."""
import os
import subprocess
import sys
import xml.etree.ElementTree as ET

import cv2
import numpy as np

from board_views import camera_view, framed_crop, looking_at
from readmarker.crop import MarkerReader, ncc
from readmarker.pictures import pets_board

PACKAGE = os.path.join(os.path.dirname(os.path.abspath(__file__)), os.pardir, os.pardir)
SHIPPED = cv2.imread(os.path.join(PACKAGE, 'boards', 'board.png'))
DRAWN, FRAMED = pets_board()


def test_the_shipped_board_is_the_one_the_aruco_tool_draws(tmp_path):
    assert SHIPPED is not None and SHIPPED.shape == DRAWN.shape == (456, 992, 3)
    # Exact today; a little room for another OpenCV's anti-aliasing of the drawings' edges.
    assert np.abs(SHIPPED.astype(int) - DRAWN).mean() < 1.0
    tool = os.path.join(PACKAGE, 'scripts', 'aruco')
    subprocess.run([sys.executable, tool, '--out', str(tmp_path), '--size', '80', '--board'], check=True,
                   stdout=subprocess.PIPE)
    written = cv2.imread(str(tmp_path / 'board.png'))
    assert written.shape == SHIPPED.shape and np.abs(written.astype(int) - DRAWN).max() == 0
    assert sorted(os.listdir(tmp_path)) == sorted(['board.png'] + ['marker_%d.png' % i for i in range(1, 9)])


def test_the_aruco_tool_wants_two_pictures_or_none(tmp_path):
    tool = os.path.join(PACKAGE, 'scripts', 'aruco')
    done = subprocess.run([sys.executable, tool, '--out', str(tmp_path), '--board', 'dog.png'],
                          stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    assert done.returncode == 2
    assert 'expected two pictures (or none, for our dog and cat), got 1' in done.stderr
    assert os.listdir(tmp_path) == []  # nothing written


def test_the_board_model_has_the_image_aspect():
    done = subprocess.run(['xacro', os.path.join(PACKAGE, 'urdf', 'marker_board.urdf.xacro')], check=True,
                          stdout=subprocess.PIPE, text=True)
    box = ET.fromstring(done.stdout).find('link[@name="board"]/visual/geometry/box')
    thickness, width, height = (float(v) for v in box.get('size').split())
    assert width == 1.0 and 0.01 <= thickness <= 0.03
    assert abs(height / width - SHIPPED.shape[0] / SHIPPED.shape[1]) < 1e-5


def test_readmarker_reads_the_shipped_board():
    framed = [framed_crop(SHIPPED, region) for region in FRAMED]
    detection = MarkerReader().read(camera_view(SHIPPED, looking_at(SHIPPED, 0.2)))
    for k, crop in enumerate(detection.crops):
        assert crop.available, crop.reason
        assert ncc(crop.image, framed[k]) >= 0.95
        assert ncc(crop.image, framed[1 - k]) < 0.5  # the dog is not the cat
