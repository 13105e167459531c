"""pioneer3dx.xacro expands cleanly and describes the report's robot with the real Pioneer
3-DX's numbers; the drive plugin's geometry matches the wheels it drives (no ROS master
needed: xacro only)."""
import math
import os
import shutil
import subprocess
import xml.etree.ElementTree as ET

import pytest

PACKAGE = os.path.abspath(os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..'))
XACRO_FILE = os.path.join(PACKAGE, 'urdf', 'pioneer3dx.xacro')


@pytest.fixture(scope='module')
def expansion():
    xacro = shutil.which('xacro')
    assert xacro, 'xacro is not on PATH (source scripts/env.sh)'
    env = dict(os.environ)
    # Finds pioneer_description before the workspace is built, too.
    env['ROS_PACKAGE_PATH'] = os.pathsep.join([PACKAGE, env.get('ROS_PACKAGE_PATH', '')])
    result = subprocess.run([xacro, XACRO_FILE], capture_output=True, text=True, env=env, timeout=60)
    assert result.returncode == 0, result.stderr
    return result


@pytest.fixture(scope='module')
def robot(expansion):
    return ET.fromstring(expansion.stdout)


def floats(text):
    return [float(v) for v in text.split()]


def joint(robot, name):
    j = robot.find("joint[@name='%s']" % name)
    assert j is not None, 'no joint ' + name
    return j


def plugin(robot, filename):
    found = [p for p in robot.iter('plugin') if p.get('filename') == filename]
    assert len(found) == 1, filename
    return found[0]


def test_xacro_expands_without_warnings(expansion):
    assert expansion.stderr.strip() == ''


def test_links_and_tree(robot):
    links = {link.get('name') for link in robot.findall('link')}
    assert links == {'base_link', 'chassis', 'top_plate', 'front_sonar', 'back_sonar', 'swivel', 'center_wheel',
                     'center_hubcap', 'left_wheel', 'left_hub', 'right_wheel', 'right_hub', 'camera_link',
                     'camera_optical_link', 'hokuyo_link'}
    children = {j.find('child').get('link') for j in robot.findall('joint')}
    assert links - children == {'base_link'}  # base_link is the root (navigation's convention)
    assert joint(robot, 'hokuyo_joint').find('parent').get('link') == 'camera_link'


def test_total_mass_is_a_pioneer_3dx(robot):
    total = sum(float(m.get('value')) for m in robot.iter('mass'))
    assert total == pytest.approx(9.0, abs=0.05)


def test_inertias_are_physical(robot):
    for inertial in robot.iter('inertial'):
        i = inertial.find('inertia')
        ixx, iyy, izz = (float(i.get(k)) for k in ('ixx', 'iyy', 'izz'))
        assert min(ixx, iyy, izz) > 0
        assert ixx + iyy >= izz and iyy + izz >= ixx and ixx + izz >= iyy  # triangle inequality


def test_drive_wheels_have_the_real_geometry(robot):
    left, right = joint(robot, 'base_left_wheel_joint'), joint(robot, 'base_right_wheel_joint')
    for j in (left, right):
        assert j.get('type') == 'continuous'
        assert floats(j.find('axis').get('xyz')) == [0, 1, 0]
    lx, ly, lz = floats(left.find('origin').get('xyz'))
    rx, ry, rz = floats(right.find('origin').get('xyz'))
    assert (lx, rx) == (0.0, 0.0) and ly == -ry
    assert ly - ry == pytest.approx(0.33)
    assert lz == rz == pytest.approx(0.0975)  # on the floor: base_link is at floor level
    radius = float(robot.find("link[@name='left_wheel']/collision/geometry/cylinder").get('radius'))
    assert 2 * radius == pytest.approx(0.195)


def test_caster_reaches_the_floor_and_is_frictionless(robot):
    swivel = floats(joint(robot, 'base_swivel_joint').find('origin').get('xyz'))
    wheel = floats(joint(robot, 'swivel_hubcap_joint').find('origin').get('xyz'))
    ball = robot.find("link[@name='center_wheel']/collision/geometry/sphere")
    assert swivel[2] + wheel[2] == pytest.approx(float(ball.get('radius')))
    assert swivel[0] + wheel[0] < -0.15  # behind the axle
    gazebo = robot.find("gazebo[@reference='center_wheel']")
    assert float(gazebo.find('mu1').text) == 0.0 and float(gazebo.find('mu2').text) == 0.0


def test_diff_drive_plugin_matches_the_wheels(robot):
    p = plugin(robot, 'libgazebo_ros_diff_drive.so')
    value = {c.tag: c.text for c in p}
    assert (value['leftJoint'], value['rightJoint']) == ('base_left_wheel_joint', 'base_right_wheel_joint')
    ly = floats(joint(robot, 'base_left_wheel_joint').find('origin').get('xyz'))[1]
    assert float(value['wheelSeparation']) == pytest.approx(2 * ly)
    assert float(value['wheelDiameter']) == pytest.approx(0.195)
    assert value['robotNamespace'] == '/'
    assert (value['commandTopic'], value['odometryTopic']) == ('pioneer/cmd_vel', 'pioneer/odom')
    assert (value['odometryFrame'], value['robotBaseFrame']) == ('odom', 'base_link')
    assert value['legacyMode'] == 'false' and value['publishWheelTF'] == 'false'


def test_no_ros_control_plugin_fights_the_drive(robot):
    assert not [p for p in robot.iter('plugin') if p.get('filename') == 'libgazebo_ros_control.so']
    names = sorted(t.find('joint').get('name') for t in robot.findall('transmission'))
    assert names == ['base_left_wheel_joint', 'base_right_wheel_joint']
    for t in robot.findall('transmission'):
        assert t.find('joint/hardwareInterface').text.endswith('EffortJointInterface')


def test_hokuyo_laser(robot):
    sensor = robot.find("gazebo[@reference='hokuyo_link']/sensor")
    assert sensor.get('type') == 'ray'
    assert float(sensor.find('update_rate').text) == 40
    h = sensor.find('ray/scan/horizontal')
    assert int(h.find('samples').text) == 720
    assert float(h.find('min_angle').text) == pytest.approx(-math.pi)
    assert float(h.find('max_angle').text) == pytest.approx(math.pi)
    r = sensor.find('ray/range')
    assert (float(r.find('min').text), float(r.find('max').text)) == (0.1, 30.0)
    assert float(sensor.find('ray/noise/stddev').text) == 0.01
    p = sensor.find('plugin')
    assert p.get('filename') == 'libgazebo_ros_laser.so'
    assert (p.find('robotNamespace').text, p.find('topicName').text) == ('/', 'pioneer/laser/scan')
    assert p.find('frameName').text == 'hokuyo_link'


def test_camera(robot):
    sensor = robot.find("gazebo[@reference='camera_link']/sensor")
    assert sensor.get('type') == 'camera'
    assert float(sensor.find('update_rate').text) == 30
    image = sensor.find('camera/image')
    assert (int(image.find('width').text), int(image.find('height').text)) == (800, 800)
    p = sensor.find('plugin')
    assert p.get('filename') == 'libgazebo_ros_camera.so'
    assert (p.find('cameraName').text, p.find('imageTopicName').text) == ('pioneer/camera1', 'image_raw')
    assert p.find('frameName').text == 'camera_optical_link'
    optical = joint(robot, 'camera_optical_joint').find('origin')
    assert floats(optical.get('rpy')) == pytest.approx([-math.pi / 2, 0, -math.pi / 2])
