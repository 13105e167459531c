# Installs the map_files Python package (src/map_files) for catkin; do not run it directly.
from setuptools import setup
from catkin_pkg.python_setup import generate_distutils_setup

setup(**generate_distutils_setup(packages=["map_files"], package_dir={"": "src"}))
