"""The scripts' own logic with stand-ins for rospy and the controller manager (no ROS master):
the spawner's teardown and YAML expansion, the controller_manager command's commands."""
import importlib.machinery
import importlib.util
import os
import sys
import threading
import time
from types import SimpleNamespace

import pytest
import yaml

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, '..', '..', 'src'))

from controller_manager_tools import core  # noqa: E402


def load_script(name):
    """Import an extension-less script as a module (its ROS imports are inside main())."""
    loader = importlib.machinery.SourceFileLoader('cm_script_' + name, os.path.join(HERE, '..', '..', 'scripts', name))
    spec = importlib.util.spec_from_loader(loader.name, loader)
    module = importlib.util.module_from_spec(spec)
    dont_write = sys.dont_write_bytecode
    sys.dont_write_bytecode = True
    try:
        loader.exec_module(module)
    finally:
        sys.dont_write_bytecode = dont_write
    return module


spawner = load_script('spawner')
cli = load_script('controller_manager')


class Log(object):
    def __init__(self):
        self.lines = []

    def loginfo(self, m):
        self.lines.append(('info', m))

    def logwarn(self, m):
        self.lines.append(('warn', m))

    def logerr(self, m):
        self.lines.append(('error', m))

    def text(self, level=None):
        return '\n'.join(m for lv, m in self.lines if level in (None, lv))


ROS_IO = SimpleNamespace(bounded_call=core.call_with_timeout)


class FakeControllerManager(object):
    """The controller manager's service semantics (as sim_control's), callable as proxies."""

    def __init__(self, types=('t/Effort', 'jsc/JSC')):
        self.types = list(types)
        self.controllers = []  # [name, state]
        self.calls = []
        self.params = {}       # name -> type
        self.gone = False
        self.hang = None       # an Event the switch waits for

    def _find(self, name):
        return next((c for c in self.controllers if c[0] == name), None)

    def proxy(self, service):
        def call(*args, **kwargs):
            self.calls.append((service, args, kwargs))
            if self.gone:
                raise RuntimeError('service [/r/controller_manager/%s] unavailable' % service)
            return getattr(self, service)(*args, **kwargs)
        call.resolved_name = '/r/controller_manager/' + service
        return call

    def load_controller(self, name):
        ok = self._find(name) is None and self.params.get(name) in self.types
        if ok:
            self.controllers.append([name, 'initialized'])
        return SimpleNamespace(ok=ok)

    def unload_controller(self, name):
        c = self._find(name)
        ok = c is not None and c[1] != 'running'
        if ok:
            self.controllers.remove(c)
        return SimpleNamespace(ok=ok)

    def switch_controller(self, start_controllers=(), stop_controllers=(), strictness=core.STRICT, start_asap=False,
                          timeout=0.0):
        if self.hang is not None:
            self.hang.wait(10)
        stop = [self._find(n) for n in stop_controllers]
        start = [self._find(n) for n in start_controllers]
        if strictness == core.STRICT and (any(c is None or c[1] != 'running' for c in stop) or
                                          any(c is None or c[1] == 'running' for c in start)):
            return SimpleNamespace(ok=False)
        for c in stop:
            if c and c[1] == 'running':
                c[1] = 'stopped'
        for c in start:
            if c and c[1] != 'running':
                c[1] = 'running'
        return SimpleNamespace(ok=True)

    def list_controllers(self):
        return SimpleNamespace(controller=[SimpleNamespace(name=n, state=s, type=self.params[n], claimed_resources=[])
                                           for n, s in self.controllers])

    def list_controller_types(self):
        return SimpleNamespace(types=self.types, base_classes=['controller_interface::ControllerBase'] * 2)

    def reload_controller_libraries(self, force_kill):
        ok = force_kill or not self.controllers
        if ok:
            del self.controllers[:]
        return SimpleNamespace(ok=ok)

    def service_calls(self, service):
        return [(args, kwargs) for s, args, kwargs in self.calls if s == service]


# --- spawner: teardown ----------------------------------------------------------------------

def make_teardown(cm, timeout=2.0):
    log = Log()
    teardown = spawner.Teardown(log, ROS_IO, cm.proxy('switch_controller'), cm.proxy('unload_controller'), timeout)
    return teardown, log


def loaded_cm(*names, running=True):
    cm = FakeControllerManager()
    for n in names:
        cm.params[n] = 't/Effort'
        cm.controllers.append([n, 'running' if running else 'initialized'])
    return cm


