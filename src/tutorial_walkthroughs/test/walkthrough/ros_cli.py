"""What a user reads off the ROS command-line tools, typed into a UserSession and parsed."""
import math
import re
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


def poll(check, timeout, period=0.5, what='condition'):
    """Calls check() until it returns a true value (which is returned); fails after timeout seconds."""
    deadline = time.monotonic() + timeout
    last = None
    while time.monotonic() < deadline:
        last = check()
        if last:
            return last
        time.sleep(period)
    raise CommandFailed('%s did not hold within %.0f s (last: %r)' % (what, timeout, last))
