"""The RE510 "Gazebo" lecture (../shared/seeds/004), typed as it is written, in a new user's
catkin workspace: a package `tutorial` with the lecture's model.xacro (two links, a continuous
joint, a transmission, gazebo_ros_control, the 32-beam vertical lidar), spawn.launch,
function.launch and param.yaml; Gazebo started both ways and stopped with killall; the position
controller commanded with `rostopic pub`; then the vehicle built in Gazebo's model editor.

Where the lecture's text would fail on real ROS too, the fix is named where it is made. The model's
link sizes, which the lecture shows only as pictures, are simple_model_description's (the lecture's
model.xacro written out in full); the GUI steps' stand-ins are named too (docs/TUTORIALS.md).
"""
import math
import os
import re
import shutil

import pytest

from ros_cli import call, echo_once, model_pose, package_dir, poll, rate, simulator_running, wait_for_service, wait_until

# "Create a launch file (spawn.launch)". Fixed: the lecture opens the xacro path with ' and closes
# it with " (xacro would be handed a path with a quote in it); the placeholders are filled in.
SPAWN_LAUNCH = '''<launch>
  <param name="robot_description" command="$(find xacro)/xacro --inorder '$(find tutorial)/model/model.xacro'" />
  <node name="urdf_spawner" pkg="gazebo_ros" type="spawn_model" respawn="false" output="screen" args="-urdf -model simple_model -param robot_description"/>
</launch>
'''

# "Create param.yaml file". Fixed: `type:joint_state_controller/...`, `joint:joint_1` and
# `pid:{...}` lack the space YAML needs after a key's colon (each is one string, and the file does
# not parse).
PARAM_YAML = '''simple_model:
  # Publish all joint states -----
  joint_state_controller:
    type: joint_state_controller/JointStateController
    publish_rate: 50

  # Position Controllers -----
  joint1_position_controller:
    type: effort_controllers/JointPositionController
    joint: joint_1
    pid: {p: 100.0, i: 0.01, d: 10.0}
'''

# "Create a launch file to start ROS Control (function.launch)": the lecture's four pieces in one
# file (the robot_state_publisher node holds the remap; the slide leaves the element open).
FUNCTION_LAUNCH = '''<launch>
  <rosparam file="$(find tutorial)/config/param.yaml" command="load"/>
  <node name="controller_spawner" pkg="controller_manager" type="spawner" respawn="false" output="screen"
    ns="/simple_model" args="joint1_position_controller joint_state_controller"/>
  <node name="robot_state_publisher" pkg="robot_state_publisher" type="robot_state_publisher" respawn="false"
    output="screen">
    <remap from="/joint_states" to="/simple_model/joint_states" />
  </node>
</launch>
'''



def joint_position(user):
    return echo_once(user, '/simple_model/joint_states')['position'][0]


