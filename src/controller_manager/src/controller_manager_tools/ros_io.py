"""The ROS side of the controller_manager tools: waiting (for the master, services, /clock, a
topic) with progress lines and clear timeouts, calls bounded in time, and the controller
manager's own log lines as the reason of a failed call.

All waits use wall time, so a paused simulation (use_sim_time, /clock standing still) cannot
stall them.
"""
import threading
import time

import rosgraph
import rospy
from rosgraph_msgs.msg import Clock, Log

from controller_manager_tools import core


class Interrupted(Exception):
    """The node is shutting down (Ctrl-C, roslaunch stop, rosnode kill) while waiting."""


class WaitTimeout(Exception):
    """A wait gave up; the message says what was missing and what to check."""


class Progress(object):
    """Says every few seconds what is still awaited: every PROGRESS_PERIOD s for the first
    minute, then every 30 s."""

    def __init__(self, what, timeout, say):
        self.what, self.timeout, self.say = what, timeout, say
        self.start = time.time()
        self.next = self.start + core.PROGRESS_PERIOD

    def waited(self):
        return time.time() - self.start

    def expired(self):
        return self.timeout is not None and self.waited() >= self.timeout

    def remaining(self):
        return None if self.timeout is None else max(0.0, self.timeout - self.waited())

    def tick(self):
        now = time.time()
        if now >= self.next:
            self.say(core.waiting_message(self.what, now - self.start, self.timeout))
            period = core.PROGRESS_PERIOD if now - self.start < 60 else 30.0
            while self.next <= now:
                self.next += period


def master_uri():
    return rosgraph.get_master_uri()


def master_online():
    try:
        return rosgraph.is_master_online()
    except Exception:  # noqa: BLE001 - any failure means "not reachable"
        return False


def wait_for_master(timeout, say):
    """Blocks until the ROS master answers (rospy.init_node would hang silently without one)."""
    if master_online():
        return
    progress = Progress('the ROS master at %s (is roscore running?)' % master_uri(), timeout, say)
    while not master_online():
        if progress.expired():
            raise WaitTimeout('Timed out after %g s waiting for the ROS master at %s: is roscore (or the launch '
                              'file that starts it) running?' % (timeout, master_uri()))
        progress.tick()
        time.sleep(0.2)


def system_services():
    """[(service, [providing nodes])] from the master; [] when it cannot be asked."""
    try:
        _, _, services = rosgraph.Master(rospy.get_name()).getSystemState()
        return services
    except Exception:  # noqa: BLE001
        return []


def service_node(service):
    for name, nodes in system_services():
        if name == service and nodes:
            return nodes[0]
    return None


def wait_for_services(services, timeout, say):
    """Waits until every (resolved) service in `services` answers a probe, all within one timeout.

    Raises WaitTimeout naming the first missing service, with the plugin/namespace hint and the
    namespaces where controller managers do run; Interrupted on shutdown."""
    progress = None
    for service in services:
        if progress is None:
            progress = Progress('service ' + service, timeout, say)
        else:
            progress.what = 'service ' + service
        while True:
            if rospy.is_shutdown():
                raise Interrupted()
            remaining = progress.remaining()
            if remaining is not None and remaining <= 0:
                raise WaitTimeout(missing_service_text(service, timeout))
            try:
                rospy.wait_for_service(service, timeout=min(0.5, remaining) if remaining else 0.5)
                break
            except rospy.ROSInterruptException:
                raise Interrupted()
            except rospy.ROSException:
                progress.tick()


def missing_service_text(service, timeout):
    reachable = master_online()
    others = core.other_controller_managers([name for name, _ in system_services()], service) if reachable else []
    return core.missing_service_message(service, timeout, others, master_uri(), reachable)


def use_sim_time():
    value = rospy.get_param('/use_sim_time', False)
    if isinstance(value, str):
        return value.strip().lower() in ('true', '1', 'yes')
    return bool(value)


def wait_for_clock(timeout, say):
    """With use_sim_time: blocks until /clock publishes (a paused simulator publishes it too)."""
    heard = threading.Event()
    sub = rospy.Subscriber('/clock', Clock, lambda _msg: heard.set(), queue_size=1)
    try:
        progress = Progress('the first message on /clock (/use_sim_time is true)', timeout, say)
        while not heard.is_set() and rospy.get_rostime().is_zero():
            if rospy.is_shutdown():
                raise Interrupted()
            if progress.expired():
                raise WaitTimeout(core.missing_clock_message(timeout))
            progress.tick()
            heard.wait(0.1)
    finally:
        sub.unregister()


def wait_for_topic(topic, timeout, say, warn):
    """--wait-for: blocks until `topic` says True (std_msgs/Bool) or, for other types, publishes.
    As upstream, it keeps waiting past the timeout, with a warning."""
    done = threading.Event()

    def callback(msg):
        msg_type = (getattr(msg, '_connection_header', None) or {}).get('type', '')
        if core.wait_for_message_satisfied(msg_type, msg._buff):
            done.set()

    sub = rospy.Subscriber(topic, rospy.AnyMsg, callback, queue_size=10)
    resolved = rospy.resolve_name(topic)
    try:
        progress = Progress('"True" on the wait-for topic %s' % resolved, None, say)
        warned = False
        while not done.is_set():
            if rospy.is_shutdown():
                raise Interrupted()
            if not warned and timeout is not None and progress.waited() > timeout:
                warned = True
                warn('Controller Spawner has not heard "True" from its "wait for" topic (%s) after %g s; still '
                     'waiting' % (resolved, timeout))
            progress.tick()
            done.wait(0.05)
    finally:
        sub.unregister()


class Reasons(object):
    """Collects the controller manager's warning and error lines from /rosout_agg: the services'
    answers are only `ok: False`, the reason is what the controller manager logs (as ros_control's
    does). Subscribe early; reasons(since) then returns the lines logged since a call started."""

    TOPIC = '/rosout_agg'
    KEEP = 200

    def __init__(self):
        self._lock = threading.Lock()
        self._entries = []
        self.source_node = None
        self._sub = rospy.Subscriber(self.TOPIC, Log, self._callback, queue_size=100)

    def _callback(self, msg):
        with self._lock:
            self._entries.append((time.time(), msg.name, msg.level, msg.msg))
            del self._entries[:-self.KEEP]

    def set_source(self, service):
        """The node that offers `service` (e.g. /gazebo): only its lines count."""
        self.source_node = service_node(service)

    def wait_connected(self, timeout=1.0):
        deadline = time.time() + timeout
        while self._sub.get_num_connections() == 0 and time.time() < deadline and not rospy.is_shutdown():
            time.sleep(0.02)

    def _select(self, since):
        with self._lock:
            entries = list(self._entries)
        return core.select_reasons(entries, since, self.source_node, rospy.get_name())

    def reasons(self, since, grace=1.0):
        """Lines logged since `since` (a time.time()); waits up to `grace` s for the first one
        (rosout is asynchronous), then briefly for the lines that follow it."""
        deadline = time.time() + grace
        found = self._select(since)
        while not found and time.time() < deadline and not rospy.is_shutdown():
            time.sleep(0.05)
            found = self._select(since)
        if found:
            time.sleep(0.15)
            found = self._select(since)
        return found


def bounded_call(proxy, limit, *args, **kwargs):
    """proxy(*args, **kwargs) within `limit` seconds (None: unbounded); CallTimeout or the call's exception."""
    return core.call_with_timeout(proxy, limit, *args, **kwargs)
