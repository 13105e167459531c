"""Names, YAML controller lists, messages, reason selection and bounded calls (no ROS master)."""
import os
import sys
import threading
import time
from types import SimpleNamespace

import pytest
import yaml

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..', 'src'))

from controller_manager_tools import core  # noqa: E402


# --- names ----------------------------------------------------------------------------------

@pytest.mark.parametrize('namespace,expected', [
    (None, 'controller_manager'),  # relative: resolved in the node's namespace (ns="/simple_model")
    ('', 'controller_manager'),
    ('/', '/controller_manager'),
    ('/simple_model', '/simple_model/controller_manager'),
    ('/simple_model/', '/simple_model/controller_manager'),
    ('rrbot', 'rrbot/controller_manager'),
    ('/a/b//', '/a/b/controller_manager'),
])
def test_controller_manager_namespace(namespace, expected):
    assert core.controller_manager_namespace(namespace) == expected


def test_service_name():
    assert core.service_name('/simple_model', 'load_controller') == '/simple_model/controller_manager/load_controller'
    assert core.service_name(None, 'switch_controller') == 'controller_manager/switch_controller'


@pytest.mark.parametrize('service,ns', [
    ('/simple_model/controller_manager/load_controller', '/simple_model'),
    ('/a/b/controller_manager/list_controllers', '/a/b'),
    ('/controller_manager/load_controller', '/'),
])
def test_robot_namespace_of(service, ns):
    assert core.robot_namespace_of(service) == ns


def test_other_controller_managers():
    services = ['/rrbot/controller_manager/load_controller', '/rrbot/controller_manager/list_controllers',
                '/simple_model/controller_manager/load_controller', '/gazebo/spawn_urdf_model',
                '/controller_manager/load_controller']
    assert core.other_controller_managers(services, '/simple_model/controller_manager/load_controller') == \
        ['/', '/rrbot']
    assert core.other_controller_managers([], '/x/controller_manager/load_controller') == []


# --- controller arguments and YAML ----------------------------------------------------------

def test_is_yaml_argument(tmp_path):
    assert core.is_yaml_argument('config/controllers.yaml')
    assert core.is_yaml_argument('/abs/Controllers.YML')
    assert not core.is_yaml_argument('joint_state_controller', isfile=lambda _p: False)
    existing = tmp_path / 'my_controllers'
    existing.write_text('a: {type: t}\n')
    assert core.is_yaml_argument(str(existing))  # upstream: an existing file is a configuration


def test_controller_names_are_top_level_keys_in_order():
    params = yaml.safe_load("""
joint_state_controller:
  type: joint_state_controller/JointStateController
  publish_rate: 50
arm_controller:
  type: effort_controllers/JointPositionController
  joint: joint1
  pid: {p: 100.0, i: 0.01, d: 10.0}
gripper_controller:
  type: position_controllers/JointPositionController
""")
    assert core.controller_names_from_params(params) == ['joint_state_controller', 'arm_controller',
                                                         'gripper_controller']


@pytest.mark.parametrize('text', ['', '- a\n- b\n', 'just a string\n', '{}\n'])
def test_yaml_without_controllers_is_an_error(text):
    with pytest.raises(ValueError) as error:
        core.controller_names_from_params(yaml.safe_load(text), 'c.yaml')
    assert 'c.yaml defines no controllers' in str(error.value)


def test_unique_keeps_first():
    assert core.unique(['a', 'b', 'a', 'c', 'b']) == ['a', 'b', 'c']


# --- messages -------------------------------------------------------------------------------

def test_upstream_spawner_lines():
    assert core.loaded_message(['a', 'b']) == 'Controller Spawner: Loaded controllers: a, b'
    assert core.started_message(['a', 'b']) == 'Started controllers: a, b'


def test_waiting_message():
    assert core.waiting_message('service /r/controller_manager/load_controller', 5.2, 30.0) == \
        'still waiting for service /r/controller_manager/load_controller (5 s so far, giving up after 30 s)'
    assert 'no timeout' in core.waiting_message('x', 10, None)


def test_missing_service_message_names_service_plugin_and_namespace():
    text = core.missing_service_message('/simple_model/controller_manager/load_controller', 30.0, [])
    assert 'Timed out after 30 s waiting for service /simple_model/controller_manager/load_controller' in text
    assert 'libgazebo_ros_control.so' in text
    assert '<robotNamespace>/simple_model</robotNamespace>' in text
    assert 'No controller manager runs at all' in text


def test_missing_service_message_points_at_other_namespaces():
    text = core.missing_service_message('/simple_model/controller_manager/load_controller', 5.0, ['/rrbot'])
    assert 'Controller managers that do run: /rrbot/controller_manager' in text
    assert 'No controller manager runs at all' not in text


def test_missing_service_message_without_master():
    text = core.missing_service_message('/r/controller_manager/load_controller', 3.0, [], 'http://localhost:11311',
                                        master_reachable=False)
    assert 'cannot reach the ROS master at http://localhost:11311' in text


