"""Argument parsing of spawner, unspawner and the controller_manager command (no ROS master)."""
import os
import subprocess
import sys

import pytest

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, '..', '..', 'src'))

from controller_manager_tools import core  # noqa: E402

SCRIPTS = os.path.join(HERE, '..', '..', 'scripts')


def usage_error(parse, argv, capsys):
    with pytest.raises(SystemExit) as exit_info:
        parse(argv)
    assert exit_info.value.code == core.EXIT_BAD_ARGS
    return capsys.readouterr().err


# --- spawner --------------------------------------------------------------------------------

def test_spawner_defaults_match_upstream():
    args = core.parse_spawner_args(['joint_state_controller'])
    assert args.controllers == ['joint_state_controller']
    assert args.stopped is False
    assert args.wait_for is None
    assert args.namespace is None
    assert args.timeout == 30.0
    assert args.shutdown_timeout == 2.0


def test_spawner_all_flags():
    args = core.parse_spawner_args(['--stopped', '--wait-for', '/ready', '--namespace', '/simple_model',
                                    '--timeout', '12.5', '--shutdown-timeout', '4', 'a', 'b.yaml', 'c'])
    assert args.stopped and args.wait_for == '/ready' and args.namespace == '/simple_model'
    assert args.timeout == 12.5 and args.shutdown_timeout == 4.0
    assert args.controllers == ['a', 'b.yaml', 'c']


@pytest.mark.parametrize('argv', [['--no-timeout', 'a'], ['--timeout', '0', 'a'], ['--timeout', '-1', 'a'],
                                  ['--timeout', '5', '--no-timeout', 'a']])
def test_spawner_waits_indefinitely(argv):
    assert core.parse_spawner_args(argv).timeout is None


def test_spawner_shutdown_timeout_zero_is_unbounded():
    assert core.parse_spawner_args(['--shutdown-timeout', '0', 'a']).shutdown_timeout is None


def test_spawner_ignores_roslaunch_remappings():
    argv = ['arm_controller', '__name:=controller_spawner', '__log:=/root/.ros/log/x/spawner-1.log', '__ns:=/r']
    assert core.parse_spawner_args(argv).controllers == ['arm_controller']


def test_spawner_needs_a_controller(capsys):
    assert 'controller' in usage_error(core.parse_spawner_args, ['--stopped'], capsys)


def test_spawner_rejects_bad_timeout(capsys):
    err = usage_error(core.parse_spawner_args, ['--timeout', 'soon', 'a'], capsys)
    assert "expected a number of seconds, got 'soon'" in err


def test_strip_ros_args():
    assert core.strip_ros_args(['a', '_param:=1', 'b', '__name:=n']) == ['a', 'b']


# --- unspawner ------------------------------------------------------------------------------

def test_unspawner_flags():
    args = core.parse_unspawner_args(['--namespace', '/r', '--shutdown-timeout', '5', 'a', 'b', '__name:=u'])
    assert args.namespace == '/r' and args.shutdown_timeout == 5.0 and args.controllers == ['a', 'b']
    assert args.timeout == 30.0


def test_unspawner_defaults():
    args = core.parse_unspawner_args(['a'])
    assert args.namespace is None and args.shutdown_timeout == 2.0


def test_unspawner_needs_a_controller(capsys):
    usage_error(core.parse_unspawner_args, [], capsys)


# --- controller_manager command -------------------------------------------------------------

@pytest.mark.parametrize('command', ['load', 'unload', 'start', 'stop', 'spawn', 'kill'])
def test_cli_named_commands(command):
    args = core.parse_cli_args([command, 'a', 'b'])
    assert args.command == command and args.names == ['a', 'b'] and args.namespace is None


@pytest.mark.parametrize('alias,command', [('lc', 'list'), ('lt', 'list-types'), ('sp', 'spawn'), ('kl', 'kill')])
def test_cli_upstream_aliases(alias, command):
    argv = [alias] + (['x'] if command in core.CLI_NAMED else [])
    assert core.parse_cli_args(argv).command == command


def test_cli_options_anywhere():
    for argv in (['--namespace', '/simple_model', 'list'], ['list', '--namespace', '/simple_model'],
                 ['list', '--namespace=/simple_model']):
        args = core.parse_cli_args(argv)
        assert args.command == 'list' and args.namespace == '/simple_model' and args.names == []
    args = core.parse_cli_args(['load', 'a', '--timeout', '3', 'b'])
    assert args.names == ['a', 'b'] and args.timeout == 3.0


def test_cli_reload_restore():
    assert core.parse_cli_args(['reload-libraries']).restore is False
    assert core.parse_cli_args(['reload-libraries', '--restore']).restore is True


def test_cli_timeout_zero_waits_indefinitely():
    assert core.parse_cli_args(['--timeout', '0', 'list']).timeout is None


@pytest.mark.parametrize('argv,message', [
    (['frobnicate'], "unknown command 'frobnicate'"),
    (['load'], "'load' needs at least one controller name"),
    (['kill'], "'kill' needs at least one controller name"),
    (['list', 'extra'], "'list' takes no controller names"),
    (['start', 'a', '--restore'], '--restore goes with reload-libraries only'),
])
def test_cli_usage_errors(argv, message, capsys):
    assert message in usage_error(core.parse_cli_args, argv, capsys)


# --- the scripts themselves (argument handling happens before any ROS import) ---------------

def run_script(name, *argv):
    return subprocess.run([sys.executable, os.path.join(SCRIPTS, name)] + list(argv),
                          stdout=subprocess.PIPE, stderr=subprocess.PIPE, universal_newlines=True, timeout=60)


@pytest.mark.parametrize('name,flags', [
    ('spawner', ['--stopped', '--wait-for', '--namespace', '--timeout', '--no-timeout', '--shutdown-timeout']),
    ('unspawner', ['--namespace', '--shutdown-timeout']),
    ('controller_manager', ['load', 'unload', 'start', 'stop', 'spawn', 'kill', 'list', 'list-types',
                            'reload-libraries', '--restore', '--namespace']),
])
def test_script_help(name, flags):
    result = run_script(name, '--help')
    assert result.returncode == 0, result.stderr
    for flag in flags:
        assert flag in result.stdout


def test_controller_manager_without_command_prints_usage():
    result = run_script('controller_manager')
    assert result.returncode == 0
    assert 'Commands:' in result.stdout and 'list-types' in result.stdout


def test_scripts_usage_errors_exit_2():
    assert run_script('spawner').returncode == core.EXIT_BAD_ARGS
    assert run_script('unspawner').returncode == core.EXIT_BAD_ARGS
    result = run_script('controller_manager', 'frobnicate')
    assert result.returncode == core.EXIT_BAD_ARGS and "unknown command 'frobnicate'" in result.stderr
