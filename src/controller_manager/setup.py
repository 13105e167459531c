# Installs the controller_manager_tools module for catkin_python_setup(); do not run it by hand.
from setuptools import setup

from catkin_pkg.python_setup import generate_distutils_setup

setup(**generate_distutils_setup(packages=['controller_manager_tools'], package_dir={'': 'src'}))
