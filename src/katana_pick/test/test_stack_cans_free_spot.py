#!/usr/bin/env python3
"""stack_cans_free_spot.test: four cans, and no can's spot takes all four. stack_cans says where
the tower goes up instead, sets the first can down there (at a steep grasp, -0.84 rad: the open
fingers still touch the can's rim) and stacks the other three on it, where a look after setting it down saw it: one upright tower, four
high, on the spot it named. The grasp fix attaches and lets go of each can once (before, open
fingers resting on the rim gripped the can again and the back-away dragged it off the spot).
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

    def test_3_the_first_can_is_looked_at_where_it_was_set_down(self):
        # The cans after it go where it stands, not where the plan put it.
        self.assertTrue(self.finished)
        number = r'\((-?[\d.]+), (-?[\d.]+)\)'
        looked = [re.search(r"the tower's first can stands at %s, ([\d.]+) mm from where it was set down at %s"
                            % (number, number), r) for r in self.reports]
        looked = [m for m in looked if m]
        self.assertEqual(len(looked), 1, self.reports)
        at, spot = [(float(looked[0].group(k)), float(looked[0].group(k + 1))) for k in (1, 4)]
        named = [r for r in self.reports if 'the tower goes up at (%.3f, %.3f)' % spot in r]
        self.assertEqual(len(named), 1, (spot, self.reports))
        self.assertAlmostEqual(float(looked[0].group(3)), 1e3 * math.dist(at, spot), delta=1.0)  # 1 mm print rounding
        bottom = min((self.truth(n) for n in CANS), key=lambda p: p.position.z).position
        # Seen within the detection's error (1.3 mm at most over 200 cans); the three cans set on
        # it since may have pushed it a little (2 mm in a run looked at by hand).
        self.assertLess(math.dist(at, (bottom.x, bottom.y)), 0.005)


if __name__ == '__main__':
    rostest.rosrun('katana_pick', 'test_stack_cans_free_spot', StackCansFreeSpotTest, sys.argv)
