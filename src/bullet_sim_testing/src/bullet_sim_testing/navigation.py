"""What a navigation rostest checks, as a unittest mixin (needs a ROS master, the simulator, the
mapper and move_base).

Goals go to move_base's action in the map frame; the simulator's ground truth
(/gazebo/get_model_state, sampled at 20 Hz of sim time in a thread) says where the robot really
went: at each goal it must be within xy_goal_tolerance (plus the mapper's error) of it, and its
outline must never overlap a wall of the maze.
"""
import math
import threading

import actionlib
import rospy
from actionlib_msgs.msg import GoalStatus
from gazebo_msgs.srv import GetModelState
from move_base_msgs.msg import MoveBaseAction, MoveBaseActionResult, MoveBaseGoal

from bullet_sim_testing.gazebo import set_real_time_factor
from bullet_sim_testing.mobile import yaw_of
from bullet_sim_testing.walls import load_walls


def outline(length, width, step=0.02, centre_x=0.0):
    """Points along a length x width rectangle centred at (centre_x, 0) (robot frame)."""
    points = []
    for k in range(int(length / step) + 1):
        x = -length / 2 + k * length / int(length / step)
        points += [(x, -width / 2), (x, width / 2)]
    for k in range(int(width / step) + 1):
        y = -width / 2 + k * width / int(width / step)
        points += [(-length / 2, y), (length / 2, y)]
    return [(centre_x + x, y) for x, y in points]


def touches_a_wall(walls, points, x, y, yaw):
    """Whether the outline `points` (robot frame) at pose (x, y, yaw) is inside any of `walls`
    (only the walls within the outline's reach of the pose are tried)."""
    reach = max(math.hypot(px, py) for px, py in points)
    c, s = math.cos(yaw), math.sin(yaw)
    near = [w for w in walls if w.contains(x, y) or w.distance(x, y) <= reach]
    return any(w.contains(x + c * px - s * py, y + s * px + c * py) for w in near for px, py in points)


