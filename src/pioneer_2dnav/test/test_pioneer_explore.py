#!/usr/bin/env python3
"""The Pioneer explores its maze on its own (explore.launch: pioneer_navigation.launch and explore_lite's
explore): explore reports completion, the map then knows at least 95 % of the maze's reachable
free area, the robot never touched a wall, every goal left room for the robot, and the map lines
up with the walls."""
import os
import unittest

import rostest

from bullet_sim_testing.exploration_checks import ExplorationChecks

PIONEER_SIM = os.path.join(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))), 'pioneer_sim')


class PioneerExploreTest(ExplorationChecks, unittest.TestCase):
    MODEL = 'pioneer'
    WALLS = os.path.join(PIONEER_SIM, 'config', 'pioneer_maze_walls.yaml')
    OUTLINE = (0.44, 0.38)      # the top plate; the tyres reach 0.19 m either side
    OUTLINE_CENTRE_X = -0.045   # the plate's centre is behind the axle (base_link)
    MAP_IN_WORLD = (-3.2, -3.2, 0.0)  # pioneer_world.launch's spawn pose: the map frame starts there
    START = (-3.2, -3.2)
    INSCRIBED = 0.2             # the padded footprint's (costmap_common_params.yaml)
    STATUS = '/explore/status'
    LASER_RANGE = 30.0
    TIMEOUT = 1500.0

    def test_1_it_reports_completion(self):
        self.check_exploration_completes()

    def test_2_the_map_knows_the_reachable_area(self):
        self.check_explored_area(at_least=0.95)

    def test_3_no_wall_was_touched(self):
        self.check_no_wall_contact()

    def test_4_goals_leave_room_for_the_robot(self):
        # Goals keep the footprint's circumscribed radius from mapped walls and from unknown space
        # (where an unseen wall may stand): 0.36 m from the true walls, the map a cell off at worst.
        self.check_goals_where_the_robot_fits(clearance=0.3)

    def test_5_the_map_lines_up_with_the_walls(self):
        self.check_map_matches_the_walls(min_precision=0.9)


if __name__ == '__main__':
    rostest.rosrun('pioneer_2dnav', 'test_pioneer_explore', PioneerExploreTest)
