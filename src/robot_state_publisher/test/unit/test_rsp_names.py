"""The name package's two executables: after `catkin build` both are in devel/lib/robot_state_publisher/
and are what rosrun/roslaunch find (one match each); the script passes every argument to Debian's
binary (checked with a stand-in binary) and names the apt package when that binary is missing.
That they bring up a working node is legacy_names.test's job (simple_model_sim)."""
import os
import stat
import subprocess

import pytest

PACKAGE = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
ROOT = os.path.dirname(os.path.dirname(PACKAGE))
SCRIPT = os.path.join(PACKAGE, 'scripts', 'run_debian_robot_state_publisher')
DEBIAN_BINARY = '/usr/lib/robot_state_publisher/robot_state_publisher'
NAMES = ['robot_state_publisher', 'state_publisher']


@pytest.mark.parametrize('name', NAMES)
def test_built_into_devel_lib_and_executable(name):
    path = os.path.join(ROOT, 'devel', 'lib', 'robot_state_publisher', name)
    assert os.path.isfile(path), '%s is missing: run catkin build robot_state_publisher' % path
    assert os.stat(path).st_mode & stat.S_IXUSR and os.access(path, os.X_OK)
    with open(path) as built, open(SCRIPT) as source:
        assert built.read() == source.read()


@pytest.mark.parametrize('name', NAMES)
def test_the_one_executable_roslaunch_finds(name):
    # roslaunch's lookup (rosrun's is the same search): exactly one match, ours, not Debian's.
    if not os.environ.get('ROS_PACKAGE_PATH'):
        pytest.skip('needs the workspace environment (. scripts/env.sh)')
    import roslib.packages
    matches = roslib.packages.find_node('robot_state_publisher', name)
    assert matches == [os.path.join(ROOT, 'devel', 'lib', 'robot_state_publisher', name)]


def test_no_source_file_has_a_node_name():
    # A same-named executable in the source tree would be a second match (rosrun then asks which).
    for folder, _, files in os.walk(PACKAGE):
        assert not set(files) & set(NAMES), folder


def stand_in(tmp_path, name, binary):
    """A copy of the script named `name` whose Debian binary is `binary`."""
    with open(SCRIPT) as f:
        text = f.read()
    assert text.count(DEBIAN_BINARY) == 1
    path = tmp_path / name
    path.write_text(text.replace(DEBIAN_BINARY, str(binary)))
    path.chmod(0o755)
    return str(path)


ARGS = ['__name:=robot_state_publisher', '__ns:=/arm', '/joint_states:=/arm/joint_states',
        '_publish_frequency:=50.0', 'an arg with spaces', '']


@pytest.mark.parametrize('name', NAMES)
def test_every_argument_reaches_the_binary(tmp_path, name):
    fake = tmp_path / 'fake_binary'
    fake.write_text('#!/usr/bin/env bash\nprintf "%s\\n" "$#" "$@"\n')
    fake.chmod(0o755)
    done = subprocess.run([stand_in(tmp_path, name, fake)] + ARGS, capture_output=True, text=True, timeout=30)
    assert done.returncode == 0, done.stderr
    assert done.stdout.split('\n')[:-1] == [str(len(ARGS))] + ARGS
    assert ('deprecated name' in done.stderr) == (name == 'state_publisher')


@pytest.mark.parametrize('name', NAMES)
def test_missing_debian_binary_names_the_apt_package(tmp_path, name):
    done = subprocess.run([stand_in(tmp_path, name, tmp_path / 'not_installed'), '__name:=x'],
                          capture_output=True, text=True, timeout=30)
    assert done.returncode == 1
    assert 'ros-robot-state-publisher' in done.stderr
    assert done.stdout == ''


def test_debian_binary_is_installed():
    assert os.access(DEBIAN_BINARY, os.X_OK), 'apt-get install ros-robot-state-publisher (scripts/setup does)'
