"""The blog post "getting started with Gazebo and ROS" with the Katana arm (../shared/seeds/000),
typed as it is written, in a new user's catkin workspace: the workspace, ROS's introspection
tools, the Katana in the simulator (KATANA_TYPE, katana_arm.launch) with forces on its joints,
the Hokuyo on /rrbot/laser/scan, a package of one's own, and the arm finding the cans in the scan
and stacking them with the triangle IK and the grasp fix.

Stand-ins (docs/TUTORIALS.md): `apt-get install ros-kinetic-katana-*` and the katana_driver and
gazebo-pkgs checkouts are this workspace's katana_description (with the post's Hokuyo and
gazebo_grasp_fix blocks already appended), katana_arm_gazebo and the grasp plugin; Gazebo's force
panel is /gazebo/apply_joint_effort; the control program the post sketches is katana_pick's
stack_cans, which implements it.
"""
import re

import pytest

from ros_cli import call, echo_once, wait_until



def joint_position(user, joint):
    return call(user, '/gazebo/get_joint_properties', '{joint_name: %s}' % joint)['position'][0]


def test_the_katana_blog_post(user):
    user.run('''mkdir -p ~/catkin_ws/src
                cd ~/catkin_ws/
                catkin_make
                source devel/setup.bash
                echo "source ~/catkin_ws/devel/setup.bash" >> ~/.bashrc''')
    roscore = user.start('roscore')
    roscore.wait_for(r'started core service \[/rosout\]')

    # The introspection tools the post lists.
    assert user.run('rospack find katana_arm_gazebo')[1].strip().endswith('/katana_arm_gazebo')
    assert 'katana_description' in user.run('rospack list')[1]
    assert user.run('rostopic type /rosout')[1].strip() == 'rosgraph_msgs/Log'
    _, log = user.run('rostopic type rosout | rosmsg show')
    assert 'string msg' in log and 'byte level' in log
    assert 'std_msgs' in user.run('rosmsg packages')[1].split()

    # The Katana in the simulator.
    arm = user.start('''export KATANA_TYPE="katana_450_6m90a"
                        roslaunch katana_arm_gazebo katana_arm.launch''')
    arm.wait_for(r'Started controllers: .*joint_state_controller', timeout=120)
    # (The post's last reader could not load joint_state_controller; here it runs.)
    listed = call(user, '/controller_manager/list_controllers')['controller']
    states = {c['name']: c['state'] for c in listed}
    assert states['joint_state_controller'] == 'running' and states['katana_arm_controller'] == 'running'
    assert 'katana' in call(user, '/gazebo/get_world_properties')['model_names']

    # "fill in forces ... per joint": the panel holds a torque on the joint while it is set. Against the
    # arm controller's hold (P 6 N m/rad on the base joint, katana_arm_controller.yaml, up to the
    # motor's 1.5 N m; no gravity about its vertical axis), 1 N m turns the base 1/6 rad; cleared,
    # it goes back.
    before = joint_position(user, 'katana_motor1_pan_joint')
    call(user, '/gazebo/apply_joint_effort', '{joint_name: katana_motor1_pan_joint, effort: 1.0, duration: {secs: -1}}')
    turned = wait_until(lambda: (joint_position(user, 'katana_motor1_pan_joint'),
                                 joint_position(user, 'katana_motor1_pan_joint')),
                        lambda two: abs(two[0] - two[1]) < 0.005 and abs(two[1] - before) > 0.1, 30,
                        'the base joint turned and still')[1]
    assert 0.13 < turned - before < 0.2
    call(user, '/gazebo/clear_joint_forces', '{joint_name: katana_motor1_pan_joint}')
    wait_until(lambda: joint_position(user, 'katana_motor1_pan_joint'), lambda q: abs(q - before) < 0.03, 30,
               'the base joint back where its controller holds it')

    # The Hokuyo the post adds: 720 beams over 180 degrees, 0.1 to 30 m, on /rrbot/laser/scan.
    scan = echo_once(user, '/rrbot/laser/scan')
    assert len(scan['ranges']) == 720 and scan['header']['frame_id'] == 'hokuyo_link'
    assert scan['angle_min'] == pytest.approx(-1.570796, abs=1e-5) and scan['range_max'] == pytest.approx(30.0)
    cans = [r for r in scan['ranges'] if isinstance(r, float) and 0.2 < r < 0.5]
    assert len(cans) > 20, 'the three cans on the table in front of the arm'

    # A package of one's own.
    user.run('''cd ~/catkin_ws/src
                catkin_create_pkg test_package std_msgs rospy roscpp
                cd ~/catkin_ws
                catkin_make
                . ~/catkin_ws/devel/setup.bash''')
    cmake = user.read('~/catkin_ws/src/test_package/CMakeLists.txt')
    assert re.search(r'find_package\(catkin REQUIRED COMPONENTS\s+roscpp\s+rospy\s+std_msgs\s+\)', cmake)

    # The control program: find the cans in the scan, the triangle IK, trajectories through via
    # points, and the grasp fix holding each can: katana_pick's stack_cans.
    user.speed_up(5)
    program = user.start('rosrun katana_pick stack_cans')
    found = program.wait_for(r'stack_cans: (\d+) cans: ', timeout=120)
    assert int(found.group(1)) == 3
    done = program.wait_for(r'stack_cans: stacked (\d+) of (\d+) cans on the tower \((\d+) high\)', timeout=400)
    assert done.groups() == ('2', '2', '3')
    heights = sorted(call(user, '/gazebo/get_model_state', '{model_name: can_%d}' % i)['pose']['position']['z']
                     for i in range(1, 4))
    # Three cans of 0.12 m one on another on the 0.4 m table: their centres 0.12 m apart.
    assert heights[1] - heights[0] == pytest.approx(0.12, abs=0.01)
    assert heights[2] - heights[1] == pytest.approx(0.12, abs=0.01)
