"""What the stack_cans rostests share: the scene's sizes, a can's tilt, the check of a tower, and
one run of stack_cans.launch watched from outside (bring-up at the world's own pace, then at the
test's real-time factor, unthrottled by default): its reports, grasp events and ground truth."""
import math
import threading
import time

import rosnode
import rospy
from gazebo_grasp_plugin_ros.msg import GazeboGraspEvent
from geometry_msgs.msg import PoseArray
from rosgraph_msgs.msg import Log

from bullet_sim_testing.gazebo import set_real_time_factor

TABLE = 0.4         # katana_arm.launch's table_height: the arm's base and the cans stand on it
CAN_HEIGHT = 0.12


def tilt(orientation):
    """The angle between the can's axis and the vertical (rad)."""
    return 2 * math.asin(min(1.0, math.hypot(orientation.x, orientation.y)))


# A can set on another stands at most this far off the axis of the can at the bottom: placed cans
# stand 1.2 mm off it on average, 1.9 mm at the 95th percentile (scripts/bench_katana_stacking.py,
# 147 cans in the old band); half a can radius (16 mm) would still stand but means a place went wrong.
TOWER_AXIS_TOLERANCE = 0.015


def tower_faults(poses):
    """What keeps `poses` ({name: pose}) from being one upright tower standing on the table, a
    can to a level, bottom first: one line per fault, each naming the can; empty if none."""
    column = sorted(poses, key=lambda n: poses[n].position.z)
    bottom = poses[column[0]].position
    faults = []
    for level, name in enumerate(column):
        p = poses[name]
        at = '%s at (%.4f, %.4f, %.4f)' % (name, p.position.x, p.position.y, p.position.z)
        if abs(p.position.z - (TABLE + level * CAN_HEIGHT)) > 0.005:
            faults.append('%s: not at level %d (z %.4f)' % (at, level, TABLE + level * CAN_HEIGHT))
        off = math.hypot(p.position.x - bottom.x, p.position.y - bottom.y)
        if off > TOWER_AXIS_TOLERANCE:
            faults.append('%s, level %d: %.1f mm off the axis of %s, the bottom can (at most %.0f mm)'
                          % (at, level, 1e3 * off, column[0], 1e3 * TOWER_AXIS_TOLERANCE))
        if tilt(p.orientation) > math.radians(3):
            faults.append('%s: tilted %.1f deg' % (at, math.degrees(tilt(p.orientation))))
    return faults


def wait_for_cans(timeout=60.0):
    """The cans stack_cans found (its latched ~cans); AssertionError if none came in `timeout` s."""
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        try:
            return rospy.wait_for_message('/stack_cans/cans', PoseArray, 0.5)
        except rospy.ROSException:
            pass
    raise AssertionError('stack_cans published no cans within %.0f s' % timeout)


def run_until_stack_cans_exits(timeout=180.0, real_time_factor=0.0):
    """The simulation at `real_time_factor` (0: unthrottled) until stack_cans exits: (whether it
    did within `timeout` wall seconds, the sim seconds that took)."""
    set_real_time_factor(real_time_factor)
    start_sim = rospy.Time.now().to_sec()
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline and '/stack_cans' in rosnode.get_node_names():
        time.sleep(0.5)
    return '/stack_cans' not in rosnode.get_node_names(), rospy.Time.now().to_sec() - start_sim


class Watch:
    """What a run shows from outside, kept from now on: stack_cans' reports on /rosout and the
    grasp fix's events."""

    def __init__(self):
        self.lock = threading.Lock()
        self.reports, self.events = [], []
        rospy.Subscriber('/rosout', Log, self._keep_report, queue_size=1000)
        rospy.Subscriber('/gazebo/grasp_events', GazeboGraspEvent, self._keep_event, queue_size=100)

    def _keep_report(self, msg):
        if msg.name == '/stack_cans':
            with self.lock:
                self.reports.append(msg.msg)

    def _keep_event(self, msg):
        with self.lock:
            self.events.append(msg)


def truth(gazebo, name):
    """A model's pose in the world, from /gazebo/get_model_state."""
    state = gazebo.state(name)
    assert state.success, name
    return state.pose
