"""What an exploration rostest checks, as a unittest mixin (needs the simulator, the mapper, move_base
and an exploration node with a ~status topic).

The simulation runs at RTF times real time: faster than the robot's nodes can keep up with, the
simulator would leave them behind (the tf goes stale). The exploration runs once, in setUpClass, until the node
reports "complete" or TIMEOUT s of sim time pass; the tests then check what a user would look at:
the completion report, how much of the maze's reachable free area the map knows (from the walls
and the robot's footprint, bullet_sim_testing.exploration), no wall contact on the way (ground
truth, NavigationChecks' recorder), goals only where the robot fits, and the map against the walls.
"""
import math
import threading

import numpy as np
import rospy
from move_base_msgs.msg import MoveBaseActionGoal
from nav_msgs.msg import OccupancyGrid
from std_msgs.msg import String

from bullet_sim_testing.exploration import ReachableArea, wall_clearance
from bullet_sim_testing.gazebo import set_real_time_factor
from bullet_sim_testing.map_scoring import map_alignment
from bullet_sim_testing.navigation import NavigationChecks


class ExplorationChecks(NavigationChecks):
    STATUS = None            # the exploration node's ~status topic (the test node's ~status overrides it)
    INSCRIBED = None         # m: the robot's inscribed radius (the reachable area)
    START = (0.0, 0.0)       # where the robot starts in the world
    TIMEOUT = 900.0          # s of sim time for the whole exploration
    LASER_RANGE = None       # m, for the map's wall coverage
    RTF = 4.0                # the simulation's target real-time factor (2-core machines keep up)
    GOAL_CLEARANCE = None    # m every goal keeps from the true walls
    MIN_EXPLORED = 0.95      # of the reachable free area, at completion
    MIN_MAP_PRECISION = 0.9  # of the map's occupied cells within 0.1 m of a wall

    @classmethod
    def setUpClass(cls):
        super().setUpClass()
        cls.STATUS = rospy.get_param('~status', cls.STATUS)
        cls.area = ReachableArea(cls.walls, cls.INSCRIBED, cls.START)
        cls.statuses, cls.goals, cls.maps = [], [], []
        cls.map_lock = threading.Lock()
        rospy.Subscriber(cls.STATUS, String, lambda m: cls.statuses.append((rospy.get_time(), m.data)), queue_size=10)
        rospy.Subscriber('move_base/goal', MoveBaseActionGoal, lambda m: cls.goals.append(m.goal.target_pose), queue_size=10)
        rospy.Subscriber('map', OccupancyGrid, cls._on_map, queue_size=1)
        # The first map with something in it: what the robot sees from its start.
        end = rospy.get_time() + 60
        while rospy.get_time() < end and not (cls.maps and cls.area.explored_fraction(*cls._grid(cls.maps[-1])) > 0):
            rospy.sleep(0.1)
        cls.first_map = cls.maps[-1] if cls.maps else None
        set_real_time_factor(cls.RTF)
        cls.start_time = rospy.get_time()
        end = cls.start_time + cls.TIMEOUT
        while rospy.get_time() < end and not rospy.is_shutdown() and not cls.completion():
            rospy.sleep(0.5)
        cls.end_time = rospy.get_time()
        rospy.sleep(3.0)  # a last map (published every 2 s)

    @classmethod
    def _on_map(cls, msg):
        with cls.map_lock:
            cls.maps[:] = [msg]

    @classmethod
    def completion(cls):
        """The node's "complete: ..." report, or None."""
        return next((text for _, text in cls.statuses if text.startswith('complete')), None)

    @classmethod
    def _grid(cls, msg):
        """explored_fraction's arguments for a map message."""
        values = np.asarray(msg.data, dtype=np.int16).reshape(msg.info.height, msg.info.width)
        return values, msg.info.resolution, (msg.info.origin.position.x, msg.info.origin.position.y), cls.MAP_IN_WORLD

    def explored(self, msg):
        return self.area.explored_fraction(*self._grid(msg))

    def last_map(self):
        with self.map_lock:
            return self.maps[-1]

    # --- the tests -----------------------------------------------------------------------------------

    def test_1_it_reports_completion(self):
        self.check_exploration_completes()

    def test_2_the_map_knows_the_reachable_area(self):
        self.check_explored_area(at_least=self.MIN_EXPLORED)

    def test_3_no_wall_was_touched(self):
        self.check_no_wall_contact()

    def test_4_goals_leave_room_for_the_robot(self):
        self.check_goals_where_the_robot_fits(clearance=self.GOAL_CLEARANCE)

    def test_5_the_map_lines_up_with_the_walls(self):
        self.check_map_matches_the_walls(min_precision=self.MIN_MAP_PRECISION)

    # --- checks ------------------------------------------------------------------------------------

    def check_exploration_completes(self):
        report = self.completion()
        print('%s exploration: %s after %.0f s of sim time; %d goals' % (
            self.MODEL, report, self.end_time - self.start_time, len(self.goals)))
        self.assertIsNotNone(report, 'no completion within %.0f s; last status: %s'
                             % (self.TIMEOUT, self.statuses[-1][1] if self.statuses else 'none'))
        self.assertTrue(report.startswith('complete: exploration complete: no '), report)

    def check_explored_area(self, at_least):
        self.assertIsNotNone(self.first_map, 'no map with anything in it on /map within 60 s of sim time')
        before = self.explored(self.first_map)
        after = self.explored(self.last_map())
        print('%s exploration: %.1f %% of the %.1f m2 reachable free area known at the start, %.1f %% at the end'
              % (self.MODEL, 100 * before, self.area.area, 100 * after))
        self.assertGreater(before, 0.0)
        self.assertLess(before, 0.9)  # the start alone does not see it all: exploring is needed
        self.assertGreaterEqual(after, at_least)
        self.assertLessEqual(after, 1.0)

    def check_no_wall_contact(self):
        self.assertEqual(self.contacts_since(self.start_time), [])

    def check_goals_where_the_robot_fits(self, clearance):
        self.assertGreater(len(self.goals), 0)
        xs, ys = zip(*(self.map_to_world(g.pose.position.x, g.pose.position.y) for g in self.goals))
        worst = float(wall_clearance(self.walls, np.array(xs), np.array(ys)).min())
        print('%s exploration: %d goals, the nearest %.3f m from a wall' % (self.MODEL, len(self.goals), worst))
        self.assertGreaterEqual(worst, clearance)
        for g in self.goals:
            self.assertTrue(math.isfinite(g.pose.position.x) and math.isfinite(g.pose.position.y))

    def check_map_matches_the_walls(self, min_precision):
        msg = self.last_map()
        values = np.asarray(msg.data, dtype=np.int16).reshape(msg.info.height, msg.info.width)
        rows, cols = np.nonzero(values >= 65)
        res, ox, oy = msg.info.resolution, msg.info.origin.position.x, msg.info.origin.position.y
        points = [self.map_to_world(ox + (c + 0.5) * res, oy + (r + 0.5) * res) for r, c in zip(rows, cols)]
        with self.lock:
            seen_from = [(x, y) for _, x, y, _ in self.truth[::40]]
        precision, mean, coverage = map_alignment(self.walls, points, seen_from, self.LASER_RANGE)
        print('%s exploration: map %d occupied cells, %.1f %% within 0.1 m of a wall (mean %.1f mm), %.1f %% of '
              'the visible wall faces mapped' % (self.MODEL, len(points), 100 * precision, 1e3 * mean, 100 * coverage))
        self.assertGreaterEqual(precision, min_precision)