class NavigationChecks:
    MODEL = None             # model name in the simulator
    WALLS = None             # the maze's walls yaml
    OUTLINE = None           # (length, width) of the robot's outline, wheels included (m)
    OUTLINE_CENTRE_X = 0.0   # where the outline's centre is ahead of the base frame (m)
    MAP_IN_WORLD = (0.0, 0.0, 0.0)  # the map frame's pose in the world (x, y, yaw)
    XY_TOLERANCE = None      # the local planner's xy_goal_tolerance (m)
    MAPPER_ERROR = 0.06      # m the mapper's pose may be off the truth
    GOAL_TIMEOUT = 120.0     # s of sim time per goal
    RTF = None               # the simulator's target real-time factor for the tests (None: the launch's)

    @classmethod
    def setUpClass(cls):
        rospy.init_node('navigation_checks_' + cls.MODEL, anonymous=True)
        rospy.wait_for_service('/gazebo/get_model_state', timeout=60)
        cls.get_state = rospy.ServiceProxy('/gazebo/get_model_state', GetModelState, persistent=True)
        if cls.RTF:
            set_real_time_factor(cls.RTF)
        cls.walls = load_walls(cls.WALLS)
        cls.client = actionlib.SimpleActionClient('move_base', MoveBaseAction)
        if not cls.client.wait_for_server(rospy.Duration(120)):
            raise RuntimeError('move_base action server did not come up')
        cls.lock = threading.Lock()
        cls.results = {}  # goal id -> (status, text), from move_base/result
        rospy.Subscriber('move_base/result', MoveBaseActionResult, cls._on_result, queue_size=10)
        cls.truth = []
        cls.contacts = []
        cls.points = outline(*cls.OUTLINE, centre_x=cls.OUTLINE_CENTRE_X)
        cls.recording = True
        cls.recorder = threading.Thread(target=cls._record, daemon=True)
        cls.recorder.start()

    @classmethod
    def tearDownClass(cls):
        cls.recording = False

    @classmethod
    def _on_result(cls, msg):
        with cls.lock:
            cls.results[msg.status.goal_id.id] = (msg.status.status, msg.status.text)

    @classmethod
    def _record(cls):
        rate = rospy.Rate(20)
        while cls.recording and not rospy.is_shutdown():
            try:
                s = cls.get_state(model_name=cls.MODEL, relative_entity_name='world')
            except (rospy.ServiceException, rospy.ROSException):
                break
            x, y, yaw = s.pose.position.x, s.pose.position.y, yaw_of(s.pose.orientation)
            touching = touches_a_wall(cls.walls, cls.points, x, y, yaw)
            with cls.lock:
                cls.truth.append((s.header.stamp.to_sec(), x, y, yaw))
                if touching:
                    cls.contacts.append((s.header.stamp.to_sec(), x, y, yaw))
            try:
                rate.sleep()
            except rospy.ROSInterruptException:
                break

    # --- helpers ------------------------------------------------------------------------------------

    def world_pose(self):
        end = rospy.get_time() + 10.0
        while not self.truth and rospy.get_time() < end:  # the recorder's first sample
            rospy.sleep(0.05)
        with self.lock:
            return self.truth[-1][1:]

    def map_to_world(self, x, y):
        mx, my, myaw = self.MAP_IN_WORLD
        return (mx + math.cos(myaw) * x - math.sin(myaw) * y, my + math.sin(myaw) * x + math.cos(myaw) * y)

    def world_to_map(self, x, y, yaw=0.0):
        mx, my, myaw = self.MAP_IN_WORLD
        dx, dy = x - mx, y - my
        return (math.cos(myaw) * dx + math.sin(myaw) * dy, -math.sin(myaw) * dx + math.cos(myaw) * dy, yaw - myaw)

    @staticmethod
    def goal(x, y, yaw=0.0, frame='map'):
        g = MoveBaseGoal()
        g.target_pose.header.frame_id = frame
        g.target_pose.header.stamp = rospy.Time.now()
        g.target_pose.pose.position.x, g.target_pose.pose.position.y = x, y
        g.target_pose.pose.orientation.z, g.target_pose.pose.orientation.w = math.sin(yaw / 2), math.cos(yaw / 2)
        return g

    def send_and_wait(self, goal, timeout=None):
        """(final state, its text) of a goal sent and waited for."""
        self.client.send_goal(goal)
        if not self.client.wait_for_result(rospy.Duration(timeout or self.GOAL_TIMEOUT)):
            self.client.cancel_goal()
            self.client.wait_for_result(rospy.Duration(10))
            return 'timeout', ''
        return self.client.get_state(), self.client.get_goal_status_text()

    def current_goal_id(self):
        return self.client.gh.comm_state_machine.action_goal.goal_id.id

    def result_of(self, goal_id, timeout=5.0):
        """(status, text) move_base published for a goal, or None."""
        end = rospy.get_time() + timeout
        while rospy.get_time() < end:
            with self.lock:
                if goal_id in self.results:
                    return self.results[goal_id]
            rospy.sleep(0.1)
        return None

    def contacts_since(self, t):
        with self.lock:
            return [c for c in self.contacts if c[0] >= t]

    # --- checks ----------------------------------------------------------------------------------

    def reach_goals(self, goals):
        """Drives to each (x, y, yaw) of `goals` (map frame) in turn, checking each arrival."""
        for x, y, yaw in goals:
            start = rospy.get_time()
            state, text = self.send_and_wait(self.goal(x, y, yaw))
            self.assertEqual(state, GoalStatus.SUCCEEDED, 'goal (%.2f, %.2f): %s %s' % (x, y, state, text))
            self.assertEqual(text, 'Goal reached.')
            rospy.sleep(0.5)  # at rest
            wx, wy = self.map_to_world(x, y)
            px, py, _ = self.world_pose()
            error = math.hypot(px - wx, py - wy)
            self.assertLessEqual(error, self.XY_TOLERANCE + self.MAPPER_ERROR,
                                 'goal (%.2f, %.2f): the robot stopped %.3f m from it' % (x, y, error))
            self.assertEqual(self.contacts_since(start), [], 'the robot touched a wall on its way to (%.2f, %.2f)' % (x, y))
