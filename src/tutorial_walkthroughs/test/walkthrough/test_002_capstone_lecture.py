"""The ME401/ME491 Capstone lectures (../shared/seeds/002), typed as they are written, in a new
user's home: the workspace and the ros_tutorials_topic publisher / subscriber pair; the maze from
the building editor; the capstone_simulation workspace with the lecture's own m_robot_description
and m_robot_gazebo (its files, tutorials/002_capstone_lecture/), m_robot spawned as the lecture
spawns it (without -z: its wheels start 0.1 m inside the ground), teleop, hector mapping, and the
frontier exploration of the maze.

Stand-ins (docs/TUTORIALS.md): the building editor's Capstone_Map is m_robot_gazebo's copy of it,
put where the editor saves it; `git clone` of hector_slam and of the lecture's me491_ros are this
workspace's hector_mapping and find_frontier; Gazebo's Topic Visualization is rostopic; rqt_graph
is `rostopic info`; rviz runs on a virtual display. Fixes to the lecture's text are named where
they are made.
"""
import math
import os
import re
import shutil

import pytest

from ros_cli import call, echo_once, model_pose, package_dir, poll, rate, wait_until

LECTURE_FILES = os.path.join(os.path.dirname(__file__), '..', '..', 'tutorials', '002_capstone_lecture')
REST_HEIGHT = 0.1  # base_frame above the ground when the wheels (r 0.05, 0.05 below it) stand on it
SCREEN = True  # the lecture opens rviz


def lecture_file(relative):
    with open(os.path.join(LECTURE_FILES, relative)) as f:
        return f.read()


def sim_time(user):
    return call(user, '/gazebo/get_world_properties')['sim_time']


def test_1_nodes_and_topics(user):
    # "Let's start with making workspace". Fixed: the slide's `mkdir catkin_make`, `cd catkin_make`
    # and `catkin_make init` (no such command) are the workspace its notes and the next line name,
    # catkin_ws, made with catkin_make.
    user.run('''cd
                mkdir catkin_ws
                cd catkin_ws
                mkdir src
                catkin_make
                echo "source ~/catkin_ws/devel/setup.bash" >> ~/.bashrc
                source ~/.bashrc''')
    _, listing = user.run('''cd src
                             catkin_create_pkg ros_tutorials_topic message_generation std_msgs roscpp
                             cd ros_tutorials_topic
                             ls''')
    assert listing.split()[-4:] == ['CMakeLists.txt', 'include', 'package.xml', 'src']
    for relative in ('package.xml', 'CMakeLists.txt', 'msg/MsgTutorial.msg', 'src/topic_publisher.cpp',
                     'src/topic_subscriber.cpp'):
        user.write('~/catkin_ws/src/ros_tutorials_topic/' + relative, lecture_file('ros_tutorials_topic/' + relative))
    _, out = user.run('''cd ~/catkin_ws
                         catkin_make''')
    assert 'Built target topic_subscriber' in out and 'Built target topic_publisher' in out

    roscore = user.start('roscore')
    roscore.wait_for(r'started core service \[/rosout\]')
    publisher = user.start('rosrun ros_tutorials_topic topic_publisher')
    subscriber = user.start('rosrun ros_tutorials_topic topic_subscriber')
    subscriber.wait_for(r'recievemsg= \d+\n(?:.*\n)*?.*recievemsg= \d+\n(?:.*\n)*?.*recievemsg= (\d+)', timeout=30)
    counts = [int(c) for c in re.findall(r'recievemsg= (\d+)', subscriber.output)[2::3]]
    assert counts == sorted(counts) and len(counts) >= 1
    assert 9.0 < rate(user, '/ros_tutorial_msg') < 11.0  # ros::Rate loop_rate(10)
    # rqt_graph's picture of the two nodes, as rostopic tells it.
    _, info = user.run('rostopic info /ros_tutorial_msg')
    assert 'Type: ros_tutorials_topic/MsgTutorial' in info
    assert re.search(r'Publishers:\s*\n \* /topic_publisher ', info)
    assert re.search(r'Subscribers:\s*\n \* /topic_subscriber ', info)
    publisher.interrupt()
    subscriber.interrupt()
    publisher.wait()
    subscriber.wait()
    roscore.interrupt()
    roscore.wait()


