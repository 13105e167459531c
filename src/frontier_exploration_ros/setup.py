# Installs the frontier_exploration_ros Python package (src/frontier_exploration_ros) for catkin; do not run it directly.
from catkin_pkg.python_setup import generate_distutils_setup
from setuptools import setup

setup(**generate_distutils_setup(packages=['frontier_exploration_ros'], package_dir={'': 'src'}))