def test_the_re510_lecture(user):
    # A catkin workspace, as ROS's own tutorials make it before the lecture starts.
    user.run('''mkdir -p ~/catkin_ws/src
                cd ~/catkin_ws
                catkin_make
                echo "source ~/catkin_ws/devel/setup.bash" >> ~/.bashrc''')

    # Build a simple machine by URDF: the package and its folders.
    user.run('''cd ~/catkin_ws/src
                catkin_create_pkg tutorial controller_manager joint_state_controller robot_state_publisher
                cd tutorial
                mkdir config
                mkdir launch''')
    # The lecture's model.xacro, in the package's model/ folder (its "Package structure" slide).
    model = package_dir('simple_model_description')
    os.makedirs(user.path('~/catkin_ws/src/tutorial/model'))
    shutil.copy(os.path.join(model, 'urdf', 'model.xacro'), user.path('~/catkin_ws/src/tutorial/model/model.xacro'))
    user.write('~/catkin_ws/src/tutorial/launch/spawn.launch', SPAWN_LAUNCH)
    # Building the new package (every catkin tutorial's next step; the lecture leaves it implied).
    _, out = user.run('''cd ~/catkin_ws
                         catkin_make''')
    assert "+++ processing catkin package: 'tutorial'" in out

    # Open Gazebo, way one: `gazebo` alone (a ROS master comes with it), then stop it as the lecture does.
    gazebo = user.start('gazebo')
    gazebo.wait_for(r'bullet_sim: world .* from .*empty\.world', timeout=60)
    assert simulator_running()
    user.run('killall -9 gazebo & killall -9 gzserver & killall -9 gzclient; wait', check=False)
    poll(lambda: not simulator_running(), 10, what='killall stops the simulator')
    gazebo.wait(timeout=15)

    # Way two, "strongly recommended": roscore, then the simulator through ROS.
    roscore = user.start('roscore')
    roscore.wait_for(r'started core service \[/rosout\]', timeout=60)
    server = user.start('rosrun gazebo_ros gazebo')
    wait_for_service(user, '/gazebo/spawn_urdf_model')

    # View it in Gazebo. Fixed: `rosrun tutorial spawn.launch` (rosrun runs executables; a launch
    # file is roslaunch's).
    spawn = user.start('roslaunch tutorial spawn.launch')
    spawn.wait_for(r'Spawn status: SpawnModel: Successfully spawned entity', timeout=60)
    world = call(user, '/gazebo/get_world_properties')
    assert 'simple_model' in world['model_names']
    properties = call(user, '/gazebo/get_model_properties', '{model_name: simple_model}')
    # Two links on a continuous joint: the arm turns on joint_1 (the post is welded to the world).
    assert properties['joint_names'] == ['joint_1']
    assert 'link_1' in properties['body_names']

    # ROS control: the controllers and the joint states.
    user.write('~/catkin_ws/src/tutorial/config/param.yaml', PARAM_YAML)
    user.write('~/catkin_ws/src/tutorial/launch/function.launch', FUNCTION_LAUNCH)
    # Fixed: `rosrun tutorial function.launch`, as above.
    function = user.start('roslaunch tutorial function.launch')
    function.wait_for(r'Loaded controllers: joint1_position_controller, joint_state_controller', timeout=60)
    function.wait_for(r'Started controllers: joint1_position_controller, joint_state_controller', timeout=30)

    states = echo_once(user, '/simple_model/joint_states')
    assert states['name'] == ['joint_1']
    assert set(states) >= {'header', 'name', 'position', 'velocity', 'effort'}
    # Topic Monitor (rqt) shows 49.85 Hz for the controller's publish_rate 50; `rostopic hz` here.
    assert 45.0 < rate(user, '/simple_model/joint_states') < 55.0
    at_rest = joint_position(user)
    assert abs(at_rest) < 0.05, 'the position controller holds the joint at 0 before any command'

    # "Give command input through the topic /command", as typed: -l latches, and the command stays on.
    command = user.start('rostopic pub -l /simple_model/joint1_position_controller/command std_msgs/Float64 "data: 1.5"')
    reached = wait_until(lambda: joint_position(user), lambda q: abs(q - 1.5) < 0.03, 30,
                         'joint_1 reaching the commanded 1.5 rad')
    assert 1.47 < reached < 1.53
    state = echo_once(user, '/simple_model/joint1_position_controller/state')
    assert state['set_point'] == pytest.approx(1.5)
    assert abs(state['error']) < 0.03
    command.interrupt()

    # Add sensors: the lidar publishes its 32 beams on the plugin's topic, in the plugin's frame.
    scan = echo_once(user, '/simple_lidar/scan')
    assert len(scan['ranges']) == 32
    assert scan['header']['frame_id'] == 'lidar_link'
    assert scan['angle_min'] == pytest.approx(-0.53529248, abs=1e-6)
    assert scan['angle_max'] == pytest.approx(0.18622663, abs=1e-6)
    assert scan['range_min'] == pytest.approx(0.05) and scan['range_max'] == pytest.approx(70.0)
    assert 25.0 < rate(user, '/simple_lidar/scan') < 35.0  # update_rate 30

    # Build a simple machine by Gazebo GUI. Stand-in for the model editor: the vehicle as it saves
    # it to ~/model_editor_models/my_vehicle, with the lecture's edits to model.sdf (the chassis
    # mesh, the skid-steer plugin, the lidar). Inserting it (the Insert tab) is spawn_model here.
    vehicle = package_dir('simple_vehicle_description')
    shutil.copytree(os.path.join(vehicle, 'models', 'my_vehicle'), user.path('~/model_editor_models/my_vehicle'))
    user.run('rosrun gazebo_ros spawn_model -sdf -file ~/model_editor_models/my_vehicle/model.sdf '
             '-model my_vehicle -x 5 -y 0')
    vehicle_scan = echo_once(user, '/my_vehicle/laser/scan')
    assert len(vehicle_scan['ranges']) == 32 and vehicle_scan['header']['frame_id'] == 'lidar_link'
    # The lidar looks down and ahead: its lowest beams meet the ground a little over a metre away.
    nearest = min(r for r in vehicle_scan['ranges'] if isinstance(r, float) and math.isfinite(r))
    assert 1.0 < nearest < 2.0
    start = model_pose(user, 'my_vehicle')
    drive = user.start("rostopic pub -r 10 /cmd_vel geometry_msgs/Twist '{linear: {x: 0.5}}'")
    moved = wait_until(lambda: model_pose(user, 'my_vehicle'), lambda p: p[0] - start[0] > 0.5, 30,
                       'the vehicle driving forward on /cmd_vel')
    drive.interrupt()
    assert abs(moved[1] - start[1]) < 0.2, 'it drove straight'

    # "Terminate Gazebo", as the lecture does.
    user.run('killall -9 gazebo & killall -9 gzserver & killall -9 gzclient; wait', check=False)
    poll(lambda: not simulator_running(), 10, what='killall stops the simulator')
    assert server.wait(timeout=15) != 0
    assert re.search(r'Spawn status', spawn.output)
