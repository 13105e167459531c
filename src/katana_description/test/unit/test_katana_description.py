"""katana_450_6m90a.urdf.xacro expands cleanly and describes the Katana 450 6M90A: katana_driver's
names, the published lengths (checked by forward kinematics of the expanded URDF), limits,
transmissions, masses and inertias, the gripper plugin, and the tutorial's laser and grasp fix
(no ROS master needed: xacro only, plus roslaunch --dump-params for the upload launch file)."""
import math
import os
import shutil
import subprocess
import xml.etree.ElementTree as ET

import numpy as np
import pytest

PACKAGE = os.path.abspath(os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..'))
XACRO_FILE = os.path.join(PACKAGE, 'urdf', 'katana_450_6m90a.urdf.xacro')
LAUNCH_FILE = os.path.join(PACKAGE, 'launch', 'upload_katana_450_6m90a.launch')

SHOULDER_HEIGHT, UPPER_ARM, FOREARM, WRIST_TO_TOOL = 0.2015, 0.19, 0.139, 0.1473
ARM_JOINTS = ['katana_motor1_pan_joint', 'katana_motor2_lift_joint', 'katana_motor3_lift_joint',
              'katana_motor4_lift_joint', 'katana_motor5_wrist_roll_joint']
FINGER_JOINTS = ['katana_r_finger_joint', 'katana_l_finger_joint']
ARM_LINKS = ['katana_base_link', 'katana_motor1_pan_link', 'katana_motor2_lift_link', 'katana_motor3_lift_link',
             'katana_motor4_lift_link', 'katana_motor5_wrist_roll_link', 'katana_r_finger_link',
             'katana_l_finger_link', 'katana_gripper_link', 'katana_gripper_tool_frame']

# The tutorial's grasp-fix block, as it appends it to katana_description/urdf/gazebo.urdf.xacro.
TUTORIAL_GRASP_FIX = """
<gazebo> <plugin name="gazebo_grasp_fix" filename="libgazebo_grasp_fix.so"> <arm>
<arm_name>katana</arm_name> <gripper_link>katana_r_finger_link</gripper_link>
<gripper_link>katana_l_finger_link</gripper_link> <palm_link>katana_motor5_wrist_roll_link</palm_link>
</arm> <forces_angle_tolerance>100</forces_angle_tolerance> <update_rate>4</update_rate>
<grip_count_threshold>4</grip_count_threshold> <max_grip_count>8</max_grip_count>
<release_tolerance>0.005</release_tolerance> <disable_collisions_on_attach>false</disable_collisions_on_attach>
<contact_topic>__default_topic__</contact_topic> </plugin> </gazebo>"""

# katana_gazebo_plugins' gripper block, as upstream's gazebo.urdf.xacro has it.
UPSTREAM_GRIPPER = """
<gazebo> <plugin name="gazebo_ros_katana_gripper" filename="libgazebo_ros_katana_gripper.so">
<r_finger_joint>katana_r_finger_joint</r_finger_joint> <l_finger_joint>katana_l_finger_joint</l_finger_joint>
</plugin> </gazebo>"""


def run_xacro(*args):
    xacro = shutil.which('xacro')
    assert xacro, 'xacro is not on PATH (source scripts/env.sh)'
    result = subprocess.run([xacro, XACRO_FILE] + list(args), capture_output=True, text=True, timeout=60)
    assert result.returncode == 0, result.stderr
    return result


@pytest.fixture(scope='module')
def expansion():
    return run_xacro()


@pytest.fixture(scope='module')
def robot(expansion):
    return ET.fromstring(expansion.stdout)


def floats(text):
    return [float(v) for v in text.split()]


def joints_of(robot):
    return {j.get('name'): j for j in robot.findall('joint')}


def joint(robot, name):
    j = robot.find("joint[@name='%s']" % name)
    assert j is not None, 'no joint ' + name
    return j


def limit(robot, name):
    lim = joint(robot, name).find('limit')
    return {k: float(lim.get(k)) for k in ('lower', 'upper', 'effort', 'velocity')}


# --- forward kinematics of the expanded URDF (numpy; kdl_parser_py is not in Debian) ---

def rotation(axis, angle):
    """Rodrigues' rotation about a unit axis."""
    x, y, z = np.asarray(axis, float) / np.linalg.norm(axis)
    k = np.array([[0, -z, y], [z, 0, -x], [-y, x, 0]])
    return np.eye(3) + math.sin(angle) * k + (1 - math.cos(angle)) * k @ k


def rpy_matrix(r, p, y):
    return rotation((0, 0, 1), y) @ rotation((0, 1, 0), p) @ rotation((1, 0, 0), r)


def origin_transform(element):
    t = np.eye(4)
    origin = element.find('origin')
    if origin is not None:
        t[:3, :3] = rpy_matrix(*floats(origin.get('rpy', '0 0 0')))
        t[:3, 3] = floats(origin.get('xyz', '0 0 0'))
    return t


def link_poses(robot, q=None):
    """Pose (4x4, in the root link's frame) of every link for joint positions q (name -> rad)."""
    q = q or {}
    by_child = {j.find('child').get('link'): j for j in robot.findall('joint')}
    poses = {}

    def pose(link):
        if link not in poses:
            j = by_child.get(link)
            if j is None:
                poses[link] = np.eye(4)
            else:
                t = origin_transform(j)
                if j.get('type') in ('revolute', 'continuous'):
                    motion = np.eye(4)
                    motion[:3, :3] = rotation(floats(j.find('axis').get('xyz')), q.get(j.get('name'), 0.0))
                    t = t @ motion
                poses[link] = pose(j.find('parent').get('link')) @ t
        return poses[link]

    for link in robot.findall('link'):
        pose(link.get('name'))
    return poses


def position(robot, link, q=None):
    return link_poses(robot, q)[link][:3, 3]


def random_configuration(robot, rng):
    q = {}
    for name in ARM_JOINTS + FINGER_JOINTS:
        lim = limit(robot, name)
        q[name] = rng.uniform(lim['lower'], lim['upper'])
    return q


# --- expansion and names ---

def test_xacro_expands_without_warnings(expansion):
    assert expansion.stderr.strip() == ''


def test_links_and_joints_have_katana_drivers_names(robot):
    links = {link.get('name') for link in robot.findall('link')}
    assert links == set(ARM_LINKS) | {'hokuyo_link', 'world'}
    moving = {j.get('name') for j in robot.findall('joint') if j.get('type') != 'fixed'}
    assert moving == set(ARM_JOINTS + FINGER_JOINTS)
    assert all(joint(robot, name).get('type') == 'revolute' for name in moving)


def test_the_chain_runs_from_the_base_through_the_five_motors_to_the_tool_frame(robot):
    parent_of = {j.find('child').get('link'): j.find('parent').get('link') for j in robot.findall('joint')}
    chain, link = [], 'katana_gripper_tool_frame'
    while link in parent_of:
        chain.append(link)
        link = parent_of[link]
    chain.append(link)
    assert chain[::-1] == ['world', 'katana_base_link', 'katana_motor1_pan_link', 'katana_motor2_lift_link',
                           'katana_motor3_lift_link', 'katana_motor4_lift_link', 'katana_motor5_wrist_roll_link',
                           'katana_gripper_link', 'katana_gripper_tool_frame']
    for finger in ('katana_r_finger_link', 'katana_l_finger_link'):
        assert parent_of[finger] == 'katana_motor5_wrist_roll_link'  # the grasp fix's palm
    assert parent_of['hokuyo_link'] == 'katana_base_link'


# --- kinematics ---

def test_zero_pose_stretches_the_arm_out_along_x_at_shoulder_height(robot):
    tool = position(robot, 'katana_gripper_tool_frame')
    np.testing.assert_allclose(tool, [UPPER_ARM + FOREARM + WRIST_TO_TOOL, 0, SHOULDER_HEIGHT], atol=1e-9)
    np.testing.assert_allclose(position(robot, 'katana_motor2_lift_link'), [0, 0, SHOULDER_HEIGHT], atol=1e-9)


def test_stretched_up_the_arm_reaches_the_sum_of_its_lengths_above_the_base(robot):
    tool = position(robot, 'katana_gripper_tool_frame', {'katana_motor2_lift_joint': math.pi / 2})
    np.testing.assert_allclose(tool, [0, 0, 0.2015 + 0.19 + 0.139 + 0.1473], atol=1e-9)


def test_link_lengths_hold_in_every_configuration(robot):
    rng = np.random.default_rng(13)
    for _ in range(200):
        poses = link_poses(robot, random_configuration(robot, rng))
        p = {name: poses[name][:3, 3] for name in poses}
        assert np.linalg.norm(p['katana_motor1_pan_link'] - p['katana_base_link']) == pytest.approx(SHOULDER_HEIGHT)
        assert np.linalg.norm(p['katana_motor3_lift_link'] - p['katana_motor2_lift_link']) == pytest.approx(UPPER_ARM)
        assert np.linalg.norm(p['katana_motor4_lift_link'] - p['katana_motor3_lift_link']) == pytest.approx(FOREARM)
        assert (np.linalg.norm(p['katana_gripper_tool_frame'] - p['katana_motor4_lift_link'])
                == pytest.approx(WRIST_TO_TOOL))
        # The lift axes stay parallel to each other and horizontal: the arm moves in a vertical plane.
        arm_plane_normal = poses['katana_motor2_lift_link'][:3, 1]
        assert abs(arm_plane_normal[2]) < 1e-9
        tool_offset = p['katana_gripper_tool_frame'] - p['katana_motor1_pan_link']
        assert abs(tool_offset @ arm_plane_normal) < 1e-9


def test_positive_lift_angles_lift_and_the_roll_does_not_move_the_tool(robot):
    def tool(**q):
        return position(robot, 'katana_gripper_tool_frame', {'katana_' + k: v for k, v in q.items()})
    for name in ('motor2_lift_joint', 'motor3_lift_joint', 'motor4_lift_joint'):
        assert tool(**{name: 0.3})[2] > SHOULDER_HEIGHT + 0.01
        assert tool(**{name: -0.1})[2] < SHOULDER_HEIGHT - 0.001
    assert tool(motor1_pan_joint=0.5)[1] > 0.2  # counter-clockwise seen from above
    for roll in (-2.5, 1.0, 2.8):
        np.testing.assert_allclose(tool(motor5_wrist_roll_joint=roll, motor4_lift_joint=-1.0),
                                   tool(motor4_lift_joint=-1.0), atol=1e-12)


def finger_tip_gap(robot, angle):
    q = {name: angle for name in FINGER_JOINTS}
    poses = link_poses(robot, q)
    tips = []
    for link in ('katana_r_finger_link', 'katana_l_finger_link'):
        tip = poses[link] @ np.array([0.08, 0, 0, 1.0])
        tips.append(tip[1])
    return tips[1] - tips[0]


def test_fingers_open_with_positive_angles_wide_enough_for_a_can(robot):
    gap_open, gap_zero, gap_closed = (finger_tip_gap(robot, a) for a in (0.30, 0.0, -0.44))
    assert gap_open > gap_zero > gap_closed
    assert 0.08 < gap_open < 0.12  # a can is 0.066 wide
    assert gap_closed < 0.0


# --- limits, transmissions, dynamics ---

def test_joint_limits(robot):
    for name in FINGER_JOINTS:
        lim = limit(robot, name)
        assert (lim['lower'], lim['upper']) == (-0.44, 0.30)
    spans = {name: limit(robot, name)['upper'] - limit(robot, name)['lower'] for name in ARM_JOINTS}
    assert 5.5 < spans['katana_motor1_pan_joint'] < 2 * math.pi
    assert 5.5 < spans['katana_motor5_wrist_roll_joint'] < 2 * math.pi
    for name in ('katana_motor2_lift_joint', 'katana_motor3_lift_joint', 'katana_motor4_lift_joint'):
        assert 2.0 < spans[name] < 4.5
    lift = limit(robot, 'katana_motor2_lift_joint')
    assert -0.3 < lift['lower'] < 0 and math.pi / 2 < lift['upper'] < math.pi  # it can stand upright
    for name in ARM_JOINTS + FINGER_JOINTS:
        lim = limit(robot, name)
        assert -math.pi <= lim['lower'] < 0 < lim['upper'] <= math.pi, name  # zero pose is inside
        assert 0.01 <= lim['effort'] <= 1.5, name
        assert 0.5 <= lim['velocity'] <= 3.0, name


def test_every_moving_joint_has_one_effort_transmission(robot):
    moving = {j.get('name') for j in robot.findall('joint') if j.get('type') != 'fixed'}
    transmitted = []
    for t in robot.findall('transmission'):
        assert t.findtext('type') == 'transmission_interface/SimpleTransmission'
        joints = t.findall('joint')
        assert len(joints) == 1
        assert joints[0].findtext('hardwareInterface') == 'hardware_interface/EffortJointInterface'
        actuator = t.find('actuator')
        assert actuator.findtext('hardwareInterface') == 'hardware_interface/EffortJointInterface'
        assert float(actuator.findtext('mechanicalReduction')) == 1.0
        transmitted.append(joints[0].get('name'))
    assert sorted(transmitted) == sorted(moving)
    assert len(transmitted) == 7


def inertia_matrix(inertial):
    i = {k: float(v) for k, v in inertial.find('inertia').attrib.items()}
    return np.array([[i['ixx'], i['ixy'], i['ixz']], [i['ixy'], i['iyy'], i['iyz']], [i['ixz'], i['iyz'], i['izz']]])


def test_every_link_has_positive_mass_and_a_physical_inertia(robot):
    for link in robot.findall('link'):
        name = link.get('name')
        if name == 'world':
            assert link.find('inertial') is None  # Gazebo's anchor, not a body
            continue
        inertial = link.find('inertial')
        assert inertial is not None, name
        mass = float(inertial.find('mass').get('value'))
        assert 0 < mass < 2.0, name
        moments = np.linalg.eigvalsh(inertia_matrix(inertial))
        assert moments.min() > 0, name
        a, b, c = moments
        assert a + b >= c * (1 - 1e-9), name  # triangle inequality of principal moments
        # No larger than the link's mass spread over a 0.3 m sphere: a typo shows up here.
        assert moments.max() < mass * 0.3 ** 2, name


def test_the_arm_weighs_what_the_datasheet_says(robot):
    masses = {link.get('name'): float(link.find('inertial/mass').get('value'))
              for link in robot.findall('link') if link.find('inertial') is not None}
    assert sum(masses[name] for name in ARM_LINKS) == pytest.approx(4.3, abs=0.1)
    moving = sum(masses[name] for name in ARM_LINKS if name != 'katana_base_link')
    assert 2.5 < moving < 3.5


def test_shapes_are_primitives_and_separate_links_do_not_overlap_at_zero_pose(robot):
    """Collisions are boxes and cylinders; at the zero pose every link is axis-aligned, so
    boxes around them show overlaps between links that are not joined to each other."""
    poses = link_poses(robot)
    parent_of = {j.find('child').get('link'): j.find('parent').get('link') for j in robot.findall('joint')}
    boxes = {}
    for link in robot.findall('link'):
        name = link.get('name')
        for collision in link.findall('collision'):
            geometry = collision.find('geometry')[0]
            assert geometry.tag in ('box', 'cylinder'), name
            if geometry.tag == 'box':
                half = np.array(floats(geometry.get('size'))) / 2
            else:
                r, length = float(geometry.get('radius')), float(geometry.get('length'))
                assert abs(floats(collision.find('origin').get('rpy'))[0]) < 1e-9  # upright
                half = np.array([r, r, length / 2])
            assert half.min() > 0, name
            centre = (poses[name] @ origin_transform(collision))[:3, 3]
            boxes[name] = (centre - half, centre + half)
    moving_bodies = [n for n in boxes if n not in ('hokuyo_link',)]  # the laser sits in the base

    def joined(a, b):
        return parent_of.get(a) == b or parent_of.get(b) == a

    for i, a in enumerate(moving_bodies):
        for b in moving_bodies[i + 1:]:
            if joined(a, b):
                continue
            overlap = np.minimum(boxes[a][1], boxes[b][1]) - np.maximum(boxes[a][0], boxes[b][0])
            assert overlap.min() < 0, (a, b)


# --- Gazebo blocks ---

def gazebo_references(robot):
    refs = {}
    for g in robot.findall('gazebo'):
        if g.get('reference'):
            refs.setdefault(g.get('reference'), []).append(g)
    return refs


def test_gravity_is_turned_off_on_every_arm_link(robot):
    refs = gazebo_references(robot)
    for name in ARM_LINKS:
        values = [g.findtext('turnGravityOff') for g in refs.get(name, []) if g.find('turnGravityOff') is not None]
        assert values == ['true'], name


def test_ros_control_plugin_is_there_once_in_the_root_namespace(robot):
    plugins = [p for p in robot.iter('plugin') if p.get('filename') == 'libgazebo_ros_control.so']
    assert len(plugins) == 1
    assert plugins[0].findtext('robotNamespace') == '/'


def test_the_tutorials_laser_on_the_base(robot):
    j = joint(robot, 'hokuyo_joint')
    assert j.get('type') == 'fixed' and j.find('parent').get('link') == 'katana_base_link'
    assert 0.0 <= floats(j.find('origin').get('xyz'))[2] < 0.12  # below the top of a can
    link = robot.find("link[@name='hokuyo_link']")
    assert floats(link.find('collision/geometry/box').get('size')) == [0.1, 0.1, 0.1]
    sensors = [s for g in gazebo_references(robot)['hokuyo_link'] for s in g.findall('sensor')]
    assert len(sensors) == 1
    s = sensors[0]
    assert s.get('type') == 'ray'
    assert float(s.findtext('update_rate')) == 40
    h = s.find('ray/scan/horizontal')
    assert int(h.findtext('samples')) == 720
    assert float(h.findtext('min_angle')) == -1.570796 and float(h.findtext('max_angle')) == 1.570796
    assert float(s.findtext('ray/range/min')) == 0.10 and float(s.findtext('ray/range/max')) == 30.0
    assert s.findtext('ray/noise/type') == 'gaussian'
    assert float(s.findtext('ray/noise/mean')) == 0.0 and float(s.findtext('ray/noise/stddev')) == 0.01
    plugin = s.find('plugin')
    assert plugin.get('filename') == 'libgazebo_ros_laser.so'
    assert plugin.findtext('topicName') == '/rrbot/laser/scan'
    assert plugin.findtext('frameName') == 'hokuyo_link'


def canonical(element):
    """Tag, attributes, stripped text and children: the XML without layout and comments."""
    return (element.tag, sorted(element.attrib.items()), (element.text or '').strip(),
            [canonical(child) for child in element])


def test_the_grasp_fix_block_is_the_tutorials(robot):
    blocks = [g for g in robot.findall('gazebo')
              if any(p.get('filename') == 'libgazebo_grasp_fix.so' for p in g.findall('plugin'))]
    assert len(blocks) == 1
    assert canonical(blocks[0]) == canonical(ET.fromstring(TUTORIAL_GRASP_FIX))


def test_the_gripper_plugin_block_is_upstreams_and_names_the_finger_joints(robot):
    blocks = [g for g in robot.findall('gazebo')
              if any(p.get('filename') == 'libgazebo_ros_katana_gripper.so' for p in g.findall('plugin'))]
    assert len(blocks) == 1
    assert canonical(blocks[0]) == canonical(ET.fromstring(UPSTREAM_GRIPPER))
    plugin = blocks[0].find('plugin')
    fingers = [plugin.findtext('r_finger_joint'), plugin.findtext('l_finger_joint')]
    assert fingers == FINGER_JOINTS
    for name in fingers:
        assert joint(robot, name).get('type') == 'revolute'


def has_laser(robot):
    return robot.find("link[@name='hokuyo_link']") is not None


def has_grasp_fix(robot):
    return any(p.get('filename') == 'libgazebo_grasp_fix.so' for p in robot.iter('plugin'))


def has_world(robot):
    return robot.find("link[@name='world']") is not None


@pytest.mark.parametrize('arg, present', [('laser', has_laser), ('grasp_fix', has_grasp_fix),
                                          ('fixed_to_world', has_world)])
def test_each_addition_can_be_left_out(robot, arg, present):
    assert present(robot)
    without = run_xacro(arg + ':=false')
    assert without.stderr.strip() == ''
    smaller = ET.fromstring(without.stdout)
    assert not present(smaller)
    assert smaller.find("link[@name='katana_gripper_tool_frame']") is not None


def test_upload_launch_file_loads_the_same_robot_description(expansion):
    roslaunch = shutil.which('roslaunch')
    assert roslaunch, 'roslaunch is not on PATH (source scripts/env.sh)'
    env = dict(os.environ)
    # Finds katana_description and the workspace's xacro before the workspace is built, too.
    env['ROS_PACKAGE_PATH'] = os.pathsep.join([PACKAGE, os.path.join(os.path.dirname(PACKAGE), 'xacro'),
                                               env.get('ROS_PACKAGE_PATH', '')])
    result = subprocess.run([roslaunch, '--dump-params', LAUNCH_FILE], capture_output=True, text=True, env=env,
                            timeout=60)
    assert result.returncode == 0, result.stderr
    import yaml
    params = yaml.safe_load(result.stdout)
    uploaded = ET.fromstring(params['/robot_description'])
    assert canonical(uploaded) == canonical(ET.fromstring(expansion.stdout))
