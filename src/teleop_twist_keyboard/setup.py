# Installs the teleop_keyboard Python package (src/teleop_keyboard) for catkin; do not run it directly.
from setuptools import setup
from catkin_pkg.python_setup import generate_distutils_setup

setup(**generate_distutils_setup(packages=["teleop_keyboard"], package_dir={"": "src"}))
