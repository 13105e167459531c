"""The loop find_frontier and explore share: at planner_frequency (sim time), and at once when a
goal ends, take the latest map and robot position, ask the Explorer, and act: send a goal, keep the
current one, wait (saying why), or report completion. ~status (std_msgs/String, latched) says
which: "exploring: ...", "waiting: ...", "complete: ...".

Goal outcomes arrive on actionlib's or rospy's threads; they are queued and handled by the loop,
so no callback ever sends a goal from inside another (explore_lite's deadlock workaround)."""
import ast
import math
import threading

import rospy
from std_msgs.msg import String
from visualization_msgs.msg import MarkerArray

from frontier_exploration.explorer import COMPLETE, KEEP, SEND, WAIT, ExplorerOptions
from frontier_exploration.frontiers import FrontierOptions
from frontier_exploration_ros.markers import frontier_markers

DEFAULT_ROBOT_RADIUS = 0.2  # m, when neither ~robot_radius nor move_base's footprint is set


def footprint_radius(move_base_ns):
    """The circumscribed radius of move_base's global costmap footprint (or robot_radius), with its
    padding, or None when move_base's parameters are not (yet) there."""
    ns = move_base_ns.rstrip('/') + '/global_costmap/'
    padding = float(rospy.get_param(ns + 'footprint_padding', 0.01))
    footprint = rospy.get_param(ns + 'footprint', None)
    if isinstance(footprint, str):
        try:
            footprint = ast.literal_eval(footprint)
        except (ValueError, SyntaxError):
            footprint = None
    if footprint:
        try:
            return max(math.hypot(float(x), float(y)) for x, y in footprint) + padding
        except (TypeError, ValueError):
            rospy.logwarn('%sfootprint: expected a list of [x, y] points, got %r' % (ns, footprint))
    if rospy.has_param(ns + 'robot_radius'):
        return float(rospy.get_param(ns + 'robot_radius'))
    return None


def explorer_options(ranking, min_distance, frontier_clearance):
    """ExplorerOptions from the node's private parameters (explore_lite's names, and ours); the
    clearance is left None for ExplorationNode to settle once move_base is up."""
    return ExplorerOptions(
        frontiers=FrontierOptions(min_distance=float(rospy.get_param('~min_distance', min_distance)),
                                  clearance=float(rospy.get_param('~frontier_clearance', frontier_clearance)),
                                  free_threshold=int(rospy.get_param('~free_threshold', 25)),
                                  occupied_threshold=int(rospy.get_param('~occupied_threshold', 65))),
        min_frontier_size=float(rospy.get_param('~min_frontier_size', 0.5)),
        clearance=None,
        approach_radius=float(rospy.get_param('~approach_radius', 1.0)),
        ranking=ranking,
        potential_scale=float(rospy.get_param('~potential_scale', 1e-3)),
        gain_scale=float(rospy.get_param('~gain_scale', 1.0)),
        progress_timeout=float(rospy.get_param('~progress_timeout', 30.0)),
        blacklist_radius=float(rospy.get_param('~blacklist_radius', 0.5)))


def robot_radius(move_base_ns):
    """~robot_radius, else move_base's footprint's circumscribed radius, else 0.2 m (said so)."""
    if rospy.has_param('~robot_radius'):
        return float(rospy.get_param('~robot_radius'))
    radius = footprint_radius(move_base_ns)
    if radius is None:
        rospy.loginfo('~robot_radius is not set and %s/global_costmap has no footprint: goals keep %.2f m from '
                      'walls' % (move_base_ns, DEFAULT_ROBOT_RADIUS))
        return DEFAULT_ROBOT_RADIUS
    return radius


