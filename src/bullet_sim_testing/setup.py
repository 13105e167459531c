from catkin_pkg.python_setup import generate_distutils_setup
from setuptools import setup

# bullet_sim_testing: helpers the robots' rostests share (wall geometry ground truth, driving).
setup(**generate_distutils_setup(packages=['bullet_sim_testing'], package_dir={'': 'src'}))
