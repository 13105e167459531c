"""Occupancy grids to and from map_server's files (PGM + YAML), and a PNG for people (pure, no ROS).

A grid is given as nav_msgs/OccupancyGrid carries it: row-major int8 data (-1 unknown, 0..100
occupancy), width, height, resolution and the map-frame (x, y, yaw) of cell (0, 0)'s corner. In the
PGM, as map_server writes it, the first row is the top of the map (largest y), occupied cells are 0
(black), free ones 254 and unknown ones 205.
"""
import math
import os

import numpy as np
import yaml

from map_files import save as map_saver  # map_server's writer

OCCUPIED, FREE, UNKNOWN = map_saver.OCCUPIED, map_saver.FREE, map_saver.UNKNOWN
# The mapper's thresholds, in whole per cent: occupied from map_server's occupied_thresh (65 %),
# free up to its free_thresh (19.6 %), so that map_server reads the map back as it was saved.
THRESHOLD_OCCUPIED, THRESHOLD_FREE = 65, 19


def occupancy_to_image(data, width, height):
    """The PGM pixels (height x width uint8, top row = largest y) of an OccupancyGrid's data."""
    return map_saver.saver_image(data, width, height, THRESHOLD_OCCUPIED, THRESHOLD_FREE)


def write_map(basename, data, width, height, resolution, origin):
    """Writes BASENAME.pgm and BASENAME.yaml as map_server's map_saver does; returns the two paths."""
    return map_saver.write_map_files(basename, data, width, height, resolution, origin, THRESHOLD_OCCUPIED,
                                     THRESHOLD_FREE)


def read_map(yaml_path):
    """(image, resolution, (x, y, yaw)) of a map_server map; the image as in the file (top row = largest y)."""
    with open(yaml_path) as f:
        meta = yaml.safe_load(f)
    for key in ('image', 'resolution', 'origin'):
        if key not in meta:
            raise ValueError('%s: no "%s" (a map_server map yaml has image, resolution and origin)' % (yaml_path, key))
    image_path = os.path.join(os.path.dirname(yaml_path), meta['image'])
    image = read_pgm(image_path)
    if meta.get('negate', 0):
        image = 255 - image
    return image, float(meta['resolution']), tuple(float(v) for v in meta['origin'])


def read_pgm(path):
    """A binary (P5) 8-bit PGM as a uint8 array."""
    with open(path, 'rb') as f:
        raw = f.read()
    fields, pos = [], 0
    while len(fields) < 4:
        while raw[pos:pos + 1].isspace():
            pos += 1
        if raw[pos:pos + 1] == b'#':
            pos = raw.index(b'\n', pos) + 1
            continue
        end = pos
        while not raw[end:end + 1].isspace():
            end += 1
        fields.append(raw[pos:end])
        pos = end
    if fields[0] != b'P5' or int(fields[3]) != 255:
        raise ValueError('%s: expected a binary 8-bit PGM (P5, maxval 255), got %s maxval %s'
                         % (path, fields[0].decode(errors='replace'), fields[3].decode(errors='replace')))
    width, height = int(fields[1]), int(fields[2])
    pixels = np.frombuffer(raw[pos + 1:pos + 1 + width * height], dtype=np.uint8)
    if pixels.size != width * height:
        raise ValueError('%s: %d pixels for %d x %d' % (path, pixels.size, width, height))
    return pixels.reshape(height, width)


def occupied_points(image, resolution, origin):
    """Map-frame centres (N x 2) of the occupied pixels of a map_server image."""
    height = image.shape[0]
    rows, cols = np.nonzero(image <= OCCUPIED)
    x0, y0, yaw = origin
    u = (cols + 0.5) * resolution
    v = (height - 1 - rows + 0.5) * resolution
    c, s = math.cos(yaw), math.sin(yaw)
    return np.column_stack([x0 + c * u - s * v, y0 + s * u + c * v])


def to_pixel(x, y, resolution, origin, height):
    """The (column, row) of map-frame point (x, y) in an image whose origin has no yaw."""
    return int((x - origin[0]) / resolution), int(height - 1 - (y - origin[1]) / resolution)


def render_png(path, image, resolution, origin, trajectory=(), scale=4):
    """A PNG of the map for people: SCALE pixels a cell, the trajectory ((x, y) in the map frame) in
    red, its start green and its end blue, and a 1 m scale bar."""
    import cv2  # only the PNG needs OpenCV
    height = image.shape[0]
    grey = {OCCUPIED: (30, 30, 30), FREE: (250, 250, 250), UNKNOWN: (200, 200, 200)}
    picture = np.zeros(image.shape + (3,), dtype=np.uint8)
    for value, bgr in grey.items():
        picture[image == value] = bgr
    picture = cv2.resize(picture, (image.shape[1] * scale, height * scale), interpolation=cv2.INTER_NEAREST)
    points = [to_pixel(x, y, resolution, origin, height) for x, y in trajectory]
    points = np.array([((c + 0.5) * scale, (r + 0.5) * scale) for c, r in points], dtype=np.int32)
    if len(points) > 1:
        cv2.polylines(picture, [points.reshape(-1, 1, 2)], False, (0, 0, 220), max(1, scale // 2), cv2.LINE_AA)
    if len(points):
        cv2.circle(picture, tuple(int(v) for v in points[0]), 2 * scale, (0, 170, 0), -1, cv2.LINE_AA)
        cv2.circle(picture, tuple(int(v) for v in points[-1]), 2 * scale, (220, 60, 0), -1, cv2.LINE_AA)
    bar = int(round(scale / resolution))
    h = picture.shape[0]
    cv2.line(picture, (10, h - 12), (10 + bar, h - 12), (0, 0, 0), 2)
    cv2.putText(picture, '1 m', (10, h - 18), cv2.FONT_HERSHEY_SIMPLEX, 0.4, (0, 0, 0), 1, cv2.LINE_AA)
    if not cv2.imwrite(path, picture):
        raise OSError('cannot write %s' % path)
    return path


def crop_to_known(image, margin=10):
    """(image cropped to the seen part plus MARGIN cells, (columns cut on the left, rows cut at the
    bottom)) so that the PNG shows the map rather than the unknown around it."""
    rows, cols = np.nonzero(image != UNKNOWN)
    if rows.size == 0:
        return image, (0, 0)
    r0, r1 = max(rows.min() - margin, 0), min(rows.max() + margin + 1, image.shape[0])
    c0, c1 = max(cols.min() - margin, 0), min(cols.max() + margin + 1, image.shape[1])
    return image[r0:r1, c0:c1], (c0, image.shape[0] - r1)
