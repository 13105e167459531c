# Installs the sim_batch Python package (src/sim_batch) for catkin; do not run it directly.
from setuptools import setup
from catkin_pkg.python_setup import generate_distutils_setup

setup(**generate_distutils_setup(packages=["sim_batch"], package_dir={"": "src"}))