def test_missing_clock_message():
    text = core.missing_clock_message(30.0)
    assert '/clock' in text and '/use_sim_time is true' in text and '30 s' in text


def test_failure_message_carries_the_controller_managers_reason():
    text = core.failure_message('load controller', 'arm', '/r/controller_manager/load_controller',
                                ["Could not load controller 'arm' because the type was not specified.",
                                 "line one\nline two"], '/gazebo')
    lines = text.splitlines()
    assert lines[0] == "Failed to load controller 'arm': /r/controller_manager/load_controller answered ok: False."
    assert lines[1] == 'The controller manager (/gazebo) says:'
    assert lines[2] == "    Could not load controller 'arm' because the type was not specified."
    assert lines[3:] == ['    line one', '    line two']


def test_failure_message_without_reason_says_where_to_look():
    text = core.failure_message('start controllers', ['a', 'b'], '/r/controller_manager/switch_controller', [])
    assert text.startswith("Failed to start controllers ['a', 'b']: ")
    assert 'logged no reason' in text


def test_missing_type_hint():
    hint = core.missing_type_hint('arm', '/simple_model')
    assert '/simple_model/arm/type' in hint and 'rosparam' in hint


def test_cli_lines_as_upstream():
    assert core.cli_loaded('a') == "Loaded 'a'"
    assert core.cli_load_error('a') == "Error when loading 'a'"
    assert core.cli_unloaded('a') == "Unloaded 'a' successfully"
    assert core.cli_unload_error('a') == "Error when unloading 'a'"
    assert core.cli_switched(['a'], []) == ["Started ['a'] successfully"]
    assert core.cli_switched([], ['a']) == ["Stopped ['a'] successfully"]
    assert core.cli_switch_error(['a'], []) == "Error when starting ['a'] and stopping []"


def test_list_lines_as_upstream():
    effort = SimpleNamespace(hardware_interface='hardware_interface::EffortJointInterface', resources=['j1'])
    position = SimpleNamespace(hardware_interface='hardware_interface::PositionJointInterface', resources=['j2'])
    controllers = [
        SimpleNamespace(name='joint_state_controller', state='running', type='jsc/JSC', claimed_resources=[]),
        SimpleNamespace(name='arm', state='stopped', type='t', claimed_resources=[effort, effort, position]),
    ]
    assert core.list_lines(controllers) == [
        "'joint_state_controller' - '' ( running )",
        "'arm' - 'hardware_interface::EffortJointInterface+hardware_interface::PositionJointInterface' ( stopped )"]
    assert core.list_lines([]) == ['No controllers are loaded in mechanism control']


def test_select_reasons():
    entries = [
        (9.0, '/gazebo', 8, 'old error'),              # before the call
        (10.5, '/gazebo', 2, 'info line'),             # below WARN
        (10.6, '/gazebo', 8, "Could not load 'a'"),
        (10.7, '/other', 8, 'unrelated error'),
        (10.8, '/gazebo', 4, 'a warning'),
        (10.9, '/gazebo', 8, "Could not load 'a'"),    # repeated
        (11.0, '/spawner_1', 8, 'our own error'),
    ]
    assert core.select_reasons(entries, 10.0, '/gazebo') == ["Could not load 'a'", 'a warning']
    # source unknown: any node but our own
    assert core.select_reasons(entries, 10.0, None, '/spawner_1') == ["Could not load 'a'", 'unrelated error',
                                                                      'a warning']


def test_wait_for_message_satisfied():
    assert core.wait_for_message_satisfied('std_msgs/Bool', b'\x01')
    assert not core.wait_for_message_satisfied('std_msgs/Bool', b'\x00')
    assert not core.wait_for_message_satisfied('std_msgs/Bool', b'')
    assert core.wait_for_message_satisfied('std_msgs/Empty', b'')


# --- bounded calls --------------------------------------------------------------------------

def test_call_with_timeout_returns_the_result():
    assert core.call_with_timeout(lambda a, b: a + b, 1.0, 2, 3) == 5


def test_call_with_timeout_passes_a_timeout_keyword_through():
    # SwitchController's request has a `timeout` field, given as a keyword.
    assert core.call_with_timeout(lambda **kw: kw, 1.0, strictness=2, timeout=0.0) == {'strictness': 2,
                                                                                        'timeout': 0.0}


def test_call_with_timeout_reraises():
    def broken():
        raise RuntimeError('service unavailable')
    with pytest.raises(RuntimeError, match='service unavailable'):
        core.call_with_timeout(broken, 1.0)


def test_call_with_timeout_gives_up_on_a_hung_call():
    release = threading.Event()
    start = time.time()
    with pytest.raises(core.CallTimeout, match='no answer within 0.2 s'):
        core.call_with_timeout(release.wait, 0.2, 30)
    assert time.time() - start < 2.0
    release.set()


def test_call_without_limit_runs_inline():
    assert core.call_with_timeout(threading.current_thread, None) is threading.current_thread()
