"""map_server's map files (map_files.load, map_files.save): no ROS master."""
import os
import sys

import numpy as np
import pytest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..', 'src'))

from map_files import load, save  # noqa: E402


def test_trinary_reads_black_as_occupied_white_as_free_and_grey_as_unknown_bottom_row_first():
    pixels = np.array([[0, 255], [205, 254]], dtype=np.uint8)  # top row: black, white
    # 205 is p = 50/255 = 0.19608 >= free_thresh 0.196: unknown; 254 is p = 0.004: free.
    assert load.occupancy_from_pixels(pixels) == [-1, 0, 100, 0]


def test_negate_swaps_black_and_white():
    assert load.occupancy_from_pixels(np.array([[0, 255]], dtype=np.uint8), negate=1) == [0, 100]


def test_scale_mode_spreads_the_middle_over_1_to_99():
    # 128: p = 127/255 = 0.498, 1 + 98 (0.498 - 0.196) / (0.65 - 0.196) = 66.2
    assert load.occupancy_from_pixels(np.array([[128, 0, 255]], dtype=np.uint8), mode='scale') == [66, 100, 0]


def test_scale_mode_leaves_transparent_middle_pixels_unknown():
    grey_alpha = np.array([[[128, 0], [128, 255]]], dtype=np.uint8)  # grey + alpha: transparent, opaque
    assert load.occupancy_from_pixels(grey_alpha, mode='scale') == [-1, 66]


def test_raw_mode_keeps_the_values():
    assert load.occupancy_from_pixels(np.array([[0, 37, 100]], dtype=np.uint8), mode='raw') == [0, 37, 100]


def test_colour_channels_are_averaged():
    bgr = np.array([[[0, 0, 255], [255, 255, 255]]], dtype=np.uint8)  # average 85: p = 0.667
    assert load.occupancy_from_pixels(bgr) == [100, 0]


def write(tmp_path, text, name='m.yaml'):
    path = tmp_path / name
    path.write_text(text)
    return str(path)


GOOD = 'image: m.pgm\nresolution: 0.05\norigin: [-1.0, 2.0, 0.0]\nnegate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n'


@pytest.mark.parametrize('drop,message', [
    ('resolution: 0.05\n', 'The map does not contain a resolution tag or it is invalid.'),
    ('negate: 0\n', 'The map does not contain a negate tag or it is invalid.'),
    ('occupied_thresh: 0.65\n', 'The map does not contain an occupied_thresh tag or it is invalid.'),
    ('free_thresh: 0.196\n', 'The map does not contain a free_thresh tag or it is invalid.'),
    ('origin: [-1.0, 2.0, 0.0]\n', 'The map does not contain an origin tag or it is invalid.'),
    ('image: m.pgm\n', 'The map does not contain an image tag or it is invalid.'),
])
def test_a_missing_tag_is_named_with_map_servers_words(tmp_path, drop, message):
    path = write(tmp_path, GOOD.replace(drop, ''))
    with pytest.raises(load.MapFileError) as e:
        load.read_yaml(path)
    assert str(e.value) == '%s: %s' % (path, message)


def test_bad_values_and_files_are_named(tmp_path):
    with pytest.raises(load.MapFileError, match='Invalid mode tag "fancy"'):
        load.read_yaml(write(tmp_path, GOOD + 'mode: fancy\n'))
    with pytest.raises(load.MapFileError, match='resolution tag or it is invalid'):
        load.read_yaml(write(tmp_path, GOOD.replace('0.05', '-0.05')))
    with pytest.raises(load.MapFileError, match='origin tag or it is invalid'):
        load.read_yaml(write(tmp_path, GOOD.replace('[-1.0, 2.0, 0.0]', '[1, 2]')))
    with pytest.raises(load.MapFileError, match='Map_server could not open .*nothing.yaml'):
        load.read_yaml(str(tmp_path / 'nothing.yaml'))
    with pytest.raises(load.MapFileError, match='Failed to open image file ".*m.pgm"'):
        load.load_map(write(tmp_path, GOOD))


def test_the_image_path_is_relative_to_the_yaml(tmp_path):
    settings = load.read_yaml(write(tmp_path, GOOD))
    assert settings['image'] == str(tmp_path / 'm.pgm')
    assert settings['origin'] == (-1.0, 2.0, 0.0)
    assert settings['mode'] == 'trinary'


def test_map_saver_files_load_back_into_the_same_map(tmp_path):
    data = [0, 100, -1, 50, 25, 65, 24, 0]  # 4 x 2, bottom row first
    pgm, yml = save.write_map_files(str(tmp_path / 'saved'), data, 4, 2, 0.1, (1.5, -2.0, 0.0))
    assert open(pgm, 'rb').read().startswith(b'P5\n')
    grid = load.load_map(yml)
    assert (grid.width, grid.height, grid.resolution, grid.origin) == (4, 2, 0.1, (1.5, -2.0, 0.0))
    # map_saver: 0..25 free, 65.. occupied, the rest (and -1) unknown; map_server reads those back.
    assert grid.data == [0, 100, -1, -1, 0, 100, 0, 0]


def test_map_saver_puts_the_maps_top_row_first():
    image = save.saver_image([0, 0, 100, 100], 2, 2)
    assert image.tolist() == [[0, 0], [254, 254]]

