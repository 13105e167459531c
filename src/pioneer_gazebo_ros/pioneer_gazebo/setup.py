# The pioneer_gazebo Python module (maze_walls), installed by catkin_python_setup(); not for pip.
from catkin_pkg.python_setup import generate_distutils_setup
from setuptools import setup

setup(**generate_distutils_setup(packages=['pioneer_gazebo'], package_dir={'': 'src'}))
