"""A map's YAML and image into OccupancyGrid data, by map_server's rules.

The YAML needs image (a path relative to the YAML), resolution, origin [x, y, yaw], negate,
occupied_thresh and free_thresh; mode is trinary (the default), scale or raw. Each pixel's colour
channels are averaged (alpha apart), inverted if negate, and read as an occupancy
p = (255 - value) / 255: above occupied_thresh it is 100, below free_thresh 0, in between -1
(trinary, or a transparent pixel) or 1 + 98 (p - free) / (occ - free) (scale); raw keeps the
value. The image's top row is the map's top: row 0 of the data is the image's bottom row.
"""
import collections
import math
import os

import numpy as np
import yaml

MapGrid = collections.namedtuple('MapGrid', 'data width height resolution origin')
MODES = ('trinary', 'scale', 'raw')


class MapFileError(ValueError):
    """A map YAML or image that cannot be loaded; the message says which file and what is wrong."""


def _number(meta, key, path, article='a'):
    value = meta.get(key)
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value):
        raise MapFileError('%s: The map does not contain %s %s tag or it is invalid.' % (path, article, key))
    return float(value)


def read_yaml(path):
    """The map's settings: dict with image (an absolute path), resolution, origin, negate,
    occupied_thresh, free_thresh, mode. Raises MapFileError with map_server's wording."""
    try:
        with open(path) as f:
            meta = yaml.safe_load(f)
    except OSError:
        raise MapFileError('Map_server could not open %s.' % path)
    except yaml.YAMLError as e:
        raise MapFileError('%s: not valid YAML: %s' % (path, e))
    if not isinstance(meta, dict):
        raise MapFileError('%s: expected a mapping of image, resolution, origin, ... got %r' % (path, meta))
    settings = {'resolution': _number(meta, 'resolution', path)}
    if not settings['resolution'] > 0:
        raise MapFileError('%s: The map does not contain a resolution tag or it is invalid.' % path)
    settings['negate'] = int(_number(meta, 'negate', path))
    settings['occupied_thresh'] = _number(meta, 'occupied_thresh', path, 'an')
    settings['free_thresh'] = _number(meta, 'free_thresh', path)
    mode = meta.get('mode', 'trinary')
    if mode not in MODES:
        raise MapFileError('%s: Invalid mode tag "%s".' % (path, mode))
    settings['mode'] = mode
    origin = meta.get('origin')
    if (not isinstance(origin, list) or len(origin) != 3 or
            not all(isinstance(v, (int, float)) and not isinstance(v, bool) and math.isfinite(v) for v in origin)):
        raise MapFileError('%s: The map does not contain an origin tag or it is invalid.' % path)
    settings['origin'] = tuple(float(v) for v in origin)
    image = meta.get('image')
    if not isinstance(image, str) or not image:
        raise MapFileError('%s: The map does not contain an image tag or it is invalid.' % path)
    settings['image'] = image if os.path.isabs(image) else os.path.join(os.path.dirname(os.path.abspath(path)), image)
    return settings


def occupancy_from_pixels(pixels, mode='trinary', negate=0, occupied_thresh=0.65, free_thresh=0.196):
    """OccupancyGrid data (a flat int list, row 0 = the image's bottom row) of an image: a
    height x width (grey) or height x width x channels (colour, the last one alpha when there are
    2 or 4) uint8 array."""
    pixels = np.asarray(pixels)
    if pixels.ndim == 2:
        colour, alpha = pixels.astype(np.float64), None
    else:
        channels = pixels.shape[2]
        has_alpha = channels in (2, 4)
        colour = pixels[:, :, :channels - 1 if has_alpha else channels].astype(np.float64).mean(axis=2)
        alpha = pixels[:, :, channels - 1] if has_alpha else None
    if negate:
        colour = 255.0 - colour
    if mode == 'raw':
        cells = colour.astype(np.int64)
    else:
        occupancy = (255.0 - colour) / 255.0
        cells = np.full(colour.shape, -1, dtype=np.int64)
        if mode == 'scale':
            middle = (occupancy >= free_thresh) & (occupancy <= occupied_thresh)
            scaled = 1 + 98 * (occupancy - free_thresh) / (occupied_thresh - free_thresh)
            cells[middle] = scaled[middle].astype(np.int64)
            if alpha is not None:
                cells[middle & (alpha < 1)] = -1
        cells[occupancy > occupied_thresh] = 100
        cells[occupancy < free_thresh] = 0
    return np.flipud(cells).ravel().tolist()


def load_map(yaml_path):
    """A MapGrid of the map's YAML and image. Raises MapFileError."""
    import cv2  # only loading an image needs OpenCV
    settings = read_yaml(yaml_path)
    pixels = cv2.imread(settings['image'], cv2.IMREAD_UNCHANGED)
    if pixels is None:
        raise MapFileError('%s: Failed to open image file "%s"' % (yaml_path, settings['image']))
    if pixels.dtype != np.uint8:
        pixels = (pixels / (np.iinfo(pixels.dtype).max / 255.0)).astype(np.uint8)
    data = occupancy_from_pixels(pixels, settings['mode'], settings['negate'], settings['occupied_thresh'],
                                 settings['free_thresh'])
    return MapGrid(data, pixels.shape[1], pixels.shape[0], settings['resolution'], settings['origin'])
