"""What the stack_cans rostests share: the scene's sizes, a can's tilt, and one run of
stack_cans.launch watched from outside (bring-up at the world's own pace, then as fast as it goes)."""
import math
import time

import rosnode
import rospy
from geometry_msgs.msg import PoseArray

from bullet_sim_testing.gazebo import set_real_time_factor

TABLE = 0.4         # katana_arm.launch's table_height: the arm's base and the cans stand on it
CAN_HEIGHT = 0.12


def tilt(orientation):
    """The angle between the can's axis and the vertical (rad)."""
    return 2 * math.asin(min(1.0, math.hypot(orientation.x, orientation.y)))


def wait_for_cans(timeout=60.0):
    """The cans stack_cans found (its latched ~cans); AssertionError if none came in `timeout` s."""
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        try:
            return rospy.wait_for_message('/stack_cans/cans', PoseArray, 0.5)
        except rospy.ROSException:
            pass
    raise AssertionError('stack_cans published no cans within %.0f s' % timeout)


def run_until_stack_cans_exits(timeout=180.0):
    """The simulation unthrottled until stack_cans exits: (whether it did within `timeout` wall
    seconds, the sim seconds that took)."""
    set_real_time_factor(0.0)
    start_sim = rospy.Time.now().to_sec()
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline and '/stack_cans' in rosnode.get_node_names():
        time.sleep(0.5)
    return '/stack_cans' not in rosnode.get_node_names(), rospy.Time.now().to_sec() - start_sim
