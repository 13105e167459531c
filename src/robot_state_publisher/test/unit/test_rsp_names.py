"""The package's two executables, robot_state_publisher and its pre-Noetic name state_publisher: after
`catkin build` both are in devel/lib/robot_state_publisher/ and are what rosrun/roslaunch find (one
match each). That they publish what they should is robot_state_publisher.test's job, and that a
lecture-style launch file with the old name runs is legacy_names.test's (simple_model_gazebo)."""
import os
import stat

import pytest

PACKAGE = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
ROOT = os.path.dirname(os.path.dirname(PACKAGE))
NAMES = ['robot_state_publisher', 'state_publisher']


@pytest.mark.parametrize('name', NAMES)
def test_built_into_devel_lib_and_executable(name):
    path = os.path.join(ROOT, 'devel', 'lib', 'robot_state_publisher', name)
    assert os.path.isfile(path), '%s is missing: run catkin build robot_state_publisher' % path
    assert os.stat(path).st_mode & stat.S_IXUSR and os.access(path, os.X_OK)


@pytest.mark.parametrize('name', NAMES)
def test_the_one_executable_roslaunch_finds(name):
    # roslaunch's lookup (rosrun's is the same search): exactly one match, ours, not Debian's.
    import roslib.packages
    matches = roslib.packages.find_node('robot_state_publisher', name)
    assert matches == [os.path.join(ROOT, 'devel', 'lib', 'robot_state_publisher', name)]


def test_no_source_file_has_a_node_name():
    # A same-named executable in the source tree would be a second match (rosrun then asks which).
    for folder, _, files in os.walk(PACKAGE):
        assert not set(files) & set(NAMES), folder
