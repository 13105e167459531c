"""The report "Robotic Arm: Simulation on Linux Using Gazebo and ROS" (../shared/seeds/001), typed
as it is written, in a new user's catkin workspace: the workspace and ROS's tools, a package with
a custom message, Gazebo's commands and a mesh in a test world, the arm's arm_gazebo and
arm_control packages (the report's launch files, tutorials/001_dual_arm_report/), forces on the
joints, the controllers switched and commanded, and their performance plotted.

The robot is arm_description's (the report's dual arm: xacro and STL meshes); the report's
"..." in arm_control.yaml are filled in as in arm_control's own copy, and arm.world (which the
report does not show) is arm_gazebo's. Stand-ins (docs/TUTORIALS.md): Gazebo's force panel is
/gazebo/apply_joint_effort; rqt's Plot is topic_plot. Fixes are named where they are made.
"""
import os
import re
import shutil
import urllib.request

import pytest

from ros_cli import call, echo_once, package_dir, wait_until

REPORT_FILES = os.path.join(os.path.dirname(__file__), '..', '..', 'tutorials', '001_dual_arm_report')
SERVO_MSG = 'string first_name\nstring last_name\nuint8 age\nuint32 score\n'


def joint_position(user, joint):
    return call(user, '/gazebo/get_joint_properties', '{joint_name: %s}' % joint)['position'][0]



def uncomment(text, first_line):
    """The report's "uncomment these lines": the '# '-commented block that starts at first_line."""
    lines = text.split('\n')
    start = lines.index(first_line)
    end = start
    while end < len(lines) and lines[end].startswith('#'):
        lines[end] = lines[end][2:] if lines[end].startswith('# ') else lines[end][1:]
        end += 1
    return '\n'.join(lines)


