# Installs the katana_pick Python package (src/katana_pick) for catkin; do not run it directly.
from catkin_pkg.python_setup import generate_distutils_setup
from setuptools import setup

setup(**generate_distutils_setup(packages=['katana_pick'], package_dir={'': 'src'}))