def test_teardown_stops_best_effort_then_unloads_in_reverse():
    cm = loaded_cm('a', 'b', 'c')
    cm.controllers[1][1] = 'stopped'  # someone stopped b: a STRICT stop would stop nothing
    teardown, log = make_teardown(cm)
    teardown.loaded.extend(['a', 'b', 'c'])
    teardown.run()
    (_, kwargs), = cm.service_calls('switch_controller')
    assert kwargs['stop_controllers'] == ['a', 'b', 'c'] and kwargs['strictness'] == core.BEST_EFFORT
    assert [args for args, _ in cm.service_calls('unload_controller')] == [('c',), ('b',), ('a',)]
    assert cm.controllers == []
    assert 'Succeeded in unloading a' in log.text('info')


def test_teardown_runs_once_per_controller():
    cm = loaded_cm('a', 'b')
    teardown, _ = make_teardown(cm)
    teardown.loaded.append('a')
    teardown.run()
    teardown.run()
    assert len(cm.service_calls('unload_controller')) == 1
    teardown.loaded.append('b')  # loaded after the first run (a load that was under way)
    teardown.run()
    assert [args for args, _ in cm.service_calls('unload_controller')] == [('a',), ('b',)]


def test_teardown_when_the_controller_manager_is_gone():
    cm = loaded_cm('a', 'b')
    cm.gone = True
    teardown, log = make_teardown(cm)
    teardown.loaded.extend(['a', 'b'])
    teardown.run()
    assert cm.service_calls('unload_controller') == []  # no point after the first failure
    assert 'cannot reach /r/controller_manager/switch_controller' in log.text('warn')
    assert 'simulator has probably stopped' in log.text('warn')


def test_teardown_is_bounded_when_the_controller_manager_hangs():
    cm = loaded_cm('a', 'b')
    cm.hang = threading.Event()
    teardown, log = make_teardown(cm, timeout=0.3)
    teardown.loaded.extend(['a', 'b'])
    start = time.time()
    teardown.run()
    assert time.time() - start < 2.0
    assert 'did not answer within 0.3 s (--shutdown-timeout)' in log.text('warn')
    assert cm.service_calls('unload_controller') == []
    cm.hang.set()


def test_teardown_call_records_loaded_controllers():
    cm = FakeControllerManager()
    cm.params['a'] = 't/Effort'
    teardown, _ = make_teardown(cm)
    load = cm.proxy('load_controller')
    assert teardown.call('a', load, 'a').ok
    assert not teardown.call('b', load, 'b').ok  # no type: refused
    assert teardown.loaded == ['a']
    cm.gone = True
    with pytest.raises(RuntimeError):
        teardown.call('a', load, 'a')


def test_shutdown_during_a_load_waits_for_it_and_unloads_it():
    cm = FakeControllerManager()
    cm.params['a'] = 't/Effort'
    teardown, _ = make_teardown(cm, timeout=5.0)
    release = threading.Event()
    load = cm.proxy('load_controller')

    def slow_load(name):
        release.wait(5)
        return load(name)

    caller = threading.Thread(target=teardown.call, args=('a', slow_load, 'a'))
    caller.start()
    time.sleep(0.2)
    shutdown = threading.Thread(target=teardown.run)  # the shutdown hook, while the load is under way
    shutdown.start()
    time.sleep(0.2)
    release.set()
    shutdown.join(5)
    caller.join(5)
    assert [args for args, _ in cm.service_calls('unload_controller')] == [('a',)]
    assert cm.controllers == []


# --- spawner: controller arguments and YAML files -------------------------------------------

class FakeRosparam(object):
    def __init__(self):
        self.uploaded = []

    def load_file(self, filename, default_namespace=None):
        with open(filename) as f:
            return [(yaml.safe_load(f), default_namespace)]

    def upload_params(self, ns, params):
        self.uploaded.append((ns, params))


def test_expand_controllers_loads_yaml_into_the_namespace(tmp_path):
    config = tmp_path / 'controllers.yaml'
    config.write_text('joint_state_controller: {type: jsc/JSC, publish_rate: 50}\n'
                      'arm_controller: {type: t/Effort, joint: j1}\n')
    rosparam, log = FakeRosparam(), Log()
    names = spawner.expand_controllers(['extra', str(config), 'arm_controller'], '/simple_model', log, rosparam)
    assert names == ['extra', 'joint_state_controller', 'arm_controller']
    assert rosparam.uploaded == [('/simple_model', {'joint_state_controller': {'type': 'jsc/JSC', 'publish_rate': 50},
                                                    'arm_controller': {'type': 't/Effort', 'joint': 'j1'}})]
    assert 'controllers joint_state_controller, arm_controller' in log.text('info')


