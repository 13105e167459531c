"""Pure logic of the controller_manager tools: no ROS import, so it is testable without a master.

Argument parsing of `spawner`, `unspawner` and `controller_manager` (upstream ros_control's
flags), the controller manager's service and parameter names, controller names from YAML
files, the messages the tools print, and a bounded call for shutdown paths.
"""
import argparse
import os
import sys
import threading

EXIT_OK = 0
EXIT_FAILURE = 1
EXIT_BAD_ARGS = 2

# controller_manager_msgs/SwitchController constants (repeated so this module needs no ROS).
BEST_EFFORT = 1
STRICT = 2

PLUGIN_FILE = 'libgazebo_ros_control.so'
DEFAULT_TIMEOUT = 30.0
DEFAULT_SHUTDOWN_TIMEOUT = 2.0
PROGRESS_PERIOD = 5.0  # seconds between "still waiting" lines
YAML_SUFFIXES = ('.yaml', '.yml')


# ---------------------------------------------------------------------------------------------
# Arguments

def strip_ros_args(argv):
    """argv without ROS remappings (`__name:=x`, `__log:=...`, `a:=b`), like rospy.myargv."""
    return [a for a in argv if ':=' not in a]


def _timeout(value):
    """A timeout flag's value: seconds > 0, or None (wait indefinitely) for <= 0."""
    return value if value is not None and value > 0 else None


def _float_arg(text):
    try:
        return float(text)
    except ValueError:
        raise argparse.ArgumentTypeError("expected a number of seconds, got '%s'" % text)


def spawner_parser():
    parser = argparse.ArgumentParser(
        prog='spawner',
        description='Loads and starts controllers in a controller manager; on shutdown (Ctrl-C, roslaunch '
                    'stop, rosnode kill) stops and unloads them again.',
        epilog='An argument ending in .yaml is a controller configuration file: it is loaded onto the parameter '
               'server (into the controller manager\'s namespace) and its top-level keys are the controllers to '
               'spawn.')
    parser.add_argument('--stopped', action='store_true', help='loads controllers, but does not start them')
    parser.add_argument('--wait-for', metavar='topic',
                        help='does not load or start controllers until it hears "True" on a topic (std_msgs/Bool; '
                             'a topic of another type: any message)')
    parser.add_argument('--namespace', metavar='ns',
                        help="namespace of the controller_manager services (default: the node's namespace)")
    parser.add_argument('--timeout', metavar='T', type=_float_arg, default=DEFAULT_TIMEOUT,
                        help='how long to wait for the controller_manager services (and /clock when use_sim_time '
                             'is true) when starting up [s] (default: %g). <=0 waits indefinitely.'
                             % DEFAULT_TIMEOUT)
    parser.add_argument('--no-timeout', action='store_true',
                        help='wait for controller_manager services indefinitely (same as `--timeout 0`)')
    parser.add_argument('--shutdown-timeout', metavar='T', type=_float_arg, default=DEFAULT_SHUTDOWN_TIMEOUT,
                        help='bound of each service call (stop, unload) when shutting down [s] (default: %g). '
                             '<=0 waits indefinitely.' % DEFAULT_SHUTDOWN_TIMEOUT)
    parser.add_argument('controllers', metavar='controller', nargs='+',
                        help='controllers to load (names, or .yaml configuration files)')
    return parser


def parse_spawner_args(argv):
    """Spawner flags (argv without the program name); timeouts <= 0 become None."""
    args = spawner_parser().parse_args(strip_ros_args(argv))
    args.timeout = None if args.no_timeout else _timeout(args.timeout)
    args.shutdown_timeout = _timeout(args.shutdown_timeout)
    return args


def unspawner_parser():
    parser = argparse.ArgumentParser(
        prog='unspawner',
        description='Stops a set of controllers until killed, then starts them again. Useful in roslaunch files to '
                    'temporarily stop controllers.')
    parser.add_argument('--namespace', metavar='ns',
                        help="namespace of the controller_manager services (default: the node's namespace)")
    parser.add_argument('--timeout', metavar='T', type=_float_arg, default=DEFAULT_TIMEOUT,
                        help='how long to wait for the controller_manager services when starting up [s] '
                             '(default: %g). <=0 waits indefinitely.' % DEFAULT_TIMEOUT)
    parser.add_argument('--shutdown-timeout', metavar='T', type=_float_arg, default=DEFAULT_SHUTDOWN_TIMEOUT,
                        help='bound of the service call that restarts the controllers on shutdown [s] '
                             '(default: %g). <=0 waits indefinitely.' % DEFAULT_SHUTDOWN_TIMEOUT)
    parser.add_argument('controllers', metavar='controller', nargs='+', help='controllers to stop')
    return parser


