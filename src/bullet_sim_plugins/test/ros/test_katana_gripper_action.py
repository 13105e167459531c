#!/usr/bin/env python3
"""libgazebo_ros_katana_gripper.so on the spawned Katana (katana_gripper.test): the
/gripper_grasp_posture_controller action opens and closes both fingers to the goal within the
threshold, sooner than upstream's fixed 3 s, without passing their limits; a goal outside the range
is aborted at once; a new goal preempts the running one, a cancel stops the fingers where they
are; /gripper_grasp_status agrees with /joint_states (which joint_state_controller publishes
through the transmissions); fingers closing on a block stop there and the goal ends as stalled,
and they open again at once."""
import threading
import unittest

import actionlib
import rospy
import rostest
from actionlib_msgs.msg import GoalStatus
from control_msgs.msg import GripperCommand, GripperCommandAction, GripperCommandActionResult, GripperCommandGoal
from control_msgs.srv import QueryTrajectoryState
from gazebo_msgs.srv import DeleteModel, GetPhysicsProperties, SetPhysicsProperties, SpawnModel
from geometry_msgs.msg import Pose
from sensor_msgs.msg import JointState

from bullet_sim_testing.waiting import wait_until

ACTION = '/gripper_grasp_posture_controller'
STATUS = '/gripper_grasp_status'
FINGERS = ('katana_r_finger_joint', 'katana_l_finger_joint')
OPEN, CLOSED = 0.30, -0.44  # the fingers' joint limits and the action's range
THRESHOLD = 0.01            # rad: the plugin's goal threshold
# How far the solver lets a finger past its limit while it is pushed there (Bullet's limits are
# soft constraints); "not beyond the limits" allows this much.
LIMIT_SLACK = 0.003
STILL = 0.05                # rad/s
PACE = 4.0                  # times real time
# A fixed 3 cm block between the open fingers of the arm's zero pose (hinges at x 0.419 m,
# y +-0.03 m, 0.2015 m up; fingers 0.08 m long): they touch its far corners at about -0.165 rad.
BLOCK = """<?xml version="1.0"?><sdf version="1.6"><model name="block"><static>true</static>
<link name="body"><collision name="c"><geometry><box><size>0.03 0.03 0.03</size></box></geometry></collision>
</link></model></sdf>"""
BLOCK_AT = (0.47, 0.0, 0.2015)


class KatanaGripperActionTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node('katana_gripper_checker')
        cls.lock = threading.Lock()
        cls.states = []  # (sim time, {joint: (position, velocity)}) of the fingers
        rospy.Subscriber('/joint_states', JointState, cls.on_joint_states, queue_size=200)
        # When each goal ended, in the simulator's time: this node's clock may lag it by a few
        # hundredths of a second when the machine is busy.
        cls.ended = {}  # goal id -> sim time
        rospy.Subscriber(ACTION + '/result', GripperCommandActionResult,
                         lambda m: cls.ended.update({m.status.goal_id.id: m.header.stamp.to_sec()}), queue_size=20)
        rospy.wait_for_service('/gazebo/set_physics_properties', timeout=60)
        props = rospy.ServiceProxy('/gazebo/get_physics_properties', GetPhysicsProperties)()
        rospy.ServiceProxy('/gazebo/set_physics_properties', SetPhysicsProperties)(
            time_step=props.time_step, max_update_rate=PACE / props.time_step, gravity=props.gravity,
            ode_config=props.ode_config)
        cls.client = actionlib.SimpleActionClient(ACTION, GripperCommandAction)
        assert wait_until(lambda: cls.client.wait_for_server(rospy.Duration(0.5)), 90), 'no action ' + ACTION
        rospy.wait_for_service(STATUS, timeout=60)
        cls.status = rospy.ServiceProxy(STATUS, QueryTrajectoryState)
        assert wait_until(lambda: cls.latest() is not None, 60), 'no finger joints on /joint_states'

    @classmethod
    def on_joint_states(cls, msg):
        fingers = {n: (p, v) for n, p, v in zip(msg.name, msg.position, msg.velocity) if n in FINGERS}
        if len(fingers) == len(FINGERS):
            with cls.lock:
                cls.states.append((msg.header.stamp.to_sec(), fingers))

    @classmethod
    def latest(cls):
        with cls.lock:
            return cls.states[-1][1] if cls.states else None

    @classmethod
    def latest_stamp(cls):
        with cls.lock:
            return cls.states[-1][0] if cls.states else 0.0

    @classmethod
    def states_since(cls, t):
        with cls.lock:
            return [s for stamp, s in cls.states if stamp >= t]

    def goal(self, position):
        return GripperCommandGoal(command=GripperCommand(position=position, max_effort=0.0))

    def goal_ended(self):
        """When the client's present goal ended, in the simulator's time."""
        goal_id = self.client.gh.comm_state_machine.action_goal.goal_id.id
        self.assertTrue(wait_until(lambda: goal_id in self.ended, 10), 'no result message')
        return self.ended[goal_id]

    def grasp(self, position):
        """Sends a goal and waits for its end: (state, result, sim seconds it took, finger states meanwhile)."""
        start = rospy.get_time()
        self.client.send_goal(self.goal(position))
        self.assertTrue(self.client.wait_for_result(rospy.Duration(10.0)), 'no result for %s' % position)
        took = rospy.get_time() - start
        self.end = self.goal_ended()
        return self.client.get_state(), self.client.get_result(), took, self.states_since(start)

    def assert_within_limits(self, states):
        for s in states:
            for name in FINGERS:
                self.assertGreaterEqual(s[name][0], CLOSED - LIMIT_SLACK, name)
                self.assertLessEqual(s[name][0], OPEN + LIMIT_SLACK, name)

    def assert_settled_at(self, target, settle=0.5):
        """From the end of the last goal on, for `settle` s of sim time, both fingers stay within the
        threshold of `target` and still."""
        start = self.end
        self.assertTrue(wait_until(lambda: self.latest_stamp() >= start + settle, 30))
        window = self.states_since(start)
        self.assertGreater(len(window), 10)
        self.assert_within_limits(window)
        for s in window:
            for name in FINGERS:
                position, velocity = s[name]
                self.assertLessEqual(abs(position - target), THRESHOLD, (name, position))
                self.assertLess(abs(velocity), STILL, (name, velocity))

    def reach(self, target):
        state, result, took, during = self.grasp(target)
        self.assertEqual(state, GoalStatus.SUCCEEDED, self.client.get_goal_status_text())
        self.assertTrue(result.reached_goal)
        self.assertFalse(result.stalled)
        self.assertLessEqual(abs(result.position - target), THRESHOLD)
        self.assertLess(took, 2.5)  # done when there, not after upstream's 3 s
        self.assert_within_limits(during)
        self.assert_settled_at(target)
        return took

    def test_1_open_reaches_the_open_limit_and_stops_there(self):
        self.reach(OPEN)

    def test_2_close_reaches_the_closed_limit_and_stops_there(self):
        self.reach(OPEN)
        took = self.reach(CLOSED)
        self.assertGreater(took, 0.05)  # 0.74 rad takes a moment with at most 0.5 N m

    def test_3_a_goal_outside_the_range_is_aborted_at_once_and_the_fingers_stay(self):
        self.reach(0.1)
        before = self.latest()
        for position in (0.5, -0.45):
            state, result, took, _ = self.grasp(position)
            self.assertEqual(state, GoalStatus.ABORTED)
            text = self.client.get_goal_status_text()
            self.assertIn('outside gripper range [-0.44, 0.3]', text)
            self.assertIn(str(position), text)
            # At once: far under the 3 s goal_timeout a goal that was tried would run into (a busy
            # CI machine has taken 0.28 s for the round trip); the fingers not moving is checked below.
            self.assertLess(took, 1.0)
        self.assert_settled_at(0.1)
        for name in FINGERS:
            self.assertLessEqual(abs(self.latest()[name][0] - before[name][0]), THRESHOLD)

    def test_4_a_new_goal_preempts_the_running_one(self):
        self.reach(CLOSED)
        first = actionlib.SimpleActionClient(ACTION, GripperCommandAction)
        self.assertTrue(wait_until(lambda: first.wait_for_server(rospy.Duration(0.5)), 30))
        first.send_goal(self.goal(OPEN))
        self.assertTrue(wait_until(lambda: first.get_state() == GoalStatus.ACTIVE, 10))
        rospy.sleep(0.05)
        state, result, _, _ = self.grasp(-0.2)
        self.assertTrue(first.wait_for_result(rospy.Duration(5.0)))
        self.assertEqual(first.get_state(), GoalStatus.PREEMPTED)
        self.assertEqual(state, GoalStatus.SUCCEEDED)
        self.assertTrue(result.reached_goal)
        self.assert_settled_at(-0.2)

    def test_4b_a_cancel_stops_the_fingers_where_they_are(self):
        self.reach(CLOSED)
        self.client.send_goal(self.goal(OPEN))
        # Cancel as soon as /joint_states shows them on the way (not after a sleep: a busy machine
        # delays the ACTIVE status and the clock, and at PACE times real time the fingers would be
        # nearly open by then).
        on_the_way = CLOSED + 0.1
        self.assertTrue(wait_until(lambda: min(p for p, _ in self.latest().values()) > on_the_way, 10))
        cancelled_at = min(p for p, _ in self.latest().values())
        self.client.cancel_goal()
        self.assertTrue(self.client.wait_for_result(rospy.Duration(5.0)))
        self.assertEqual(self.client.get_state(), GoalStatus.PREEMPTED)
        stopped = self.client.get_result().position
        self.assertGreater(stopped, cancelled_at - THRESHOLD)
        self.assertLess(stopped, OPEN - 0.1)  # 0.4 rad short of open: the cancel stopped them
        self.end = self.goal_ended() + 0.5  # they were moving at 1 rad/s: a short swing back
        self.assert_settled_at(stopped)

    def test_5_the_status_service_gives_the_angle_of_joint_states(self):
        self.reach(0.0)
        response = self.status()
        self.assertEqual(len(response.position), 1)
        latest = self.latest()
        for name in FINGERS:
            self.assertLessEqual(abs(response.position[0] - latest[name][0]), THRESHOLD, name)
        self.assertLessEqual(abs(response.position[0]), THRESHOLD)

    def test_6_fingers_closing_on_a_block_stall_there_and_open_at_once(self):
        self.reach(OPEN)
        at = Pose()
        at.position.x, at.position.y, at.position.z = BLOCK_AT
        at.orientation.w = 1.0
        spawned = rospy.ServiceProxy('/gazebo/spawn_sdf_model', SpawnModel)(
            model_name='block', model_xml=BLOCK, robot_namespace='', initial_pose=at, reference_frame='')
        self.assertTrue(spawned.success, spawned.status_message)
        try:
            state, result, took, during = self.grasp(CLOSED)
            self.assertEqual(state, GoalStatus.SUCCEEDED)
            self.assertTrue(result.stalled)
            self.assertFalse(result.reached_goal)
            self.assertGreater(result.position, -0.2)
            self.assertLess(result.position, -0.13)
            # 0.46 rad at 1 rad/s, then 0.25 s still: not upstream's 3 s.
            self.assertGreater(took, 0.5)
            self.assertLess(took, 1.5)
            self.assert_within_limits(during)
            for name in FINGERS:
                self.assertLessEqual(abs(self.latest()[name][0] - result.position), THRESHOLD, name)
            took = self.reach(OPEN)
            self.assertLess(took, 1.0)  # nothing of the squeeze holds the fingers back
        finally:
            rospy.ServiceProxy('/gazebo/delete_model', DeleteModel)(model_name='block')


if __name__ == '__main__':
    rostest.rosrun('bullet_sim_plugins', 'katana_gripper_action', KatanaGripperActionTest)
