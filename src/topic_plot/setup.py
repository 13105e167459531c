# Installs the topic_plot Python package (src/topic_plot) for catkin; do not run it directly.
from setuptools import setup
from catkin_pkg.python_setup import generate_distutils_setup

setup(**generate_distutils_setup(packages=["topic_plot"], package_dir={"": "src"}))
