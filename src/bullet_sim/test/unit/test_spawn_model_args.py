"""Unit tests for scripts/spawn_model's argument parsing and model loading (no ROS master needed)."""
import argparse
import importlib.machinery
import importlib.util
import io
import math
import os
import sys

import pytest

SCRIPT = os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..', 'scripts', 'spawn_model')


def _load_script():
    """Import the extension-less script as a module (no bytecode left next to it)."""
    loader = importlib.machinery.SourceFileLoader('spawn_model_script', SCRIPT)
    spec = importlib.util.spec_from_loader(loader.name, loader)
    module = importlib.util.module_from_spec(spec)
    dont_write = sys.dont_write_bytecode
    sys.dont_write_bytecode = True
    try:
        loader.exec_module(module)
    finally:
        sys.dont_write_bytecode = dont_write
    return module


sm = _load_script()


def parse(line):
    return sm.parse_args(line.split())


def parse_error(line, capsys):
    with pytest.raises(SystemExit) as exit_info:
        parse(line)
    assert exit_info.value.code == sm.EXIT_BAD_FLAGS
    return capsys.readouterr().err


def test_script_is_executable_with_python3_shebang():
    assert os.access(SCRIPT, os.X_OK)
    with open(SCRIPT) as f:
        assert f.readline().strip() == '#!/usr/bin/env python3'


def test_minimal_urdf_from_param_defaults():
    args = parse('-urdf -param robot_description -model robot')
    assert args.urdf and not args.sdf
    assert args.param == 'robot_description'
    assert args.model == 'robot'
    assert (args.x, args.y, args.z, args.R, args.P, args.Y) == (0.0,) * 6
    assert args.joint_names == [] and args.joint_positions == []
    assert args.gazebo_namespace == '/gazebo'
    assert args.reference_frame == ''
    assert args.robot_namespace is None  # filled from the node's namespace at run time
    assert args.timeout is None  # wait forever, like upstream
    assert not args.unpause and args.wait is None and not args.bond
    assert sm.spawn_service_name(args) == '/gazebo/spawn_urdf_model'


def test_full_command_line():
    args = parse('-sdf -file /tmp/m.sdf -model box -x 1 -y -2.5 -z .5 -R 0.1 -P -0.2 -Y 3 '
                 '-J shoulder 0.5 -J elbow -1e-3 -unpause -wait ground -robot_namespace /r1 '
                 '-reference_frame table::link -gazebo_namespace /sim/ -timeout 2.5 -b')
    assert args.sdf and args.file == '/tmp/m.sdf' and args.model == 'box'
    assert (args.x, args.y, args.z, args.R, args.P, args.Y) == (1.0, -2.5, 0.5, 0.1, -0.2, 3.0)
    assert args.joint_names == ['shoulder', 'elbow']
    assert args.joint_positions == [0.5, -1e-3]
    assert args.unpause and args.wait == 'ground' and args.bond
    assert args.robot_namespace == '/r1'
    assert args.reference_frame == 'table::link'
    assert args.gazebo_namespace == '/sim'
    assert args.timeout == 2.5
    assert sm.spawn_service_name(args) == '/sim/spawn_sdf_model'


def test_ros_remapping_arguments_are_ignored():
    args = sm.parse_args(['-urdf', '-param', 'robot_description', '-model', 'r',
                          '__name:=spawner', '__log:=/tmp/x.log', 'foo:=bar'])
    assert args.model == 'r'


def test_database_implies_sdf():
    args = parse('-database table -model t')
    assert args.sdf and not args.urdf and args.database == 'table'


@pytest.mark.parametrize('namespace, expected', [
    ('/gazebo', '/gazebo'), ('gazebo', '/gazebo'), ('/gazebo/', '/gazebo'), ('/', ''), ('/a/b', '/a/b')])
def test_gazebo_namespace_normalized(namespace, expected):
    assert sm.normalize_namespace(namespace) == expected
    assert sm.service_names(expected)['unpause_physics'] == expected + '/unpause_physics'