def test_expand_controllers_reports_a_bad_file(tmp_path):
    with pytest.raises(ValueError, match='cannot load controller configuration .*missing.yaml'):
        spawner.expand_controllers([str(tmp_path / 'missing.yaml')], '/r', Log(), FakeRosparam())
    empty = tmp_path / 'empty.yaml'
    empty.write_text('[]\n')
    with pytest.raises(ValueError, match='defines no controllers'):
        spawner.expand_controllers([str(empty)], '/r', Log(), FakeRosparam())


# --- controller_manager command -------------------------------------------------------------

class FakeReasons(object):
    def __init__(self, lines):
        self.lines = lines
        self.source_node = '/gazebo'

    def reasons(self, since):
        return self.lines

    def set_source(self, service):
        pass

    def wait_connected(self, timeout):
        pass


def run_cli(cm, argv, reasons=()):
    args = core.parse_cli_args(argv)
    rospy = SimpleNamespace(resolve_name=lambda n: n if n.startswith('/') else '/r/' + n,
                            ServiceProxy=lambda name, cls: cm.proxy(name.rsplit('/', 1)[-1]))
    ros_io = SimpleNamespace(bounded_call=core.call_with_timeout, wait_for_services=lambda *a: None,
                             Reasons=lambda: FakeReasons(list(reasons)))
    srv = SimpleNamespace(LoadController=0, UnloadController=0, SwitchController=0, ListControllers=0,
                          ListControllerTypes=0, ReloadControllerLibraries=0)
    return cli.Cli(args, rospy, ros_io, srv).run()


def test_cli_list_and_list_types(capsys):
    cm = loaded_cm('a')
    assert run_cli(cm, ['list'])
    assert run_cli(cm, ['list-types'])
    assert capsys.readouterr().out.splitlines() == ["'a' - '' ( running )", 't/Effort', 'jsc/JSC']


def test_cli_spawn_reports_the_failure_with_its_reason(capsys):
    cm = FakeControllerManager()
    cm.params['a'] = 't/Effort'
    assert not run_cli(cm, ['spawn', 'a', 'b'], reasons=["Could not load controller 'b' because the type was not "
                                                         "specified."])
    out, err = capsys.readouterr()
    assert out.splitlines() == ["Loaded 'a'", "Started ['a'] successfully"]
    assert err.splitlines() == ["Error when loading 'b'", 'The controller manager (/gazebo) says:',
                                "    Could not load controller 'b' because the type was not specified."]
    assert cm.controllers == [['a', 'running']]


def test_cli_start_stop_unload(capsys):
    cm = loaded_cm('a', running=False)
    assert run_cli(cm, ['start', 'a'])
    assert not run_cli(cm, ['unload', 'a'])  # still running
    assert run_cli(cm, ['stop', 'a'])
    assert run_cli(cm, ['unload', 'a'])
    out, err = capsys.readouterr()
    assert out.splitlines() == ["Started ['a'] successfully", "Stopped ['a'] successfully",
                                "Unloaded 'a' successfully"]
    assert err.splitlines()[0] == "Error when unloading 'a'"


def test_cli_kill_stops_only_running_controllers(capsys):
    cm = loaded_cm('a', 'b')
    cm.controllers[1][1] = 'stopped'
    assert run_cli(cm, ['kill', 'a', 'b'])
    assert capsys.readouterr().out.splitlines() == ["Stopped ['a'] successfully", "Unloaded 'a' successfully",
                                                    "Unloaded 'b' successfully"]
    assert cm.controllers == []


def test_cli_reload_libraries_restore(capsys):
    cm = loaded_cm('a', 'b')
    cm.controllers[1][1] = 'stopped'
    assert run_cli(cm, ['reload-libraries', '--restore'])
    assert capsys.readouterr().out.splitlines() == [
        'Restore: True', 'Successfully reloaded libraries', "Loaded 'a'", "Loaded 'b'",
        "Started ['a'] successfully", 'Controllers restored to original state']
    assert cm.controllers == [['a', 'running'], ['b', 'initialized']]
    (args, _), = cm.service_calls('reload_controller_libraries')
    assert args == (True,)  # force_kill, as upstream