def parse_unspawner_args(argv):
    args = unspawner_parser().parse_args(strip_ros_args(argv))
    args.timeout = _timeout(args.timeout)
    args.shutdown_timeout = _timeout(args.shutdown_timeout)
    return args


CLI_COMMANDS = ('load', 'unload', 'start', 'stop', 'spawn', 'kill', 'list', 'list-types', 'reload-libraries')
CLI_ALIASES = {'lc': 'list', 'lt': 'list-types', 'sp': 'spawn', 'kl': 'kill'}  # upstream's short forms
CLI_NAMED = ('load', 'unload', 'start', 'stop', 'spawn', 'kill')

CLI_USAGE = """usage: controller_manager [--namespace NS] [--timeout T] <command> [args]

Commands:
    load <name>...       - Load the controllers named <name>
    unload <name>...     - Unload the controllers named <name>
    start <name>...      - Start the controllers named <name>
    stop <name>...       - Stop the controllers named <name>
    spawn <name>...      - Load and start the controllers named <name>
    kill <name>...       - Stop and unload the controllers named <name>
    list                 - List active controllers
    list-types           - List controller Types
    reload-libraries     - Reloads all plugin controller libraries
                           (--restore: reload the controllers and restart the running ones afterwards)

The services are <namespace>/controller_manager/*: NS, else the node's namespace
(ROS_NAMESPACE=/my_robot or __ns:=/my_robot).
Options:
    --namespace NS       namespace of the controller_manager services
    --timeout T          how long to wait for a service [s] (default: %g; <=0 waits indefinitely)
""" % DEFAULT_TIMEOUT


class _CliParser(argparse.ArgumentParser):
    def format_usage(self):
        return CLI_USAGE.splitlines()[0] + '\n'

    def format_help(self):
        return CLI_USAGE


def cli_parser():
    parser = _CliParser(prog='controller_manager', add_help=True)
    parser.add_argument('--namespace', metavar='NS')
    parser.add_argument('--timeout', metavar='T', type=_float_arg, default=DEFAULT_TIMEOUT)
    parser.add_argument('--restore', action='store_true')
    parser.add_argument('command')
    parser.add_argument('names', nargs='*')
    return parser


def parse_cli_args(argv):
    """`controller_manager` arguments; exits with EXIT_BAD_ARGS and a usage line on errors.

    Options may stand anywhere (`controller_manager list --namespace /robot`). Upstream's
    short forms lc, lt, sp, kl are accepted.
    """
    parser = cli_parser()
    args = parser.parse_intermixed_args(strip_ros_args(argv))
    args.command = CLI_ALIASES.get(args.command, args.command)
    if args.command not in CLI_COMMANDS:
        parser.error("unknown command '%s' (expected one of: %s)" % (args.command, ', '.join(CLI_COMMANDS)))
    if args.command in CLI_NAMED and not args.names:
        parser.error("'%s' needs at least one controller name" % args.command)
    if args.command not in CLI_NAMED and args.names:
        parser.error("'%s' takes no controller names (got: %s)" % (args.command, ' '.join(args.names)))
    if args.restore and args.command != 'reload-libraries':
        parser.error("--restore goes with reload-libraries only")
    args.timeout = _timeout(args.timeout)
    return args


# ---------------------------------------------------------------------------------------------
# Names

def controller_manager_namespace(namespace):
    """The controller manager's namespace for --namespace (None/'' -> relative 'controller_manager',
    resolved in the node's namespace; '/robot' or '/robot/' -> '/robot/controller_manager')."""
    if not namespace:
        return 'controller_manager'
    stripped = namespace.rstrip('/')
    if not stripped:  # '/'
        return '/controller_manager'
    return stripped + '/controller_manager'


def service_name(namespace, service):
    """Name of one controller manager service, e.g. ('/robot', 'load_controller')."""
    return controller_manager_namespace(namespace) + '/' + service


