#!/usr/bin/env python3
"""katana_pick.action_wait.wait_for_result against a real GripperCommand server in this node.

The race it guards against (a server answering before SimpleActionClient holds its goal handle)
is made certain, not left to chance: the client's send_goal is wrapped so that it returns only
once the goal's own state machine has seen the server's answer, as a descheduled client thread
would. Then SimpleActionClient.wait_for_result misses the result; ours does not."""
import sys
import time
import unittest

import actionlib
import rospy
import rostest
from actionlib import CommState
from control_msgs.msg import GripperCommandAction, GripperCommandGoal, GripperCommandResult

from katana_pick.action_wait import wait_for_result


class Server:
    """Answers each goal at once with position = the goal's position, except a negative position,
    which it accepts and never finishes."""

    def __init__(self, name):
        self.server = actionlib.ActionServer(name, GripperCommandAction, self.on_goal, auto_start=False)
        self.server.start()
        self.kept = []

    def on_goal(self, handle):
        handle.set_accepted()
        position = handle.get_goal().command.position
        if position < 0:
            self.kept.append(handle)
            return
        handle.set_succeeded(GripperCommandResult(position=position, reached_goal=True))


def client_that_loses_the_race(name):
    client = actionlib.SimpleActionClient(name, GripperCommandAction)
    assert client.wait_for_server(rospy.Duration(10))
    send = client.action_client.send_goal

    def send_then_wait_for_the_answer(*args, **kwargs):
        handle = send(*args, **kwargs)
        deadline = time.time() + 5
        while handle.get_comm_state() != CommState.DONE and time.time() < deadline:
            time.sleep(0.005)
        return handle

    client.action_client.send_goal = send_then_wait_for_the_answer
    return client


class ActionWaitTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node('test_action_wait')
        cls.server = Server('gripper')

    def goal(self, position):
        goal = GripperCommandGoal()
        goal.command.position = position
        return goal

    def test_plain_client_misses_a_result_that_came_before_it_held_the_goal(self):
        client = client_that_loses_the_race('gripper')
        client.send_goal(self.goal(0.3))
        start = time.time()
        self.assertFalse(client.wait_for_result(rospy.Duration(0.5)))
        self.assertGreaterEqual(time.time() - start, 0.45)

    def test_wait_for_result_sees_it_at_once_with_state_and_result(self):
        client = client_that_loses_the_race('gripper')
        client.send_goal(self.goal(0.25))
        start = time.time()
        self.assertTrue(wait_for_result(client, rospy.Duration(10)))
        self.assertLess(time.time() - start, 0.5)
        self.assertEqual(client.get_state(), actionlib.GoalStatus.SUCCEEDED)
        self.assertAlmostEqual(client.get_result().position, 0.25, places=6)

    def test_wait_for_result_on_a_plain_client_is_its_wait(self):
        client = actionlib.SimpleActionClient('gripper', GripperCommandAction)
        self.assertTrue(client.wait_for_server(rospy.Duration(10)))
        for position in (0.1, 0.2, 0.3):
            client.send_goal(self.goal(position))
            self.assertTrue(wait_for_result(client, rospy.Duration(10)))
            self.assertAlmostEqual(client.get_result().position, position, places=6)

    def test_a_goal_that_never_ends_times_out_after_the_timeout(self):
        client = actionlib.SimpleActionClient('gripper', GripperCommandAction)
        self.assertTrue(client.wait_for_server(rospy.Duration(10)))
        client.send_goal(self.goal(-1.0))
        start = time.time()
        self.assertFalse(wait_for_result(client, rospy.Duration(0.6)))
        self.assertGreaterEqual(time.time() - start, 0.55)
        self.assertLess(time.time() - start, 1.2)
        self.assertEqual(client.get_state(), actionlib.GoalStatus.ACTIVE)
        client.cancel_goal()


if __name__ == '__main__':
    rostest.rosrun('katana_pick', 'action_wait', ActionWaitTest, sys.argv)
