# Installs the pioneer_ros Python package (src/pioneer_ros) for catkin; do not run it directly.
from catkin_pkg.python_setup import generate_distutils_setup
from setuptools import setup

setup(**generate_distutils_setup(packages=['pioneer_ros'], package_dir={'': 'src'}))
