"""map_saver's files: a PGM with the map's top row first (occupied 0, free 254, unknown 205) and
the YAML that loads it back."""
import os

import numpy as np

OCCUPIED, FREE, UNKNOWN = 0, 254, 205


def saver_image(data, width, height, threshold_occupied=65, threshold_free=25):
    """The PGM pixels (height x width uint8, top row = largest y) of OccupancyGrid data, with
    map_saver's thresholds: 0..free -> free, occupied and above -> occupied, the rest unknown."""
    cells = np.asarray(data, dtype=np.int16).reshape(height, width)
    image = np.full((height, width), UNKNOWN, dtype=np.uint8)
    image[(cells >= 0) & (cells <= threshold_free)] = FREE
    image[cells >= threshold_occupied] = OCCUPIED
    return np.flipud(image)


def write_map_files(basename, data, width, height, resolution, origin, threshold_occupied=65, threshold_free=25):
    """Writes BASENAME.pgm and BASENAME.yaml as map_saver does; returns the two paths."""
    image = saver_image(data, width, height, threshold_occupied, threshold_free)
    pgm, yml = basename + '.pgm', basename + '.yaml'
    with open(pgm, 'wb') as f:
        f.write(b'P5\n# CREATOR: map_saver.cpp %.3f m/pix\n%d %d\n255\n' % (resolution, width, height))
        f.write(image.tobytes())
    x, y, yaw = origin
    with open(yml, 'w') as f:
        f.write('image: %s\nresolution: %f\norigin: [%f, %f, %f]\nnegate: 0\noccupied_thresh: 0.65\n'
                'free_thresh: 0.196\n\n' % (os.path.basename(pgm), resolution, x, y, yaw))
    return pgm, yml
