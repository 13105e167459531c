"""CameraInfo from a camera_info_url, as camera_info_manager reads it: file:// or package:// URLs
of the calibration YAML camera_calibration writes (image_width, image_height, camera_matrix,
distortion_model, distortion_coefficients, rectification_matrix, projection_matrix)."""
import os

import yaml
from sensor_msgs.msg import CameraInfo


class CalibrationError(ValueError):
    """A URL or file that gives no calibration: names it and the field."""


def resolve_url(url, find_package=None):
    """The file a camera_info_url names ('' for none)."""
    if not url:
        return ''
    if url.startswith('file://'):
        return url[len('file://'):]
    if url.startswith('package://'):
        package, _, rest = url[len('package://'):].partition('/')
        if find_package is None:
            import rospkg
            find_package = rospkg.RosPack().get_path
        try:
            return os.path.join(find_package(package), rest)
        except Exception as e:  # rospkg.ResourceNotFound
            raise CalibrationError("camera_info_url %s: no package '%s' (%s)" % (url, package, e)) from None
    raise CalibrationError("camera_info_url %s: expected a file:// or package:// URL" % url)


def _matrix(data, name, rows, cols, path):
    try:
        values = [float(v) for v in data[name]['data']]
    except (KeyError, TypeError, ValueError):
        raise CalibrationError("%s: %s: expected {rows: %d, cols: %d, data: [...]}" % (path, name, rows, cols)) from None
    if len(values) != rows * cols:
        raise CalibrationError('%s: %s: expected %d values, got %d' % (path, name, rows * cols, len(values)))
    return values


def load_camera_info(path):
    """CameraInfo (without header) from a calibration YAML file."""
    try:
        with open(path) as f:
            data = yaml.safe_load(f)
    except (OSError, yaml.YAMLError) as e:
        raise CalibrationError('%s: cannot read the calibration: %s' % (path, e)) from None
    if not isinstance(data, dict):
        raise CalibrationError('%s: expected a calibration mapping' % path)
    info = CameraInfo()
    try:
        info.width, info.height = int(data['image_width']), int(data['image_height'])
    except (KeyError, TypeError, ValueError):
        raise CalibrationError('%s: image_width, image_height: expected whole numbers' % path) from None
    info.K = _matrix(data, 'camera_matrix', 3, 3, path)
    info.distortion_model = str(data.get('distortion_model', 'plumb_bob'))
    try:
        info.D = [float(v) for v in data['distortion_coefficients']['data']]
    except (KeyError, TypeError, ValueError):
        raise CalibrationError('%s: distortion_coefficients: expected {rows, cols, data: [...]}' % path) from None
    info.R = _matrix(data, 'rectification_matrix', 3, 3, path)
    info.P = _matrix(data, 'projection_matrix', 3, 4, path)
    return info


def uncalibrated(width, height):
    """What cv_camera publishes without a calibration: the size, all else zero."""
    info = CameraInfo()
    info.width, info.height = width, height
    return info
