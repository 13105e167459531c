#!/usr/bin/env python3
"""stack_cans_free_spot.test: four cans, and no can's spot takes all four. stack_cans says where
the tower goes up instead, sets the first can down there (at a steep grasp, -0.84 rad: the open
fingers still touch the can's rim) and stacks the other three on it: one upright tower, four high,
on the spot it named. The grasp fix attaches and lets go of each can once (before, open fingers
resting on the rim gripped the can again and the back-away dragged it off the spot).
Ground truth from /gazebo/get_model_state."""
import math
import re
import sys
import unittest

import rospy
import rostest

from bullet_sim_testing.gazebo import Gazebo
from stack_cans_run import Watch, run_until_stack_cans_exits, tower_faults, truth, wait_for_cans

LAYOUT = [(0.1896, 0.3250), (0.3372, -0.2833), (0.4196, 0.1453), (0.3970, -0.0842)]
CANS = ['can_1', 'can_2', 'can_3', 'can_4']
CAN_RADIUS = 0.033


class StackCansFreeSpotTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node('test_stack_cans_free_spot')
        cls.watch = Watch()
        cls.gazebo = Gazebo()
        wait_for_cans()
        cls.finished, cls.sim_seconds = run_until_stack_cans_exits()
        cls.reports, cls.events = cls.watch.reports, cls.watch.events

    def truth(self, name):
        return truth(self.gazebo, name)

    def test_1_four_high_on_the_free_spot_it_named(self):
        self.assertTrue(self.finished, 'stack_cans still running after 180 s')
        named = [re.search(r"no can's spot takes every can: the tower goes up at \((-?[\d.]+), (-?[\d.]+)\)", r)
                 for r in self.reports]
        named = [m for m in named if m]
        self.assertEqual(len(named), 1, self.reports)
        spot = (float(named[0].group(1)), float(named[0].group(2)))
        for can in LAYOUT:  # free: no can stood there
            self.assertGreater(math.dist(spot, can), 2 * CAN_RADIUS)
        by_name = {n: self.truth(n) for n in CANS}
        bottom = min(by_name.values(), key=lambda p: p.position.z).position
        self.assertLess(math.dist((bottom.x, bottom.y), spot), 0.01)  # not dragged off it
        self.assertEqual(tower_faults(by_name), [])
        self.assertTrue(any('stacked 4 of 4 cans on the tower (4 high)' in r for r in self.reports), self.reports)

    def test_2_each_can_is_attached_and_let_go_once(self):
        self.assertTrue(self.finished)
        by_can = {}
        for e in self.events:
            self.assertEqual(e.arm, 'katana')
            by_can.setdefault(e.object, []).append(e.attached)
        self.assertEqual(by_can, {name: [True, False] for name in CANS})


if __name__ == '__main__':
    rostest.rosrun('katana_pick', 'test_stack_cans_free_spot', StackCansFreeSpotTest, sys.argv)
