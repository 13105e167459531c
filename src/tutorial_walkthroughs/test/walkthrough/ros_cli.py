"""What a user reads off the ROS command-line tools, typed into a UserSession and parsed."""
import math
import re
import subprocess
import time

import yaml

from user_session import CommandFailed


def echo_once(user, topic, timeout=30):
    """The next message on the topic, as `rostopic echo -n1` prints it (YAML), as a dict."""
    _, out = user.run('timeout %d rostopic echo -n1 %s' % (timeout, topic), timeout=timeout + 15)
    return yaml.safe_load(out.split('\n---')[0])


def call(user, service, request=''):
    """`rosservice call` and its YAML answer as a dict."""
    _, out = user.run("rosservice call %s %s" % (service, "'%s'" % request if request else ''), timeout=60)
    return yaml.safe_load(out)


def wait_for_service(user, service, timeout=60):
    """Until `rosservice info` finds the service."""
    poll(lambda: user.run('rosservice info %s' % service, check=False)[0] == 0, timeout, period=1.0,
         what='service %s' % service)


def rate(user, topic, window=2.0):
    """Mean rate as `rostopic hz` reports it after `window` seconds of listening (Hz)."""
    _, out = user.run('timeout -s INT %g rostopic hz %s || true' % (window + 1.5, topic), timeout=window + 30)
    rates = re.findall(r'average rate: ([0-9.]+)', out)
    if not rates:
        raise CommandFailed('`rostopic hz %s` reported no rate; it printed:\n%s' % (topic, out))
    return float(rates[-1])


def model_pose(user, model):
    """(x, y, z, yaw) of a model from /gazebo/get_model_state."""
    state = call(user, '/gazebo/get_model_state', '{model_name: %s}' % model)
    if not state['success']:
        raise CommandFailed('get_model_state %s: %s' % (model, state['status_message']))
    p, q = state['pose']['position'], state['pose']['orientation']
    yaw = math.atan2(2 * (q['w'] * q['z'] + q['x'] * q['y']), 1 - 2 * (q['y'] ** 2 + q['z'] ** 2))
    return p['x'], p['y'], p['z'], yaw


def wait_until(get, accept, timeout, what, period=0.5):
    """Calls get() until accept(its value) holds and returns that value; fails after timeout
    seconds, saying what was awaited and the last value seen."""
    deadline = time.monotonic() + timeout
    while True:
        value = get()
        if accept(value):
            return value
        if time.monotonic() > deadline:
            raise CommandFailed('%s did not happen within %.0f s (last: %r)' % (what, timeout, value))
        time.sleep(period)


def poll(check, timeout, period=0.5, what='condition'):
    """Until check() is true."""
    wait_until(check, bool, timeout, what, period)


def package_dir(name):
    """`rospack find NAME`: where a package of this workspace is."""
    return subprocess.check_output(['rospack', 'find', name], text=True).strip()


def simulator_running():
    """Whether a process named gzserver (the simulator, however it was started) runs."""
    return subprocess.run(['pgrep', '-x', 'gzserver'], stdout=subprocess.DEVNULL).returncode == 0