def test_2_the_robot_in_its_world(user):
    # "Making a structure": Gazebo, then its building editor, which saves Capstone_Map in
    # ~/building_editor_models (stand-in: m_robot_gazebo's copy of the lecture's maze).
    roscore = user.start('roscore')
    roscore.wait_for(r'started core service \[/rosout\]')
    gazebo = user.start('rosrun gazebo_ros gazebo')
    gazebo.wait_for(r'bullet_sim: world', timeout=60)
    gazebo.interrupt()
    gazebo.wait(timeout=30)
    shutil.copytree(os.path.join(package_dir('m_robot_gazebo'), 'models', 'Capstone_Map'),
                    user.path('~/building_editor_models/Capstone_Map'))
    _, models = user.run('''cd ~/building_editor_models
                            cp -r Capstone_Map ~/.gazebo/models
                            cd ~/.gazebo/models
                            ls''')
    assert models.split() == ['Capstone_Map']

    user.run('''cd
                mkdir capstone_simulation
                cd capstone_simulation
                mkdir src
                cd src
                mkdir m_robot_ws''')
    user.run('''cd m_robot_ws
                catkin_create_pkg m_robot_description
                catkin_create_pkg m_robot_gazebo''')
    _, listing = user.run('''cd ~/capstone_simulation
                             catkin_make
                             ls''')
    assert listing.split()[-3:] == ['build', 'devel', 'src']
    user.run('''echo "source ~/capstone_simulation/devel/setup.bash" >> ~/.bashrc''')

    # The robot. Fixed: the slides make urdf/ and then open m_robot.xacro (and later m_robot.gazebo)
    # in the package folder, but m_robot_world.launch reads urdf/m_robot.xacro: they go in urdf/.
    user.run('''cd src/m_robot_ws/m_robot_description
                mkdir urdf''')
    for name in ('m_robot.xacro', 'm_robot.gazebo'):
        user.write('~/capstone_simulation/src/m_robot_ws/m_robot_description/urdf/' + name,
                   lecture_file('m_robot_description/urdf/' + name))
    user.run('''cd ~/capstone_simulation/src/m_robot_ws/m_robot_gazebo
                mkdir launch worlds''')
    gazebo_package = '~/capstone_simulation/src/m_robot_ws/m_robot_gazebo/'
    user.write(gazebo_package + 'worlds/m_robot.world', lecture_file('m_robot_gazebo/worlds/m_robot.world'))
    user.write(gazebo_package + 'launch/m_robot_world.launch', lecture_file('m_robot_gazebo/launch/m_robot_world.launch'))
    user.run('''cd ~/capstone_simulation
                catkin_make''')
    assert user.run('rospack find m_robot_gazebo')[1].strip() == user.path(gazebo_package[:-1])

    # roscore runs since the building editor's step.
    world = user.start('roslaunch m_robot_gazebo m_robot_world.launch')
    world.wait_for(r'Spawn status: SpawnModel: Successfully spawned entity', timeout=90)
    # Spawned without -z, its wheels start 0.1 m inside the ground; the contacts push it out, slowly
    # (Gazebo's max_vel, 0.01 m/s), and it stands on its wheels, level.
    spawned = sim_time(user)
    heights = []
    wait_until(lambda: heights.append(model_pose(user, 'm_robot')[2]) or heights[-1],
               lambda z: abs(z - REST_HEIGHT) < 0.003, 30, 'm_robot standing on its wheels')
    assert sim_time(user) - spawned < 15.0, 'on its wheels within 15 s of sim time'
    assert max(heights) < REST_HEIGHT + 0.05, 'it was not thrown up: %s' % heights
    x, y, z, yaw = model_pose(user, 'm_robot')
    assert abs(x) < 0.02 and abs(y) < 0.02 and abs(yaw) < 0.02
    world.interrupt()
    world.wait(timeout=60)

    # "Now, let's insert the map": the world with Capstone_Map (found in ~/.gazebo/models).
    user.write(gazebo_package + 'worlds/m_robot.world', lecture_file('m_robot_gazebo/worlds/m_robot_with_map.world'))
    user.run('''cd ~/capstone_simulation
                catkin_make''')
    world = user.start('roslaunch m_robot_gazebo m_robot_world.launch')
    world.wait_for(r'Spawn status: SpawnModel: Successfully spawned entity', timeout=90)
    wait_until(lambda: model_pose(user, 'm_robot'), lambda p: abs(p[2] - REST_HEIGHT) < 0.003, 30,
               'm_robot on its wheels in the maze')

    # "Check the controllers": teleop_twist_keyboard, driving backwards (','), out of the corner the
    # lecture's start pose puts it in, then any other key stops it.
    teleop = user.start('rosrun teleop_twist_keyboard teleop_twist_keyboard')
    teleop.wait_for(r'Moving around', timeout=30)
    start = model_pose(user, 'm_robot')
    teleop.send(',')
    moved = wait_until(lambda: model_pose(user, 'm_robot'), lambda p: start[0] - p[0] > 0.2, 20,
                       'm_robot driving 0.2 m backwards')
    teleop.send('k')
    assert abs(moved[1] - start[1]) < 0.05 and abs(moved[3] - start[3]) < 0.1, 'it drove straight back'
    stopped = wait_until(lambda: (model_pose(user, 'm_robot'), model_pose(user, 'm_robot')),
                         lambda two: abs(two[0][0] - two[1][0]) < 0.002, 10, 'm_robot stopping')[1]
    assert 0.2 < start[0] - stopped[0] < 0.6
    teleop.interrupt()

    # "Check the sensors": Gazebo's Topic Visualization (stand-in: rostopic), then rostopic list -v.
    scan = echo_once(user, '/m_robot/laser/scan')
    assert len(scan['ranges']) == 359 and scan['header']['frame_id'] == 'laser_frame'
    walls = [r for r in scan['ranges'] if isinstance(r, float) and math.isfinite(r)]
    assert len(walls) > 300 and 0.15 < min(walls) < 1.0  # the maze all round, its nearest wall close by
    image = echo_once(user, '/m_robot/camera1/image_raw/width')
    assert image == 800
    _, topics = user.run('rostopic list -v')
    for topic in ('/m_robot/laser/scan', '/m_robot/camera1/image_raw', '/cmd_vel', '/tf'):
        assert topic in topics


