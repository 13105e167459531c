"""map_files: map_server's PGM + YAML written and read back, orientation, occupied points, the PNG."""
import os
import sys

import numpy as np
import pytest

sys.path.insert(0, os.path.join(os.path.dirname(__file__), '..', '..', 'src'))
# map_server's map_files (its writer is the mapper's): from the source tree, as before a build.
sys.path.insert(0, os.path.join(os.path.dirname(__file__), '..', '..', '..', 'map_server', 'src'))
from hector_style_mapping_tools import map_files  # noqa: E402
from map_files import load as map_server_load  # noqa: E402


def grid(width=6, height=4):
    """-1 everywhere, free row 0, one wall cell at column 4, row 3 (top right)."""
    data = np.full((height, width), -1, dtype=np.int8)
    data[0, :] = 0
    data[3, 4] = 100
    return data.ravel().tolist()


def test_image_is_map_servers_trinary_with_the_top_row_at_the_largest_y():
    image = map_files.occupancy_to_image(grid(), 6, 4)
    assert image.shape == (4, 6)
    assert image[0, 4] == map_files.OCCUPIED        # grid row 3 is the image's top row
    assert (image[3, :] == map_files.FREE).all()    # grid row 0 is the bottom row
    assert image[1, 1] == map_files.UNKNOWN


def test_middle_occupancy_values_follow_map_savers_thresholds():
    image = map_files.occupancy_to_image([10, 50, 70], 3, 1)
    assert image.tolist() == [[map_files.FREE, map_files.UNKNOWN, map_files.OCCUPIED]]


def test_written_map_reads_back_with_its_geometry(tmp_path):
    base = str(tmp_path / 'maze')
    pgm, yml = map_files.write_map(base, grid(), 6, 4, 0.05, (-1.0, -0.5, 0.0))
    assert os.path.basename(pgm) == 'maze.pgm'
    with open(yml) as f:
        text = f.read()
    for line in ('image: maze.pgm', 'resolution: 0.050000', 'origin: [-1.000000, -0.500000, 0.000000]',
                 'negate: 0', 'occupied_thresh: 0.65', 'free_thresh: 0.196'):
        assert line in text
    image, resolution, origin = map_files.read_map(yml)
    assert resolution == pytest.approx(0.05)
    assert origin == pytest.approx((-1.0, -0.5, 0.0))
    assert (image == map_files.occupancy_to_image(grid(), 6, 4)).all()



def test_saved_maps_load_into_map_server(tmp_path):
    data = [0, 100, -1, 19, 20, 65, 64, 0]  # 4 x 2, bottom row first
    _, yml = map_files.write_map(str(tmp_path / 'mapped'), data, 4, 2, 0.05, (-2.0, -3.0, 0.0))
    grid = map_server_load.load_map(yml)
    assert (grid.width, grid.height, grid.resolution, grid.origin) == (4, 2, 0.05, (-2.0, -3.0, 0.0))
    # Up to 19 % free, from 65 % occupied, the rest unknown, as map_server reads the thresholds back.
    assert grid.data == [0, 100, -1, 0, -1, 100, -1, 0]


def test_occupied_points_are_cell_centres_in_the_map_frame():
    image = map_files.occupancy_to_image(grid(), 6, 4)
    points = map_files.occupied_points(image, 0.05, (-1.0, -0.5, 0.0))
    assert points.shape == (1, 2)
    assert points[0].tolist() == pytest.approx([-1.0 + 4.5 * 0.05, -0.5 + 3.5 * 0.05])


def test_read_map_names_what_is_missing(tmp_path):
    bad = tmp_path / 'bad.yaml'
    bad.write_text('image: x.pgm\n')
    with pytest.raises(ValueError, match='resolution'):
        map_files.read_map(str(bad))


def test_a_plain_text_pgm_is_refused_with_a_reason(tmp_path):
    path = tmp_path / 'ascii.pgm'
    path.write_text('P2\n2 1\n255\n0 254\n')
    with pytest.raises(ValueError, match='P5'):
        map_files.read_pgm(str(path))


def test_crop_keeps_the_seen_part_and_says_what_it_cut():
    image = np.full((100, 80), map_files.UNKNOWN, dtype=np.uint8)
    image[40:50, 30:35] = map_files.FREE
    cropped, (left, bottom) = map_files.crop_to_known(image, margin=2)
    assert cropped.shape == (14, 9)
    assert (left, bottom) == (28, 100 - 52)


def test_png_draws_the_trajectory_over_the_map(tmp_path):
    cv2 = pytest.importorskip('cv2')
    image = np.full((40, 40), map_files.FREE, dtype=np.uint8)
    path = map_files.render_png(str(tmp_path / 'map.png'), image, 0.05, (0.0, 0.0, 0.0),
                                trajectory=[(0.5, 0.5), (1.5, 0.5)], scale=4)
    picture = cv2.imread(path)
    assert picture.shape == (160, 160, 3)
    # Half-way along the trajectory (1.0, 0.5): red.
    column, row = map_files.to_pixel(1.0, 0.5, 0.05, (0.0, 0.0), 40)
    b, g, r = picture[row * 4 + 2, column * 4 + 2]
    assert r > 150 and g < 80 and b < 80
