#!/usr/bin/env python3
"""gazebo_ros_control + ros_control + ros_controllers, as a tutorial user meets them:
the spawner, controller manager services and their error messages, and each controller
family moving real joints in the simulator (ros_control.test)."""
import math
import os
import signal
import subprocess
import unittest

import actionlib
import rospy
import rostest
from control_msgs.msg import FollowJointTrajectoryAction, FollowJointTrajectoryGoal, FollowJointTrajectoryResult
from controller_manager_msgs.srv import ListControllers, LoadController, SwitchController, UnloadController
from geometry_msgs.msg import Twist
from nav_msgs.msg import Odometry
from rosgraph_msgs.msg import Log
from sensor_msgs.msg import JointState
from std_msgs.msg import Float64, Float64MultiArray
from trajectory_msgs.msg import JointTrajectoryPoint

from bullet_sim_testing.gazebo import Gazebo
from bullet_sim_testing.waiting import wait_until

STRICT = 2
CM = '/rig/controller_manager/'


class RosControlTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node('test_ros_control')
        cls.gz = Gazebo()
        for name in ('load_controller', 'unload_controller', 'switch_controller', 'list_controllers'):
            rospy.wait_for_service(CM + name, timeout=60)
        cls.load_srv = rospy.ServiceProxy(CM + 'load_controller', LoadController)
        cls.unload_srv = rospy.ServiceProxy(CM + 'unload_controller', UnloadController)
        cls.switch_srv = rospy.ServiceProxy(CM + 'switch_controller', SwitchController)
        cls.list_srv = rospy.ServiceProxy(CM + 'list_controllers', ListControllers)
        cls.log = []
        rospy.Subscriber('/rosout', Log, lambda m: cls.log.append(m.msg))
        # The simulator's log reaches us only once this subscription has connected to it; until
        # then a test could miss what it says. Have it say something until we hear it.
        for _ in range(30):
            cls.load_srv(name='never_configured')
            if wait_until(lambda: any("'never_configured'" in m for m in cls.log), 0.5):
                break
        cls.joints = {}
        rospy.Subscriber('/rig/joint_states', JointState, cls.on_joints)
        cls.publishers = {}

    @classmethod
    def on_joints(cls, msg):
        cls.joints = dict(zip(msg.name, zip(msg.position, msg.velocity)))

    # --- helpers ------------------------------------------------------------------------------

    def states(self):
        return {c.name: c.state for c in self.list_srv().controller}

    def load(self, name):
        return self.load_srv(name=name).ok

    def switch(self, start=(), stop=()):
        return self.switch_srv(start_controllers=list(start), stop_controllers=list(stop), strictness=STRICT,
                               start_asap=False, timeout=0.0).ok

    def ensure_running(self, *names):
        """Start exactly these controllers (and joint_state_controller), stopping the others."""
        for name in names + ('joint_state_controller',):
            if name not in self.states():
                self.assertTrue(self.load(name), name)
        running = [n for n, s in self.states().items() if s == 'running']
        stop = [n for n in running if n not in names + ('joint_state_controller',)]
        start = [n for n in names + ('joint_state_controller',) if n not in running]
        self.assertTrue(self.switch(start, stop), 'switch start=%s stop=%s' % (start, stop))
        self.assertTrue(wait_until(lambda: self.joints, 10), 'no /rig/joint_states')

    def publish(self, topic, msg_type, msg):
        if topic not in self.publishers:
            self.publishers[topic] = rospy.Publisher(topic, msg_type, queue_size=1, latch=True)
            wait_until(lambda: self.publishers[topic].get_num_connections() > 0, 5)
        self.publishers[topic].publish(msg)

    def position(self, joint):
        return self.joints[joint][0]

    def settles_at(self, joint, target, tolerance, timeout=5.0):
        return wait_until(lambda: abs(self.position(joint) - target) < tolerance, timeout)

    def logged(self, fragment, timeout=5.0):
        return wait_until(lambda: any(fragment in m for m in self.log), timeout)

    # --- the spawner --------------------------------------------------------------------------

    def test_spawner_loads_starts_and_unloads_on_shutdown(self):
        self.ensure_running()  # nothing else may hold effort_joint
        for name in ('effort_effort_controller', 'velocity_velocity_controller'):
            if name in self.states():
                self.assertTrue(self.unload_srv(name=name).ok)
        env = dict(os.environ, ROS_NAMESPACE='/rig')
        spawner = subprocess.Popen(['rosrun', 'controller_manager', 'spawner', 'effort_effort_controller',
                                    'velocity_velocity_controller'], env=env, stdout=subprocess.PIPE,
                                   stderr=subprocess.STDOUT, text=True)
        try:
            self.assertTrue(wait_until(lambda: self.states().get('effort_effort_controller') == 'running' and
                                       self.states().get('velocity_velocity_controller') == 'running', 30),
                            'spawner did not start its controllers: %s' % self.states())
        finally:
            spawner.send_signal(signal.SIGINT)
            output, _ = spawner.communicate(timeout=30)
        self.assertNotIn('effort_effort_controller', self.states(), output)
        self.assertNotIn('velocity_velocity_controller', self.states(), output)

    def test_spawner_in_a_launch_file_started_the_diffbot_controllers(self):
        list_diffbot = rospy.ServiceProxy('/diffbot/controller_manager/list_controllers', ListControllers)
        self.assertTrue(wait_until(lambda: {c.name: c.state for c in list_diffbot().controller}.get('base_controller')
                                   == 'running', 30))

    # --- errors a user searches for -----------------------------------------------------------

    def test_unknown_type_gives_the_exact_error_and_the_list_of_types(self):
        self.assertFalse(self.load('no_such_type_controller'))
        self.assertTrue(self.logged("Could not load controller 'no_such_type_controller' because controller type "
                                    "'effort_controllers/NoSuchController' does not exist."))
        message = next(m for m in self.log if 'no_such_type_controller' in m)
        for known in ('effort_controllers/JointPositionController', 'joint_state_controller/JointStateController',
                      'effort_controllers/JointTrajectoryController', 'diff_drive_controller/DiffDriveController'):
            self.assertIn(known, message)
        self.assertNotIn('no_such_type_controller', self.states())

    def test_missing_p_gain_is_named(self):
        self.assertFalse(self.load('missing_p_controller'))
        self.assertTrue(self.logged("Initializing controller 'missing_p_controller' failed"))
        self.assertTrue(self.logged('/rig/missing_p_controller/pid/p'))

    def test_missing_publish_rate_is_named(self):
        self.assertFalse(self.load('missing_rate_controller'))
        self.assertTrue(self.logged('/rig/missing_rate_controller/publish_rate'))

    def test_a_type_that_is_no_string_is_named(self):
        self.assertFalse(self.load('numbered_type_controller'))
        self.assertTrue(self.logged("Could not load controller 'numbered_type_controller': "
                                    "/rig/numbered_type_controller/type: expected a controller type such as "
                                    "effort_controllers/JointPositionController, got 3"))
        self.assertNotIn('numbered_type_controller', self.states())

    def test_missing_type_says_where_it_looked(self):
        self.assertFalse(self.load('never_configured'))
        self.assertTrue(self.logged("Could not load controller 'never_configured' because the type was not specified"))

    def test_resource_conflict_is_refused(self):
        self.ensure_running('group_effort_position_controller')
        if 'trajectory_controller' not in self.states():
            self.assertTrue(self.load('trajectory_controller'))
        self.assertFalse(self.switch(start=['trajectory_controller']))
        self.assertTrue(self.logged("resource conflict for joint 'group_a'"))
        self.assertEqual(self.states()['trajectory_controller'], 'initialized')

    # --- controllers move joints -----------------------------------------------------------------

    def test_switch_stop_leaves_the_joint_undriven_and_start_resumes(self):
        self.ensure_running('effort_position_controller')
        self.publish('/rig/effort_position_controller/command', Float64, Float64(1.0))
        self.assertTrue(self.settles_at('effort_joint', 1.0, 0.03), self.joints)
        self.assertTrue(self.switch(stop=['effort_position_controller']))
        self.assertEqual(self.states()['effort_position_controller'], 'stopped')
        # Undriven, gravity swings the arm down towards pi/2.
        self.assertTrue(wait_until(lambda: abs(self.position('effort_joint') - 1.0) > 0.2, 3), self.joints)
        # Started again, it holds where the joint is (ros_controllers' starting()) ...
        self.assertTrue(self.switch(start=['effort_position_controller']))
        self.assertTrue(wait_until(lambda: abs(self.joints['effort_joint'][1]) < 0.01, 5), self.joints)
        held = self.position('effort_joint')
        rospy.sleep(0.5)
        self.assertAlmostEqual(self.position('effort_joint'), held, delta=0.01)
        # ... and follows new commands.
        self.publish('/rig/effort_position_controller/command', Float64, Float64(0.2))
        self.assertTrue(self.settles_at('effort_joint', 0.2, 0.03, timeout=8), self.joints)

    def test_services_answer_while_physics_is_paused(self):
        self.gz.pause_physics()
        try:
            self.assertIsInstance(self.states(), dict)  # list_controllers answers
            self.ensure_running('effort_position_controller')
            self.assertTrue(self.switch(stop=['effort_position_controller']))
            self.assertTrue(self.switch(start=['effort_position_controller']))
        finally:
            self.gz.unpause_physics()

    def test_forward_position_and_velocity_controllers(self):
        self.ensure_running('position_position_controller', 'pid_position_controller', 'velocity_velocity_controller')
        self.publish('/rig/position_position_controller/command', Float64, Float64(0.7))
        self.publish('/rig/pid_position_controller/command', Float64, Float64(-0.4))
        self.publish('/rig/velocity_velocity_controller/command', Float64, Float64(2.0))
        self.assertTrue(self.settles_at('position_joint', 0.7, 0.02), self.joints)  # joint motor
        self.assertTrue(self.settles_at('pid_position_joint', -0.4, 0.03), self.joints)  # pid_gains
        self.assertTrue(wait_until(lambda: abs(self.joints['velocity_joint'][1] - 2.0) < 0.05, 5), self.joints)
        self.publish('/rig/velocity_velocity_controller/command', Float64, Float64(0.0))

    def test_group_position_controller_moves_both_joints(self):
        self.ensure_running('group_effort_position_controller')
        self.publish('/rig/group_effort_position_controller/command', Float64MultiArray,
                     Float64MultiArray(data=[0.5, -0.5]))
        self.assertTrue(self.settles_at('group_a', 0.5, 0.03), self.joints)
        self.assertTrue(self.settles_at('group_b', -0.5, 0.03), self.joints)

    def trajectory(self, controller, joints, positions, seconds):
        client = actionlib.SimpleActionClient('/rig/%s/follow_joint_trajectory' % controller,
                                              FollowJointTrajectoryAction)
        self.assertTrue(client.wait_for_server(rospy.Duration(10)))
        goal = FollowJointTrajectoryGoal()
        goal.trajectory.joint_names = joints
        goal.trajectory.points = [JointTrajectoryPoint(positions=positions, velocities=[0.0] * len(positions),
                                                       time_from_start=rospy.Duration(seconds))]
        client.send_goal(goal)
        self.assertTrue(client.wait_for_result(rospy.Duration(30)))
        return client.get_result()

    def test_trajectory_controller_result_codes(self):
        self.ensure_running('trajectory_controller', 'weak_trajectory_controller')
        result = self.trajectory('trajectory_controller', ['group_a', 'group_b'], [0.3, -0.3], 1.0)
        self.assertEqual(result.error_code, FollowJointTrajectoryResult.SUCCESSFUL, result.error_string)
        self.assertLess(abs(self.position('group_a') - 0.3), 0.02)
        self.assertLess(abs(self.position('group_b') + 0.3), 0.02)
        result = self.trajectory('trajectory_controller', ['group_a', 'no_such_joint'], [0.1, 0.1], 1.0)
        self.assertEqual(result.error_code, FollowJointTrajectoryResult.INVALID_JOINTS, result.error_string)
        # 1 N m cannot hold a 1 kg arm 0.2 m out: the goal is out of reach.
        result = self.trajectory('weak_trajectory_controller', ['weak_joint'], [-1.0], 1.0)
        self.assertEqual(result.error_code, FollowJointTrajectoryResult.GOAL_TOLERANCE_VIOLATED, result.error_string)

    def test_diff_drive_controller_drives_the_base(self):
        state = lambda: self.gz.state('diffbot').pose.position
        rospy.wait_for_service('/diffbot/controller_manager/list_controllers', 30)  # spawned by the launch file
        self.assertTrue(wait_until(lambda: rospy.ServiceProxy('/diffbot/controller_manager/list_controllers',
                                                              ListControllers)().controller, 30))
        start = state()
        twist = Twist()
        twist.linear.x = 0.5
        pub = rospy.Publisher('/diffbot/base_controller/cmd_vel', Twist, queue_size=1)
        wait_until(lambda: pub.get_num_connections() > 0, 5)
        t0 = rospy.get_time()
        while rospy.get_time() < t0 + 2.0:
            pub.publish(twist)
            rospy.sleep(0.05)
        pub.publish(Twist())
        rospy.sleep(0.5)
        moved = math.hypot(state().x - start.x, state().y - start.y)
        self.assertGreater(moved, 0.8, 'the base moved %.3f m' % moved)
        self.assertLess(moved, 1.4, 'the base moved %.3f m' % moved)
        odom = rospy.wait_for_message('/diffbot/base_controller/odom', Odometry, timeout=5)
        self.assertEqual(odom.header.frame_id, 'odom')
        self.assertAlmostEqual(odom.pose.pose.position.x, moved, delta=0.1)


if __name__ == '__main__':
    rostest.rosrun('bullet_sim', 'test_ros_control', RosControlTest)