@pytest.mark.parametrize('line, words', [
    ('-param robot_description -model r', ['-urdf or -sdf']),
    ('-urdf -sdf -param p -model r', ['-urdf and -sdf']),
    ('-urdf -model r', ['-file', '-param', '-database', 'required']),
    ('-urdf -file a -param p -model r', ['-file and -param']),
    ('-urdf -database table -model r', ['-database', '-sdf']),
    ('-urdf -param p', ['-model']),
    ('-urdf -param p -model r -x abc', ['-x', 'expected a number', 'abc']),
    ('-urdf -param p -model r -Y nan', ['-Y', 'finite']),
    ('-urdf -param p -model r -J elbow', ['-J', 'expected 2 arguments']),
    ('-urdf -param p -model r -J elbow up', ['-J', 'POSITION a number', 'up']),
    ('-urdf -param p -model r -timeout 0', ['-timeout', 'positive']),
    ('-urdf -param p -model r -timeout soon', ['-timeout', 'soon']),
    ('-urdf -param p -model r -bogus', ['unrecognized flag', "'-bogus'"]),
    ('-urdf -param p -model r -mod x', ['unrecognized flag', "'-mod'"]),  # no abbreviations
    ('-urdf -param p -model r stray', ['unrecognized', 'stray']),
])
def test_bad_flags_name_the_flag_and_expectation(line, words, capsys):
    err = parse_error(line, capsys)
    for word in words:
        assert word in err


def test_empty_values_rejected(capsys):
    with pytest.raises(SystemExit):
        sm.parse_args(['-urdf', '-param', 'p', '-model', ' '])
    assert '-model' in capsys.readouterr().err
    with pytest.raises(SystemExit):
        sm.parse_args(['-urdf', '-param', '', '-model', 'r'])
    assert '-param' in capsys.readouterr().err


@pytest.mark.parametrize('rpy', [(0, 0, 0), (0.3, 0, 0), (0, -0.7, 0), (0, 0, 2.0), (0.1, 0.2, 0.3), (-2, 1, 3)])
def test_rpy_to_quaternion_matches_fixed_axis_rotation(rpy):
    roll, pitch, yaw = rpy
    x, y, z, w = sm.rpy_to_quaternion(roll, pitch, yaw)
    assert math.isclose(x * x + y * y + z * z + w * w, 1.0)

    def quat_mul(a, b):
        ax, ay, az, aw = a
        bx, by, bz, bw = b
        return (aw * bx + ax * bw + ay * bz - az * by,
                aw * by - ax * bz + ay * bw + az * bx,
                aw * bz + ax * by - ay * bx + az * bw,
                aw * bw - ax * bx - ay * by - az * bz)

    qx = (math.sin(roll / 2), 0, 0, math.cos(roll / 2))
    qy = (0, math.sin(pitch / 2), 0, math.cos(pitch / 2))
    qz = (0, 0, math.sin(yaw / 2), math.cos(yaw / 2))
    expected = quat_mul(qz, quat_mul(qy, qx))  # R = Rz(yaw) Ry(pitch) Rx(roll)
    assert all(math.isclose(a, b, abs_tol=1e-12) for a, b in zip((x, y, z, w), expected))


def test_find_database_model_searches_path_in_order(tmp_path):
    first, second = tmp_path / 'a', tmp_path / 'b'
    (second / 'table').mkdir(parents=True)
    (second / 'table' / 'model.sdf').write_text('<sdf/>')
    (first / 'table').mkdir(parents=True)  # no model.sdf here
    env = {'GAZEBO_MODEL_PATH': '%s:%s' % (first, second)}
    assert sm.find_database_model('table', env, str(tmp_path / 'home')) == str(second / 'table' / 'model.sdf')

    home = tmp_path / 'home'
    (home / '.gazebo' / 'models' / 'chair').mkdir(parents=True)
    (home / '.gazebo' / 'models' / 'chair' / 'model.sdf').write_text('<sdf/>')
    assert sm.find_database_model('chair', env, str(home)).endswith('chair/model.sdf')

    with pytest.raises(sm.SpawnError) as error:
        sm.find_database_model('sofa', env, str(home))
    assert "'sofa'" in str(error.value) and 'GAZEBO_MODEL_PATH' in str(error.value)