def test_the_dual_arm_report(user):
    # 2.1.2: the workspace.
    user.run('''mkdir -p ~/catkin_ws/src
                cd ~/catkin_ws/src
                catkin_init_workspace
                cd ~/catkin_ws/
                catkin_make
                source devel/setup.bash
                echo "source ~/catkin_ws/devel/setup.bash" >> ~/.bashrc''')
    assert user.run('echo $ROS_PACKAGE_PATH')[1].split(':')[0] == user.path('~/catkin_ws/src')

    # 2.1.3 - 2.1.4: ROS's tools.
    roscore = user.start('roscore')
    roscore.wait_for(r'started core service \[/rosout\]')
    assert '/rosout' in user.run('rosnode list')[1].split()
    assert 'Publications:' in user.run('rosnode info /rosout')[1]
    assert user.run('rospack find arm_control')[1].strip() == package_dir('arm_control')
    _, listing = user.run('rosls arm_control')
    assert {'config', 'launch', 'package.xml', 'CMakeLists.txt'} <= set(listing.split())

    # 2.1.5: a package, built.
    user.run('''cd ~/catkin_ws/src
                catkin_create_pkg sample_package std_msgs rospy roscpp
                cd ~/catkin_ws
                catkin_make''')
    assert set(user.run('rospack depends1 sample_package')[1].split()) == {'roscpp', 'rospy', 'std_msgs'}

    # 2.1.6: a custom message. Fixed: the report's <run_depend> is package.xml format 1's;
    # catkin_create_pkg writes format 2, where it is <exec_depend>.
    package = '~/catkin_ws/src/sample_package/'
    user.write(package + 'msg/servo.msg', SERVO_MSG)
    manifest = user.read(package + 'package.xml')
    manifest = manifest.replace('<!--   <build_depend>message_generation</build_depend> -->',
                                '<build_depend>message_generation</build_depend>')
    manifest = manifest.replace('<!--   <exec_depend>message_runtime</exec_depend> -->',
                                '<exec_depend>message_runtime</exec_depend>')
    assert '<build_depend>message_generation</build_depend>' in manifest
    user.write(package + 'package.xml', manifest)
    cmake = user.read(package + 'CMakeLists.txt')
    cmake = cmake.replace('find_package(catkin REQUIRED COMPONENTS\n  roscpp\n  rospy\n  std_msgs\n)',
                          'find_package(catkin REQUIRED COMPONENTS\n  roscpp\n  rospy\n  std_msgs\n  message_generation\n)')
    cmake = cmake.replace('#  CATKIN_DEPENDS roscpp rospy std_msgs', '  CATKIN_DEPENDS message_runtime roscpp rospy std_msgs')
    cmake = cmake.replace('#   Message1.msg\n#   Message2.msg', '#   servo.msg')
    cmake = uncomment(cmake, '# generate_messages(')
    cmake = uncomment(cmake, '# add_message_files(')
    assert 'message_generation\n)' in cmake and '\ngenerate_messages(' in cmake and '\nadd_message_files(' in cmake
    user.write(package + 'CMakeLists.txt', cmake)
    user.run('''cd ~/catkin_ws
                catkin_make''')
    assert user.run('rosmsg show sample_package/servo')[1].split() == SERVO_MSG.split()
    roscore.interrupt()
    roscore.wait()

    # 2.2.1: Gazebo's commands: the server on a world from GAZEBO_RESOURCE_PATH, the client.
    server = user.start('gzserver worlds/empty.world')
    server.wait_for(r'bullet_sim: world .* from .*worlds/empty\.world', timeout=60)
    assert call(user, '/gazebo/get_world_properties')['model_names'] == ['ground_plane']
    client = user.start('gzclient')  # the studio: Gazebo's client in a browser, no display needed
    url = client.wait_for(r'sim_studio: open (http://127\.0\.0\.1:\d+/) in a browser', timeout=30).group(1)
    with urllib.request.urlopen(url, timeout=10) as page:
        assert page.status == 200 and b'<title>sim_studio</title>' in page.read()
    client.interrupt()
    client.wait(timeout=30)
    server.interrupt()
    server.wait(timeout=30)

    # 2.2.5: "To test the mesh": a test world with the arm's mesh, opened with gazebo.
    mesh = os.path.join(package_dir('arm_description'), 'meshes', 'shoulder.stl')
    with open(os.path.join(REPORT_FILES, 'test.world')) as f:
        user.write('~/test.world', f.read().replace('[mesh_path]', mesh))
    gazebo = user.start('gazebo test.world')
    gazebo.wait_for(r'bullet_sim: world .* from test\.world with 2 models', timeout=60)  # ground, mesh
    assert 'my_mesh' in call(user, '/gazebo/get_world_properties')['model_names']
    gazebo.interrupt()
    gazebo.wait(timeout=30)

    # 2.2.6 and 2.3.4: arm_gazebo and arm_control. "catkin_create_pkg MYROBOT_control ros_control
    # ros_controllers", MYROBOT being the robot (arm); arm_gazebo's own creation the report leaves implied.
    user.run('''cd ~/catkin_ws/src
                catkin_create_pkg arm_gazebo
                catkin_create_pkg arm_control ros_control ros_controllers
                cd arm_control
                mkdir config''')
    os.makedirs(user.path('~/catkin_ws/src/arm_gazebo/worlds'))
    shutil.copy(os.path.join(package_dir('arm_gazebo'), 'worlds', 'arm.world'), user.path('~/catkin_ws/src/arm_gazebo/worlds'))
    shutil.copy(os.path.join(package_dir('arm_control'), 'config', 'arm_control.yaml'),
                user.path('~/catkin_ws/src/arm_control/config'))
    for relative in ('arm_gazebo/launch/arm_world.launch', 'arm_control/launch/arm_control.launch'):
        with open(os.path.join(REPORT_FILES, relative)) as f:
            user.write('~/catkin_ws/src/' + relative, f.read())
    _, out = user.run('''cd ~/catkin_ws
                         catkin_make''')
    assert "+++ processing catkin package: 'arm_control'" in out
    # The user's packages shadow this workspace's of the same names (roslaunch lists the files it reads).
    files = user.run('roslaunch --files arm_gazebo arm_world.launch')[1].split()
    assert user.path('~/catkin_ws/src/arm_gazebo/launch/arm_world.launch') in files
    assert os.path.join(package_dir('arm_gazebo'), 'launch', 'arm_world.launch') not in files

    # 2.3.5: the world and the arm, then (2.2.7) forces on a joint, then the controllers.
    world = user.start('roslaunch arm_gazebo arm_world.launch')
    world.wait_for(r'Spawn status: SpawnModel: Successfully spawned entity', timeout=90)
    # The force panel holds a torque on the joint while it is set: 5 N m lifts the arm (joint1_1 carries
    # arm, elbow and forearm, at most 7.3 N m of gravity held out straight, arm_control.yaml) until
    # gravity balances it, at asin(5 / 7.3) = 0.75 rad; cleared, the arm hangs down again.
    call(user, '/gazebo/apply_joint_effort', '{joint_name: joint1_1, effort: 5.0, duration: {secs: -1}}')
    lifted = wait_until(lambda: (joint_position(user, 'joint1_1'), joint_position(user, 'joint1_1')),
                        lambda two: abs(two[0] - two[1]) < 0.005 and abs(two[1]) > 0.3, 30, 'the arm lifted and still')[1]
    assert 0.70 < abs(lifted) < 0.82
    call(user, '/gazebo/clear_joint_forces', '{joint_name: joint1_1}')
    wait_until(lambda: joint_position(user, 'joint1_1'), lambda q: abs(q) < 0.05, 30, 'the arm hanging down again')

    control = user.start('roslaunch arm_control arm_control.launch')
    names = 'joint1_1_controller, joint1_2_controller, joint2_1_controller, joint2_2_controller, joint3_1_controller'
    control.wait_for(r'Started controllers: ' + re.escape(names), timeout=60)
    services = user.run('rosservice list')[1].split()
    assert '/arm/controller_manager/switch_controller' in services

    # Fixed: the report calls /arm_control/controller_manager/... and /arm_control/joint1_1_controller/...,
    # but its controllers live in /arm (the plugin's robotNamespace and the spawner's ns).
    stopped = call(user, '/arm/controller_manager/switch_controller',
                   "{start_controllers: [], stop_controllers: ['joint1_1_controller'], strictness: 2}")
    assert stopped['ok'] is True
    listed = call(user, '/arm/controller_manager/list_controllers')['controller']
    assert {c['name']: c['state'] for c in listed}['joint1_1_controller'] == 'stopped'
    started = call(user, '/arm/controller_manager/switch_controller',
                   "{start_controllers: ['joint1_1_controller'], stop_controllers: [], strictness: 2}")
    assert started['ok'] is True

    user.run('rostopic pub -1 /arm/joint1_1_controller/command std_msgs/Float64 "data: 1.57"')
    held = wait_until(lambda: echo_once(user, '/arm/joint1_1_controller/state'),
                      lambda s: abs(s['process_value'] - 1.57) < 0.03, 20, 'joint1_1 at 1.57 rad')
    assert held['set_point'] == pytest.approx(1.57) and abs(held['error']) < 0.03

    # 2.3.7: the controller's performance, plotted (rqt's Plot; topic_plot here).
    user.run('rosrun topic_plot topic_plot /arm/joint1_1_controller/state/process_value '
             '/arm/joint1_1_controller/state/error --duration 2 --output ~/joint1_1.png --csv ~/joint1_1.csv',
             timeout=60)
    assert os.path.getsize(user.path('~/joint1_1.png')) > 1000
    samples = {}  # field -> values, from topic_plot's rows "field,time,value"
    for field, _, value in (row.split(',') for row in user.read('~/joint1_1.csv').strip().split('\n')[1:]):
        samples.setdefault(field, []).append(float(value))
    position, error = samples['/arm/joint1_1_controller/state/process_value'], samples['/arm/joint1_1_controller/state/error']
    assert len(position) > 50 and len(error) > 50  # 2 s of the controller's state
    assert all(abs(q - 1.57) < 0.03 for q in position) and all(abs(e) < 0.03 for e in error)
