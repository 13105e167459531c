"""README's "Building, and your own workspace", typed as written: a user's workspace overlaying
this one, built with catkin_make and with catkin build, from a package that lists the tutorials'
names (ros_control, ros_controllers, joint_state_controller, gazebo_ros, ...) in catkin_create_pkg
and so in find_package(catkin REQUIRED COMPONENTS ...); and Gazebo's commands on PATH."""
import os

import pytest

from user_session import WORKSPACE, UserSession

NAMES = ('controller_manager joint_state_controller effort_controllers position_controllers velocity_controllers '
         'joint_trajectory_controller diff_drive_controller hardware_interface controller_interface '
         'transmission_interface ros_control ros_controllers gazebo_ros gazebo_plugins gazebo_ros_control '
         'robot_state_publisher xacro')


@pytest.fixture
def user(tmp_path):
    session = UserSession(tmp_path, 'readme')
    yield session
    session.close()


@pytest.mark.parametrize('tool', ['catkin_make', 'catkin build'])
def test_a_users_workspace_overlays_this_one(user, tool):
    init = 'catkin init' if tool == 'catkin build' else 'true'
    _, out = user.run('''mkdir -p ~/catkin_ws/src
                         cd ~/catkin_ws
                         %s
                         cd src
                         catkin_create_pkg my_robot_control %s
                         cd ..
                         %s''' % (init, NAMES, tool), timeout=600)
    cmake = user.read('~/catkin_ws/src/my_robot_control/CMakeLists.txt')
    assert 'ros_controllers' in cmake and 'gazebo_ros_control' in cmake  # find_package lists them all
    assert os.path.isfile(user.path('~/catkin_ws/devel/share/my_robot_control/cmake/my_robot_controlConfig.cmake'))
    # The overlay: the user's package first, this workspace's below it.
    _, path = user.run('''source ~/catkin_ws/devel/setup.bash
                          echo $ROS_PACKAGE_PATH''')
    folders = path.strip().split(':')
    assert folders[0].startswith(user.path('~/catkin_ws/src')) and os.path.join(WORKSPACE, 'src') in folders
    # Gazebo's three commands, from catkin's global bin.
    _, where = user.run('''source ~/catkin_ws/devel/setup.bash
                           command -v gazebo gzserver gzclient''')
    assert where.split() == [os.path.join(WORKSPACE, 'devel', 'bin', name) for name in ('gazebo', 'gzserver', 'gzclient')]