def test_read_model_xml_from_each_source(tmp_path):
    model = tmp_path / 'm.urdf'
    model.write_text('<robot name="r"/>')
    assert sm.read_model_xml(parse('-urdf -file %s -model r' % model)) == '<robot name="r"/>'

    params = {'robot_description': '<robot name="p"/>'}
    args = parse('-urdf -param robot_description -model r')
    assert sm.read_model_xml(args, get_param=params.__getitem__) == '<robot name="p"/>'

    args = parse('-urdf -stdin -model r')
    assert sm.read_model_xml(args, stdin=io.StringIO('<robot name="s"/>')) == '<robot name="s"/>'

    (tmp_path / 'models' / 'box').mkdir(parents=True)
    (tmp_path / 'models' / 'box' / 'model.sdf').write_text('<sdf version="1.6"/>')
    args = parse('-database box -model b')
    env = {'GAZEBO_MODEL_PATH': str(tmp_path / 'models')}
    assert sm.read_model_xml(args, environ=env, home=str(tmp_path)) == '<sdf version="1.6"/>'


def test_read_model_xml_missing_or_empty(tmp_path):
    with pytest.raises(sm.SpawnError, match='does not exist'):
        sm.read_model_xml(parse('-urdf -file %s -model r' % (tmp_path / 'nope.urdf')))
    empty = tmp_path / 'empty.urdf'
    empty.write_text('  \n')
    with pytest.raises(sm.SpawnError, match='empty'):
        sm.read_model_xml(parse('-urdf -file %s -model r' % empty))
    args = parse('-urdf -param robot_description -model r')
    with pytest.raises(sm.SpawnError, match='not set'):
        sm.read_model_xml(args, get_param={}.__getitem__)
    with pytest.raises(sm.SpawnError, match='empty'):
        sm.read_model_xml(args, get_param={'robot_description': ''}.__getitem__)
    with pytest.raises(sm.SpawnError, match='XML text'):
        sm.read_model_xml(args, get_param={'robot_description': 3}.__getitem__)


def test_check_model_xml():
    text = '<robot name="r"><link name="a"><visual><geometry><mesh filename="package://p/m.dae"/>' \
           '</geometry></visual></link></robot>'
    assert sm.check_model_xml(text) == text
    assert 'model://p/m.dae' in sm.check_model_xml(text, package_to_model=True)
    with pytest.raises(sm.SpawnError, match='not valid XML'):
        sm.check_model_xml('<robot name="r">')


class FakeClock:
    def __init__(self):
        self.now = 0.0

    def __call__(self):
        return self.now


def test_wait_for_service_logs_periodically_until_available():
    clock, logs, calls = FakeClock(), [], []

    def wait_once(name, seconds):
        calls.append(seconds)
        clock.now += seconds
        return len(calls) == 3

    sm.wait_for_service('/gazebo/spawn_urdf_model', None, wait_once, logs.append, clock, interval=5.0)
    assert calls == [5.0, 5.0, 5.0]
    assert len(logs) == 3 and all('/gazebo/spawn_urdf_model' in line for line in logs)
    assert 'Still waiting' in logs[1] and '10 s' in logs[2]


def test_wait_for_service_times_out_with_clear_message():
    clock, logs, calls = FakeClock(), [], []

    def wait_once(name, seconds):
        calls.append(seconds)
        clock.now += seconds
        return False

    with pytest.raises(sm.SpawnError) as error:
        sm.wait_for_service('/gazebo/spawn_sdf_model', 7.0, wait_once, logs.append, clock, interval=5.0)
    assert calls == [5.0, 2.0]
    assert '/gazebo/spawn_sdf_model' in str(error.value) and '-timeout' in str(error.value)


def test_number_type_messages():
    assert sm._number('-1e-3') == -1e-3
    with pytest.raises(argparse.ArgumentTypeError, match="got 'x'"):
        sm._number('x')