def test_3_hector_slam(user):
    # "Now let's run it!". Fixed: `rosrun ... .launch` (a launch file is roslaunch's). The world is
    # still running from the last step; hector_mapping.launch and find_frontier are the lecture's
    # me491_ros packages, which this workspace holds.
    hector = user.start('roslaunch find_frontier hector_mapping.launch')
    hector.wait_for(r'hector_mapping', timeout=60)
    pose = echo_once(user, '/slam_out_pose', timeout=60)
    assert pose['header']['frame_id'] == 'map'
    # The map, once hector has put the maze walls round the robot in it (it publishes every 2 s).
    grid = wait_until(lambda: echo_once(user, '/map'), lambda g: sum(1 for v in g['data'] if v == 100) > 200, 60,
                      "the maze walls in hector's map")
    assert grid['info']['resolution'] == pytest.approx(0.05) and grid['info']['width'] == 200
    rviz = user.start('rosrun rviz rviz')
    poll(lambda: '/rviz' in user.run('rosnode list')[1], 60, what='rviz running')
    # find_frontier on its own sends its first goal to move_base_simple/goal.
    frontier = user.start('rosrun find_frontier find_frontier')
    goal = echo_once(user, '/move_base_simple/goal', timeout=60)
    assert goal['header']['frame_id'] == 'map'
    for terminal in (frontier, rviz, hector):
        terminal.interrupt()
        terminal.wait(timeout=60)


def test_4_frontier_exploration(user):
    # "Run example": the world, then nav_run.launch (hector mapping, move_base, find_frontier).
    user.speed_up(5)
    nav = user.start('roslaunch find_frontier nav_run.launch')
    nav.wait_for(r'find_frontier', timeout=60)
    status = user.start('rostopic echo /find_frontier/status')
    status.wait_for(r'data: "complete: ', timeout=300)
    grid = echo_once(user, '/map')
    free = sum(1 for v in grid['data'] if v == 0)
    # The maze's inside is about 2.8 x 4.8 m (5400 cells of 5 cm); the map holds most of it.
    assert 4000 < free < 6500
