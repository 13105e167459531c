"""The Katana's URDF for the tests: katana_description's top-level xacro, expanded by xacro."""
import os
import shutil
import subprocess

HERE = os.path.dirname(os.path.abspath(__file__))
XACRO_PATH = os.path.join('urdf', 'katana_450_6m90a.urdf.xacro')


def katana_description_path():
    """katana_description's folder: from ROS_PACKAGE_PATH once the workspace is sourced, else
    next to this package in the source tree."""
    try:
        import rospkg
        return rospkg.RosPack().get_path('katana_description')
    except Exception:  # rospkg missing, or the package not on ROS_PACKAGE_PATH
        return os.path.normpath(os.path.join(HERE, '..', '..', '..', 'katana_description'))


def katana_urdf(*xacro_args):
    xacro = shutil.which('xacro')
    assert xacro, 'xacro is not on PATH (source scripts/env.sh)'
    result = subprocess.run([xacro, os.path.join(katana_description_path(), XACRO_PATH)] + list(xacro_args),
                            capture_output=True, text=True, timeout=60)
    assert result.returncode == 0, result.stderr
    return result.stdout