def robot_namespace_of(resolved_service):
    """'/robot/controller_manager/load_controller' -> '/robot'; '/controller_manager/x' -> '/'."""
    parts = resolved_service.rstrip('/').split('/')
    ns = '/'.join(parts[:-2])
    return ns if ns else '/'


def other_controller_managers(service_names, wanted_service):
    """Namespaces of the controller managers whose load_controller is in service_names, other than
    the one of wanted_service (a fully resolved load_controller name), sorted."""
    found = set()
    for name in service_names:
        if name.endswith('/controller_manager/load_controller') and name != wanted_service:
            found.add(robot_namespace_of(name))
    return sorted(found)


# ---------------------------------------------------------------------------------------------
# Controller arguments and YAML files

def is_yaml_argument(arg, isfile=os.path.isfile):
    """A controller configuration file rather than a controller name: a name ending in .yaml/.yml,
    or (upstream's test) an existing file."""
    return arg.lower().endswith(YAML_SUFFIXES) or isfile(arg)


def controller_names_from_params(params, source='the YAML file'):
    """The controller names a YAML configuration defines: its top-level keys, in file order.

    Raises ValueError when the document is not a mapping (nothing to spawn)."""
    if not isinstance(params, dict) or not params:
        raise ValueError("%s defines no controllers: expected a mapping whose top-level keys are controller names "
                         "(e.g. 'joint_state_controller: {type: joint_state_controller/JointStateController}')"
                         % source)
    return [str(key) for key in params]


def unique(names):
    """names without repeats, first occurrence kept."""
    seen = set()
    out = []
    for n in names:
        if n not in seen:
            seen.add(n)
            out.append(n)
    return out


# ---------------------------------------------------------------------------------------------
# Messages

def join_names(names):
    return ', '.join(names)


def loaded_message(names):
    return 'Controller Spawner: Loaded controllers: %s' % join_names(names)


def started_message(names):
    return 'Started controllers: %s' % join_names(names)


def _seconds(value):
    return '%g s' % value


def waiting_message(what, waited, timeout):
    """The periodic line while waiting, e.g. 'waiting for service /r/controller_manager/load_controller
    (5 s so far, giving up after 30 s)'."""
    limit = 'giving up after %s' % _seconds(timeout) if timeout else 'no timeout'
    return 'still waiting for %s (%s so far, %s)' % (what, _seconds(round(waited)), limit)


def missing_service_message(service, timeout, other_managers, master_uri=None, master_reachable=True):
    """Why the controller manager was not found: which service, the plugin hint, and the namespaces
    where controller managers do run (the usual cause is a namespace mismatch)."""
    if not master_reachable:
        return ('Timed out after %s waiting for service %s: cannot reach the ROS master%s. Is roscore (or the '
                'launch file that starts it) running?' % (_seconds(timeout), service,
                                                          ' at ' + master_uri if master_uri else ''))
    ns = robot_namespace_of(service)
    lines = ['Timed out after %s waiting for service %s: no controller manager runs in namespace %s.'
             % (_seconds(timeout), service, ns),
             "The simulator starts one for each spawned robot whose URDF has the ros_control plugin, with the "
             "robot's namespace:",
             '    <gazebo><plugin name="gazebo_ros_control" filename="%s"><robotNamespace>%s</robotNamespace>'
             '</plugin></gazebo>' % (PLUGIN_FILE, ns)]
    if other_managers:
        lines.append('Controller managers that do run: %s. Use the matching namespace (ns="..." on the <node>, '
                     'ROS_NAMESPACE or --namespace), or change <robotNamespace>.'
                     % join_names(m.rstrip('/') + '/controller_manager' for m in other_managers))
    else:
        lines.append('No controller manager runs at all: is the simulator running, and was the robot spawned '
                     '(spawn_model) with that plugin in its URDF?')
    return '\n'.join(lines)


def missing_clock_message(timeout):
    return ('Timed out after %s waiting for /clock: /use_sim_time is true but nothing publishes simulated time. '
            'Is the simulator running (it publishes /clock, also while paused)? Otherwise set /use_sim_time '
            'to false.' % _seconds(timeout))


def reason_lines(reasons, source_node=None):
    """The controller manager's explanation of a failed call, or where to look for it."""
    if not reasons:
        return ["The controller manager logged no reason; see its output (the simulator's console, or "
                "rqt_console / rostopic echo /rosout_agg)."]
    lines = ['The controller manager%s says:' % (' (%s)' % source_node if source_node else '')]
    lines.extend('    ' + line for reason in reasons for line in reason.splitlines())
    return lines


