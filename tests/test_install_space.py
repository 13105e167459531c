"""The workspace from its install space, as a robot or a Docker image runs it: `catkin_make
install`, then, in an environment made only by install/setup.bash (the devel space and the source
folders taken off every path, as on a machine that has only install/), m_robot's world with the
mapper and move_base (`roslaunch find_frontier m_robot_navigation.launch`) comes up from install/
and drives the robot to a goal across the maze."""
import json
import os
import signal
import socket
import subprocess
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
INSTALL = os.path.join(ROOT, 'install')
NOT_INSTALLED = (os.path.join(ROOT, 'devel'), os.path.join(ROOT, 'src'), os.path.join(ROOT, 'build'))
PATH_LISTS = ('PATH', 'PYTHONPATH', 'LD_LIBRARY_PATH', 'PKG_CONFIG_PATH', 'CMAKE_PREFIX_PATH', 'ROS_PACKAGE_PATH')

# The client, run with the install space's Python path: a goal up the maze's east side (as in
# find_frontier's m_robot_navigation.test), then where the simulator says the robot is.
CLIENT = r'''
import json, math
import actionlib, rospy
from gazebo_msgs.srv import GetModelState
from geometry_msgs.msg import Quaternion
from move_base_msgs.msg import MoveBaseAction, MoveBaseGoal
from bullet_sim_testing.gazebo import set_real_time_factor
rospy.init_node('install_space_client')
rospy.wait_for_service('/gazebo/get_model_state', timeout=120)
set_real_time_factor(2.0)
client = actionlib.SimpleActionClient('move_base', MoveBaseAction)
assert client.wait_for_server(rospy.Duration(120)), 'no move_base action server'
goal = MoveBaseGoal()
goal.target_pose.header.frame_id = 'map'
goal.target_pose.header.stamp = rospy.Time.now()
goal.target_pose.pose.position.x, goal.target_pose.pose.position.y = -0.1, 3.0
goal.target_pose.pose.orientation = Quaternion(0, 0, math.sin(math.pi / 4), math.cos(math.pi / 4))
client.send_goal_and_wait(goal, rospy.Duration(150))
state = rospy.ServiceProxy('/gazebo/get_model_state', GetModelState)('m_robot', 'world')
print('RESULT ' + json.dumps({'state': client.get_state(), 'x': state.pose.position.x, 'y': state.pose.position.y}))
'''


def install_environment():
    """os.environ as install/setup.bash alone makes it: started from a bare PATH (the venv
    scripts/setup makes stays on it, as a user's would), every entry under devel/, src/ or build/
    removed from the path lists (install/setup.bash chains to the devel space it was built beside)."""
    bare = {'HOME': os.environ['HOME'], 'ROS_PYTHON_VERSION': '3', 'LANG': 'C.UTF-8',
            'PATH': os.path.join(ROOT, '.venv', 'bin') + ':/usr/bin:/bin'}
    dump = subprocess.run(['bash', '-c', '. "%s/setup.bash" && env -0' % INSTALL], env=bare, check=True,
                          capture_output=True).stdout.decode()
    env = dict(line.split('=', 1) for line in dump.split('\0') if '=' in line)
    for name in PATH_LISTS:
        if name in env:
            env[name] = ':'.join(p for p in env[name].split(':') if p and not p.startswith(NOT_INSTALLED))
    return env


def free_port():
    with socket.socket() as s:
        s.bind(('127.0.0.1', 0))
        return s.getsockname()[1]


def test_the_navigation_stack_runs_from_the_install_space():
    subprocess.run(['catkin_make', '-j2', 'install'], cwd=ROOT, check=True, stdout=subprocess.DEVNULL,
                   stderr=subprocess.PIPE, timeout=900)
    env = install_environment()
    assert not any(p.startswith(NOT_INSTALLED) for name in PATH_LISTS for p in env.get(name, '').split(':'))
    for package in ('bullet_sim', 'move_base', 'find_frontier', 'm_robot_gazebo', 'hector_style_mapping'):
        found = subprocess.run(['rospack', 'find', package], env=env, capture_output=True, text=True).stdout.strip()
        assert found == os.path.join(INSTALL, 'share', package)

    port = free_port()
    env.update(ROS_MASTER_URI='http://127.0.0.1:%d' % port, ROS_HOME=tempfile.mkdtemp(prefix='install_space_'))
    launch = subprocess.Popen(['roslaunch', '-p', str(port), 'find_frontier', 'm_robot_navigation.launch'], env=env,
                              stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, start_new_session=True)
    client = subprocess.Popen(['/usr/bin/python3', '-c', CLIENT], env=env, stdout=subprocess.PIPE,
                              stderr=subprocess.STDOUT, text=True)
    try:
        deadline = time.time() + 400
        while client.poll() is None and launch.poll() is None and time.time() < deadline:
            time.sleep(1)  # a launch that fails (a file not installed) ends the test at once
        programs = subprocess.run(['ps', '-o', 'args=', '--ppid', str(launch.pid)], capture_output=True,
                                  text=True).stdout
    finally:
        if client.poll() is None:
            client.kill()
        client_output = client.communicate()[0]
        os.killpg(launch.pid, signal.SIGINT)
        try:
            log = launch.communicate(timeout=60)[0]
        except subprocess.TimeoutExpired:
            os.killpg(launch.pid, signal.SIGKILL)
            log = launch.communicate()[0]
    assert client.returncode == 0, client_output + log[-3000:]

    # Every node ran from install/, none from the build's folders.
    for program in ('lib/bullet_sim/bullet_sim_node', 'lib/move_base/move_base', 'lib/hector_style_mapping/hector_mapping',
                    'lib/joint_state_publisher/joint_state_publisher'):
        assert os.path.join(INSTALL, program) in programs, programs
    assert not any(folder in programs for folder in NOT_INSTALLED), programs

    result = json.loads(client_output.split('RESULT ', 1)[1])
    assert result['state'] == 3, result  # actionlib's SUCCEEDED
    # Within the local planner's xy_goal_tolerance (0.15 m) plus the mapper's error (0.06 m).
    assert abs(result['x'] - -0.1) < 0.21 and abs(result['y'] - 3.0) < 0.21, result
