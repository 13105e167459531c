#!/usr/bin/env python3
"""find_frontier's faults, staged by the test (which stands in for the mapper and move_base): move_base
not running yet, a goal sent once and not re-sent, an aborted goal given up for the next frontier,
the map changing size and origin (a mapper reset), and a robot boxed in: each with its message on
~status, the node alive and no goal off the free cells."""
import math
import time
import unittest

import numpy as np
import rospy
import rostest
from actionlib_msgs.msg import GoalStatus
from geometry_msgs.msg import PoseStamped
from move_base_msgs.msg import MoveBaseActionGoal, MoveBaseActionResult
from nav_msgs.msg import OccupancyGrid
from std_msgs.msg import String

U, F, O = -1, 0, 100
RES = 0.05


def room(origin=(0.0, 0.0), pad=0, closed=False):
    """A walled 2 x 2 m room (cells 0-40) with a 1 m opening east (rows 10-29) and a 0.5 m one north
    (columns 25-34), unknown beyond, `pad` unknown cells round it (the origin moved to match)."""
    g = np.full((46, 46), U)
    g[0:41, 0:41] = O
    g[1:40, 1:40] = F
    if not closed:
        g[10:30, 40] = F
        g[40, 25:35] = F
    g = np.pad(g, pad, constant_values=U)
    msg = OccupancyGrid()
    msg.header.frame_id = 'map'
    msg.info.resolution = RES
    msg.info.height, msg.info.width = g.shape
    msg.info.origin.position.x, msg.info.origin.position.y = origin[0] - pad * RES, origin[1] - pad * RES
    msg.info.origin.orientation.w = 1.0
    msg.data = g.ravel().tolist()
    return msg, g


class FindFrontierFaults(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node('find_frontier_fault_checks')
        cls.statuses = []
        rospy.Subscriber('/find_frontier/status', String, lambda m: cls.statuses.append(m.data), queue_size=10)
        cls.map_pub = rospy.Publisher('/map', OccupancyGrid, queue_size=1, latch=True)
        cls.action_goal_pub = rospy.Publisher('/move_base/goal', MoveBaseActionGoal, queue_size=10)
        cls.result_pub = rospy.Publisher('/move_base/result', MoveBaseActionResult, queue_size=10)
        cls.goals = []
        cls.msg, cls.grid = room()

    def wait_for(self, predicate, timeout=10.0):
        end = time.time() + timeout
        while time.time() < end and not predicate():
            time.sleep(0.05)
        return predicate()

    def on_goal(self, pose):
        """As move_base does with move_base_simple/goal: an action goal with an id of its own."""
        goal_id = 'goal_%d' % (len(self.goals) + 1)
        self.goals.append((goal_id, pose))
        action_goal = MoveBaseActionGoal()
        action_goal.goal_id.id = goal_id
        action_goal.goal.target_pose = pose
        self.action_goal_pub.publish(action_goal)

    def finish(self, goal_id, status):
        result = MoveBaseActionResult()
        result.status.goal_id.id = goal_id
        result.status.status = status
        self.result_pub.publish(result)

    def assert_on_free_cell(self, pose, grid, origin=(0.0, 0.0)):
        col = int(math.floor((pose.pose.position.x - origin[0]) / RES))
        row = int(math.floor((pose.pose.position.y - origin[1]) / RES))
        self.assertEqual(grid[row, col], F, 'goal (%.2f, %.2f)' % (pose.pose.position.x, pose.pose.position.y))

    def test_1_without_move_base_it_waits_and_says_why(self):
        # No map yet: it says so. Once the map comes, the new reason (no move_base) is said at once (within
        # a few planning rounds of 0.2 s), not held back by the 10 s between repeats of one reason.
        self.assertTrue(self.wait_for(lambda: self.statuses, timeout=30.0), 'no status')
        self.assertEqual(self.statuses, ['waiting: waiting for a map on /map'])
        self.map_pub.publish(self.msg)
        sent = time.time()
        expected = 'waiting: waiting for move_base: nothing subscribes to /move_base_simple/goal'
        self.assertTrue(self.wait_for(lambda: self.statuses[-1] == expected), self.statuses)
        self.assertLess(time.time() - sent, 3.0)
        self.assertEqual(self.statuses, ['waiting: waiting for a map on /map', expected])

    def test_2_a_goal_is_sent_once_on_a_free_cell(self):
        self.__class__.sub = rospy.Subscriber('/move_base_simple/goal', PoseStamped, self.on_goal, queue_size=10)
        self.assertTrue(self.wait_for(lambda: self.goals))
        goal_id, pose = self.goals[0]
        self.assertEqual(pose.header.frame_id, 'map')
        self.assert_on_free_cell(pose, self.grid)
        self.assertGreater(pose.pose.position.x, 1.7)  # at the larger (east) opening
        self.assertTrue(self.wait_for(lambda: self.statuses[-1].startswith('exploring: goal 1: (')), self.statuses[-1])
        self.map_pub.publish(self.msg)  # the same map again, as the mapper sends it every 2 s
        time.sleep(2.0)                 # 10 planning rounds
        self.assertEqual(len(self.goals), 1)

    def test_3_an_aborted_goal_is_given_up_for_the_next_frontier(self):
        self.finish(self.goals[0][0], GoalStatus.ABORTED)
        self.assertTrue(self.wait_for(lambda: len(self.goals) == 2))
        pose = self.goals[1][1]
        self.assert_on_free_cell(pose, self.grid)
        self.assertGreater(pose.pose.position.y, 1.7)  # the north opening
        self.assertTrue(self.wait_for(lambda: self.statuses[-1].startswith('exploring: goal 2: (')), self.statuses[-1])

    def test_4_a_map_of_another_size_and_origin_is_taken_as_it_comes(self):
        # The mapper restarted with a bigger map whose origin moved: the same room, in the same place.
        msg, grid = room(pad=20)
        self.map_pub.publish(msg)
        self.finish(self.goals[1][0], GoalStatus.PREEMPTED)  # someone else's goal took over: not given up
        self.assertTrue(self.wait_for(lambda: len(self.goals) == 3))
        pose = self.goals[2][1]
        self.assert_on_free_cell(pose, grid, origin=(-20 * RES, -20 * RES))
        self.assertGreater(pose.pose.position.y, 1.7)  # the north opening again (the east one is given up)

    def test_5_a_closed_room_is_complete(self):
        msg, _ = room(closed=True)
        self.map_pub.publish(msg)
        self.assertTrue(self.wait_for(lambda: self.statuses[-1].startswith('complete')), self.statuses[-1])
        self.assertEqual(self.statuses[-1], 'complete: exploration complete: no frontier left')
        self.assertEqual(len(self.goals), 3)


if __name__ == '__main__':
    rostest.rosrun('find_frontier', 'test_find_frontier_faults', FindFrontierFaults)