def failure_message(action, names, service, reasons, source_node=None):
    """A failed controller manager call: what failed, the service's answer (ok: False) and the reason
    the controller manager logged for it (its ROS_ERROR/ROS_WARN lines)."""
    what = "'%s'" % names if isinstance(names, str) else '[%s]' % join_names("'%s'" % n for n in names)
    lines = ['Failed to %s %s: %s answered ok: False.' % (action, what, service)]
    return '\n'.join(lines + reason_lines(reasons, source_node))


# `controller_manager` command lines, as upstream prints them.
def cli_loaded(name):
    return "Loaded '%s'" % name


def cli_load_error(name):
    return "Error when loading '%s'" % name


def cli_unloaded(name):
    return "Unloaded '%s' successfully" % name


def cli_unload_error(name):
    return "Error when unloading '%s'" % name


def cli_switched(start, stop):
    lines = []
    if start:
        lines.append('Started {} successfully'.format(list(start)))
    if stop:
        lines.append('Stopped {} successfully'.format(list(stop)))
    return lines


def cli_switch_error(start, stop):
    return 'Error when starting {} and stopping {}'.format(list(start), list(stop))


def missing_type_hint(name, param_ns):
    """Hint when <ns>/<name>/type is not on the parameter server."""
    ns = param_ns.rstrip('/')
    return ("Hint: there is no parameter %s/%s/type: load the controller's configuration into %s first "
            "(<rosparam file=\"...yaml\" command=\"load\"/> in that namespace, or give the .yaml file to the "
            "spawner)." % (ns, name, ns or '/'))


# rosgraph_msgs/Log levels
LOG_WARN = 4


def select_reasons(entries, since, source_node=None, own_node=None, min_level=LOG_WARN):
    """The log lines that explain a failed call: entries are (received_wall_time, node, level, text)
    received at or after `since`, from source_node when known (else from any node but our own),
    at level min_level (WARN) or above; repeats removed."""
    out = []
    for received, node, level, text in entries:
        if received < since or level < min_level:
            continue
        if source_node is not None and node != source_node:
            continue
        if source_node is None and own_node is not None and node == own_node:
            continue
        if text not in out:
            out.append(text)
    return out


def wait_for_message_satisfied(msg_type, buff):
    """--wait-for: a std_msgs/Bool counts when it is True (upstream); any other type counts on arrival."""
    if msg_type == 'std_msgs/Bool':
        return bool(buff) and buff[0] != 0
    return True


def list_lines(controllers):
    """`controller_manager list` output as upstream: "'name' - 'hw_interface+...' ( state )" per
    controller (the hardware interfaces it claims), or the upstream sentence when none is loaded."""
    if not controllers:
        return ['No controllers are loaded in mechanism control']
    lines = []
    for c in controllers:
        interfaces = unique(r.hardware_interface for r in c.claimed_resources)
        lines.append("'%s' - '%s' ( %s )" % (c.name, '+'.join(interfaces), c.state))
    return lines


# ---------------------------------------------------------------------------------------------
# Bounded calls

class CallTimeout(Exception):
    pass


def call_with_timeout(fn, limit, *args, **kwargs):
    """fn(*args, **kwargs), giving up after `limit` seconds (None: wait indefinitely). (Not named
    `timeout`: SwitchController has a field of that name, passed as a keyword.)

    The call runs in a daemon thread so that a controller manager (or master) that is gone or
    hung cannot hold up shutdown; raises CallTimeout on timeout, else returns fn's result or
    raises its exception."""
    if limit is None:
        return fn(*args, **kwargs)
    result = {}

    def run():
        try:
            result['value'] = fn(*args, **kwargs)
        except BaseException as exc:  # noqa: B902 - handed to the caller
            result['error'] = exc

    thread = threading.Thread(target=run, name='bounded-call', daemon=True)
    thread.start()
    thread.join(limit)
    if thread.is_alive():
        raise CallTimeout('no answer within %s' % _seconds(limit))
    if 'error' in result:
        raise result['error']
    return result.get('value')


def print_err(*lines):
    for line in lines:
        sys.stderr.write(line + '\n')
    sys.stderr.flush()
