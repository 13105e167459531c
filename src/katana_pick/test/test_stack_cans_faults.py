#!/usr/bin/env python3
"""stack_cans with faults: of four cans, can_4 stands beyond the arm's reach and can_3 is deleted
from the world as soon as stack_cans has seen it. stack_cans skips can_4 and says why, fails to
grip can_3, backs off, looks again, reports it gone, and still puts can_1 on the tower (can_2);
can_4 is never touched. Ground truth from /gazebo/get_model_state, the reports from /rosout."""
import math
import re
import sys
import unittest

import rospy
import rostest

from bullet_sim_testing.gazebo import Gazebo
from stack_cans_run import TABLE, Watch, run_until_stack_cans_exits, tower_faults, truth, wait_for_cans

LAYOUT = {'can_1': (0.31, -0.18), 'can_2': (0.38, 0.0), 'can_3': (0.31, 0.18), 'can_4': (0.45, -0.45)}


class StackCansFaultsTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node('test_stack_cans_faults')
        cls.watch = Watch()
        cls.gazebo = Gazebo()
        cls.detected = wait_for_cans()
        cls.deleted = cls.gazebo.delete_model(model_name='can_3').success
        cls.finished, _ = run_until_stack_cans_exits()
        cls.events, cls.reports = cls.watch.events, cls.watch.reports

    def truth(self, name):
        return truth(self.gazebo, name)

    def reported(self, pattern, can=None):
        """The reports with every string of pattern in them and, given a can's (x, y), about a can
        found within 5 mm of it (test_1's bound: the report prints what detection saw)."""
        def about(report):
            at = re.search(r'can at \((-?[0-9.]+), (-?[0-9.]+)\)', report)
            return at is not None and math.dist(can, (float(at.group(1)), float(at.group(2)))) < 0.005
        return [r for r in self.reports if all(p in r for p in pattern) and (can is None or about(r))]

    def test_1_all_four_cans_are_seen(self):
        self.assertTrue(self.deleted)
        seen = [(p.position.x, p.position.y) for p in self.detected.poses]
        self.assertEqual(len(seen), 4)
        for name, xy in LAYOUT.items():
            self.assertLess(min(math.dist(xy, s) for s in seen), 0.005, name)

    def test_2_the_can_out_of_reach_is_skipped_with_the_reason_and_left_alone(self):
        self.assertTrue(self.finished, 'stack_cans still running after 180 s')
        self.assertTrue(self.reported(['unreachable, skipped', 'out of reach by'], LAYOUT['can_4']), self.reports)
        p = self.truth('can_4').position
        self.assertLess(math.dist((p.x, p.y, p.z), LAYOUT['can_4'] + (TABLE,)), 0.005)

    def test_3_the_vanished_can_is_tried_backed_off_from_and_reported_gone(self):
        self.assertTrue(self.finished)
        self.assertEqual(len(self.reported(['attempt 1 of 2 failed at close on the can', 'nothing between the fingers'],
                                           LAYOUT['can_3'])), 1, self.reports)
        self.assertEqual(len(self.reported(['gone'], LAYOUT['can_3'])), 1, self.reports)
        self.assertTrue(self.reported(['stacked 1 of 3 cans on the tower (2 high)']), self.reports)

    def test_4_the_other_can_still_makes_a_tower_of_two(self):
        self.assertTrue(self.finished)
        bottom, top = self.truth('can_2'), self.truth('can_1')
        self.assertLess(math.hypot(bottom.position.x - 0.38, bottom.position.y), 0.01)
        self.assertEqual(tower_faults({'can_2': bottom, 'can_1': top}), [])
        by_can = {}
        for e in self.events:
            by_can.setdefault(e.object, []).append(e.attached)
        self.assertEqual(by_can, {'can_1': [True, False]})


if __name__ == '__main__':
    rostest.rosrun('katana_pick', 'test_stack_cans_faults', StackCansFaultsTest, sys.argv)
