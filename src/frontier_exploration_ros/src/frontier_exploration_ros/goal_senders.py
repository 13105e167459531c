"""Goals to move_base, and their outcomes back as frontier_exploration outcomes.

ActionGoals uses the move_base action (explore_lite's way); TopicGoals publishes
geometry_msgs/PoseStamped on move_base_simple/goal (the lecture's find_frontier) and finds its
goal's outcome on move_base/result through the id move_base gives it on move_base/goal."""
import math
import threading

import actionlib
import rospy
from actionlib_msgs.msg import GoalID, GoalStatus
from geometry_msgs.msg import PoseStamped
from move_base_msgs.msg import MoveBaseAction, MoveBaseActionGoal, MoveBaseActionResult, MoveBaseGoal

from frontier_exploration.explorer import ABORTED, LOST, PREEMPTED, REJECTED, SUCCEEDED

OUTCOMES = {GoalStatus.SUCCEEDED: SUCCEEDED, GoalStatus.ABORTED: ABORTED, GoalStatus.REJECTED: REJECTED,
            GoalStatus.PREEMPTED: PREEMPTED, GoalStatus.RECALLED: PREEMPTED, GoalStatus.LOST: LOST}


def pose_stamped(goal, frame):
    x, y, yaw = goal
    p = PoseStamped()
    p.header.frame_id = frame
    p.header.stamp = rospy.Time.now()
    p.pose.position.x, p.pose.position.y = x, y
    p.pose.orientation.z, p.pose.orientation.w = math.sin(yaw / 2), math.cos(yaw / 2)
    return p


class ActionGoals:
    def __init__(self, action_name, on_finished):
        self.client = actionlib.SimpleActionClient(action_name, MoveBaseAction)
        self.on_finished = on_finished
        self.name = rospy.resolve_name(action_name)

    def ready(self):
        """None when goals can go out, else why not."""
        if self.client.wait_for_server(rospy.Duration(0.05)):
            return None
        return 'waiting for the move_base action server %s' % self.name

    def send(self, number, goal, frame):
        g = MoveBaseGoal(target_pose=pose_stamped(goal, frame))
        self.client.send_goal(g, done_cb=lambda state, _result: self.on_finished(number, OUTCOMES.get(state, LOST)))

    def cancel(self):
        if self.client.simple_state != actionlib.SimpleGoalState.DONE:
            self.client.cancel_goal()


class TopicGoals:
    RESEND_AFTER = 5.0  # s (sim) without move_base taking the goal up: publish it again

    def __init__(self, goal_topic, move_base_ns, on_finished):
        self.publisher = rospy.Publisher(goal_topic, PoseStamped, queue_size=1)
        self.name = rospy.resolve_name(goal_topic)
        self.on_finished = on_finished
        self.lock = threading.Lock()
        self.pending = None       # (number, PoseStamped, time sent) not yet seen on move_base/goal
        self.numbers = {}         # move_base's goal id -> our number
        self.current_id = None
        self.cancel_pub = rospy.Publisher(move_base_ns + '/cancel', GoalID, queue_size=1)
        rospy.Subscriber(move_base_ns + '/goal', MoveBaseActionGoal, self._on_goal, queue_size=10)
        rospy.Subscriber(move_base_ns + '/result', MoveBaseActionResult, self._on_result, queue_size=10)

    def ready(self):
        if self.publisher.get_num_connections() > 0:
            with self.lock:
                pending = self.pending
            if pending and rospy.get_time() - pending[2] > self.RESEND_AFTER:
                rospy.logwarn('move_base has not taken up goal %d on %s in %.0f s: sending it again'
                              % (pending[0], self.name, self.RESEND_AFTER))
                self._publish(pending[0], pending[1])
            return None
        return 'waiting for move_base: nothing subscribes to %s' % self.name

    def send(self, number, goal, frame):
        self._publish(number, pose_stamped(goal, frame))

    def _publish(self, number, pose):
        with self.lock:
            self.pending = (number, pose, rospy.get_time())
        self.publisher.publish(pose)

    def cancel(self):
        with self.lock:
            goal_id = self.current_id
        if goal_id is not None:
            self.cancel_pub.publish(GoalID(id=goal_id))

    def _on_goal(self, msg):
        p = msg.goal.target_pose.pose.position
        with self.lock:
            if self.pending is None:
                return
            mine = self.pending[1].pose.position
            if abs(p.x - mine.x) < 1e-6 and abs(p.y - mine.y) < 1e-6:
                self.numbers[msg.goal_id.id] = self.pending[0]
                self.current_id = msg.goal_id.id
                self.pending = None

    def _on_result(self, msg):
        with self.lock:
            number = self.numbers.pop(msg.status.goal_id.id, None)
            if msg.status.goal_id.id == self.current_id:
                self.current_id = None
        if number is not None:
            self.on_finished(number, OUTCOMES.get(msg.status.status, LOST))
