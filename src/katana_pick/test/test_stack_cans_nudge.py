#!/usr/bin/env python3
"""stack_cans_nudge.test: of three cans, one stands 0.26 m from the base, nearer than any grasp
takes a can (0.315 m). stack_cans says so and nudges it outward along its line from the base
(the closed fingers pointing down, low on the can), looks again and sees it where a grasp takes it
(0.335 m, on the same line, upright), and then stacks all three into one upright tower.
Ground truth from /gazebo/get_model_state."""
import math
import re
import sys
import threading
import unittest

import rospy
import rostest
from geometry_msgs.msg import PoseArray

from bullet_sim_testing.gazebo import Gazebo
from stack_cans_run import Watch, run_until_stack_cans_exits, tower_faults, truth, wait_for_cans

NEAR = (0.2423, 0.0943)  # 0.26 m out, 0.371 rad
CANS = ['can_1', 'can_2', 'can_3']
TAKEN_FROM = 0.315  # katana_pick.reach: the nearest range a grasp takes a can at (5 mm grid)


class StackCansNudgeTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node('test_stack_cans_nudge')
        cls.lock = threading.Lock()
        cls.looks = []
        rospy.Subscriber('/stack_cans/cans', PoseArray, cls.keep_look, queue_size=10)
        cls.watch = Watch()
        cls.gazebo = Gazebo()
        wait_for_cans()
        cls.finished, cls.sim_seconds = run_until_stack_cans_exits()
        cls.reports = cls.watch.reports

    @classmethod
    def keep_look(cls, msg):
        with cls.lock:
            cls.looks.append([(p.position.x, p.position.y) for p in msg.poses])

    def truth(self, name):
        return truth(self.gazebo, name)

    def test_1_the_near_can_is_nudged_into_reach_and_seen_there(self):
        self.assertTrue(self.finished, 'stack_cans still running after 180 s')
        nudged = [r for r in self.reports if 'nudged outward' in r]
        self.assertEqual(len(nudged), 1, self.reports)
        said = re.search(r'([\d.]+) m from the base \(a grasp takes a can from ([\d.]+) m\): nudged outward', nudged[0])
        self.assertIsNotNone(said, nudged[0])
        self.assertAlmostEqual(float(said.group(1)), math.hypot(*NEAR), delta=0.005)  # as detected
        self.assertAlmostEqual(float(said.group(2)), TAKEN_FROM, delta=1e-6)
        self.assertEqual(len(self.looks), 2, 'a look before the nudge and one after')
        first, second = self.looks
        self.assertEqual(len(first), 3)
        self.assertEqual(len(second), 3)
        seen = min(first, key=lambda c: math.dist(c, NEAR))
        self.assertLess(math.dist(seen, NEAR), 0.005)
        # After the push: the can nearest its old spot is now where a grasp takes it, on its line.
        moved = min(second, key=lambda c: math.dist(c, NEAR))
        r, bearing = math.hypot(*moved), math.atan2(moved[1], moved[0])
        self.assertGreater(r, TAKEN_FROM)
        self.assertLess(r, 0.36)  # pushed to 0.335 m; it may slide on a little
        self.assertLess(abs(bearing - math.atan2(NEAR[1], NEAR[0])), 0.05)
        # The other two did not move.
        for can in first:
            if can != seen:
                self.assertLess(min(math.dist(can, c) for c in second), 0.005)

    def test_2_all_three_end_in_one_upright_tower(self):
        self.assertTrue(self.finished)
        self.assertEqual(tower_faults({n: self.truth(n) for n in CANS}), [])
        self.assertTrue(any(re.search(r'stacked (\d) of \1 cans on the tower \(3 high\)', r) for r in self.reports),
                        self.reports)


if __name__ == '__main__':
    rostest.rosrun('katana_pick', 'test_stack_cans_nudge', StackCansNudgeTest, sys.argv)