class ExplorationNode:
    def __init__(self, explorer, maps, pose, goals_factory, planner_frequency, visualize, move_base_ns):
        self.explorer = explorer
        self.move_base_ns = move_base_ns
        self.maps, self.pose = maps, pose
        self.goals = goals_factory(self.on_finished)
        self.period = 1.0 / planner_frequency if planner_frequency > 0 else 1.0
        self.lock = threading.Lock()
        self.finished = []          # (number, outcome, time) not yet handled
        self.wake = threading.Event()
        self.active = None          # the number of our goal move_base is working on
        self.state = None           # (kind, message) last reported
        self.last_report = -math.inf
        self.status_pub = rospy.Publisher('~status', String, queue_size=1, latch=True)
        self.marker_pub = rospy.Publisher('~frontiers', MarkerArray, queue_size=1, latch=True) if visualize else None
        self.marker_count = 0

    def on_finished(self, number, outcome):
        with self.lock:
            self.finished.append((number, outcome, rospy.get_time()))
        self.wake.set()

    def spin(self):
        next_plan = -math.inf
        while not rospy.is_shutdown():
            woken = self.wake.wait(0.02)
            self.wake.clear()
            now = rospy.get_time()
            if now < next_plan - self.period:  # sim time went back (a world reset): plan now
                next_plan = now
            if now < next_plan and not woken:
                continue
            next_plan = now + self.period
            try:
                self.step(now)
            except Exception as e:  # a bad map or a bug must not end the exploration silently
                rospy.logerr_throttle(10.0, 'exploration step failed: %s: %s' % (type(e).__name__, e))

    def step(self, now):
        with self.lock:
            finished, self.finished = self.finished, []
        for number, outcome, at in finished:
            if number == self.active:
                self.active = None
            message = self.explorer.finished(number, outcome, at)
            if message:
                (rospy.loginfo if outcome in ('succeeded', 'preempted') else rospy.logwarn)(message)
        grid, frame, made_at = self.maps.grid()
        if grid is None:
            return self.report(WAIT, 'waiting for a map on %s' % self.maps.topic)
        why = self.goals.ready()
        if why:
            return self.report(WAIT, why)
        xy, why = self.pose.xy(frame)
        if xy is None:
            return self.report(WAIT, 'no robot position: %s' % why)
        if self.explorer.options.clearance is None:  # move_base is up: its footprint is on the server
            self.explorer.options.clearance = robot_radius(self.move_base_ns)
            rospy.loginfo('goals keep %.2f m from walls (the robot\'s radius)' % self.explorer.options.clearance)
        decision = self.explorer.plan(grid, xy, now, made_at)
        if decision.note:
            rospy.loginfo(decision.note)
        if self.marker_pub is not None:
            markers, self.marker_count = frontier_markers(decision.candidates, decision.grid, frame, decision.goal,
                                                          self.marker_count)
            self.marker_pub.publish(markers)
        if decision.kind == SEND:
            self.goals.send(decision.number, decision.goal, frame)
            self.active = decision.number
            self.report(SEND, decision.message)
        elif decision.kind == COMPLETE:
            if self.active is not None:
                self.goals.cancel()
                self.active = None
            self.report(COMPLETE, decision.message)
        elif decision.kind == WAIT:
            self.report(WAIT, decision.message)
        elif self.state is None or self.state[0] != SEND:  # KEEP after a wait: exploring again
            self.report(SEND, decision.message)

    def report(self, kind, message):
        """Log and publish a change of state. A new reason to wait is said at once; the same reason with
        other details (a tf error's times) at most every 10 s."""
        state = (kind, message)
        now = rospy.get_time()
        same_kind = self.state is not None and self.state[0] == kind
        same_reason = same_kind and message.split(':')[0] == self.state[1].split(':')[0]
        if state == self.state or (same_kind and kind == COMPLETE) or \
                (same_reason and kind == WAIT and now - self.last_report < 10):
            return
        self.state, self.last_report = state, now
        if kind == SEND:
            rospy.loginfo(message)
            text = 'exploring: ' + message
        elif kind == COMPLETE:
            e = self.explorer
            rospy.loginfo('%s (%d goals sent, %d reached, %d given up)' % (message, e.goals_sent, e.goals_reached,
                                                                             e.goals_failed))
            text = 'complete: ' + message
        else:
            rospy.logwarn(message)
            text = 'waiting: ' + message
        self.status_pub.publish(String(data=text))
