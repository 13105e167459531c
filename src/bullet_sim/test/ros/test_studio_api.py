#!/usr/bin/env python3
"""What a client like sim_studio reads and sends, as it meets them: /gazebo/pose_info (every link's
pose, at most 60 Hz of wall time, also while paused), /gazebo/scene_info (latched: every visual in its
link's frame, the sensors' topics), /gazebo/joint_cmd (Gazebo's joint control panel: a force, a
position and a velocity target held every step), /gazebo/step_world (its step button) and
/gazebo/get_link_properties (its masses). The simulator starts paused (see studio_api.test).

The joint tests use the physics tests' pendulum (urdf/pendulum.urdf: 1 kg at 0.25 m below a hinge
about y): hanging, gravity pulls it back with m g L sin(angle); spawned rolled 90 degrees its hinge
is vertical and gravity has no moment about it (a turntable). Either way its inertia about the hinge
is the bob's 1e-4 plus m L^2."""
import math
import threading
import time
import unittest

import rospy
import rostest
from bullet_sim_msgs.msg import JointCmd, Pid
from bullet_sim_msgs.srv import StepWorld
from gazebo_msgs.msg import LinkStates
from geometry_msgs.msg import Pose
from rosgraph_msgs.msg import Log
from visualization_msgs.msg import Marker, MarkerArray

from bullet_sim_testing.gazebo import G, Gazebo, pose
from sim_test_utils import read

BOX = read('urdf', 'falling_box.urdf')
MAST = read('urdf', 'sensor_mast.urdf')
PENDULUM = read('package', 'urdf', 'pendulum.urdf')
MASS, ARM = 1.0, 0.25
INERTIA = 1e-4 + MASS * ARM ** 2  # about the hinge, kg m^2
PULL = MASS * G * ARM             # gravity's moment on the hanging pendulum at 90 degrees, N m


def rolled(x=0.0, y=0.0, z=0.0):
    """A pose rolled 90 degrees about x: the pendulum's hinge (about y) stands vertical."""
    p = Pose()
    p.position.x, p.position.y, p.position.z = x, y, z
    p.orientation.x, p.orientation.w = math.sin(math.pi / 4), math.cos(math.pi / 4)
    return p


def pid(target, p=0.0, i=0.0, d=0.0, **bounds):
    return Pid(target=target, p=p, i=i, d=d, **bounds)


class Recorder:
    """Every message of a topic with its wall arrival time (time.monotonic())."""

    def __init__(self, topic, message_type):
        self.messages = []
        self.lock = threading.Lock()
        self.subscriber = rospy.Subscriber(topic, message_type, self.add, queue_size=100)

    def add(self, message):
        with self.lock:
            self.messages.append((time.monotonic(), message))

    def since(self, start):
        with self.lock:
            return [(t, m) for t, m in self.messages if t >= start]

    def wait_for(self, predicate, timeout, since=0.0):
        """The first message after `since` for which predicate(message) holds: (arrival, message), or None."""
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline:
            for arrival, message in self.since(since):
                if predicate(message):
                    return arrival, message
            time.sleep(0.005)
        return None

    def close(self):
        self.subscriber.unregister()


def by_model(scene, model):
    return [m for m in scene.markers if m.ns == model]


class StudioApiTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node('test_studio_api')
        cls.gz = Gazebo()
        cls.joint_cmd = rospy.Publisher('/gazebo/joint_cmd', JointCmd, queue_size=10)
        deadline = time.monotonic() + 10
        while cls.joint_cmd.get_num_connections() == 0 and time.monotonic() < deadline:
            time.sleep(0.05)

    def setUp(self):
        self.gz.pause_physics()
        for name in self.gz.get_world_properties().model_names:
            if name != 'ground_plane':
                self.gz.delete_model(model_name=name)

    def send(self, name, reset=False, force=None, position=None, velocity=None):
        """A JointCmd as the panel sends it; returns once the (paused) simulator has surely read it."""
        msg = JointCmd(name=name, reset=reset)
        if force is not None:
            msg.set_force, msg.force = True, force
        if position is not None:
            msg.set_position, msg.position = True, position
        if velocity is not None:
            msg.set_velocity, msg.velocity = True, velocity
        self.joint_cmd.publish(msg)
        time.sleep(0.3)  # the paused loop reads its callbacks every 10 ms

    def joint(self, name):
        props = self.gz.get_joint_properties(joint_name=name)
        self.assertTrue(props.success, props.status_message)
        return props.position[0], props.rate[0]

    def assertStill(self, name):
        angle, rate = self.joint(name)
        self.assertAlmostEqual(angle, 0.0, delta=1e-9)
        self.assertAlmostEqual(rate, 0.0, delta=1e-9)

    def run_for(self, seconds):
        """Runs the simulation and returns the sim time it ran (a little more than asked)."""
        start = self.gz.sim_time()
        self.gz.run_for(seconds)
        return self.gz.sim_time() - start

    # --- /gazebo/pose_info -----------------------------------------------------------------------

    def test_pose_info_names_every_link_as_link_states_does_at_get_link_state_poses(self):
        self.assertTrue(self.gz.spawn_urdf('pendulum', PENDULUM, pose(1, 0, 0)).success)
        self.assertTrue(self.gz.spawn_urdf('box', BOX, pose(0, 2, 0.5, yaw=0.4)).success)
        self.assertTrue(self.gz.set_model_configuration(model_name='pendulum', joint_names=['hinge'],
                                                        joint_positions=[0.7]).success)
        time.sleep(0.2)  # paused: nothing moves from here on
        info = rospy.wait_for_message('/gazebo/pose_info', LinkStates, timeout=5)
        links = rospy.wait_for_message('/gazebo/link_states', LinkStates, timeout=5)
        self.assertEqual(info.name, links.name)
        self.assertIn('pendulum::bob', info.name)
        self.assertIn('box::body', info.name)
        for name, got in zip(info.name, info.pose, strict=True):
            expected = self.gz.get_link_state(link_name=name, reference_frame='world').link_state.pose
            for field in ('x', 'y', 'z'):
                self.assertAlmostEqual(getattr(got.position, field), getattr(expected.position, field), delta=1e-3)
            for field in ('x', 'y', 'z', 'w'):
                self.assertAlmostEqual(getattr(got.orientation, field), getattr(expected.orientation, field),
                                       delta=1e-3)
        bob = info.pose[info.name.index('pendulum::bob')]
        self.assertAlmostEqual(bob.position.x, 1.0, places=6)  # the bob's link frame sits on the hinge
        self.assertAlmostEqual(bob.orientation.y, math.sin(0.35), places=6)

    def test_pose_info_comes_at_30_to_60_hz_of_wall_time_running_and_paused(self):
        self.assertTrue(self.gz.spawn_urdf('box', BOX, pose(0, 0, 0.1)).success)
        recorder = Recorder('/gazebo/pose_info', LinkStates)
        try:
            self.assertIsNotNone(recorder.wait_for(lambda m: True, 5), 'no pose_info while paused')
            for running in (False, True):
                if running:
                    self.gz.unpause_physics()
                time.sleep(0.5)
                start = time.monotonic()
                time.sleep(3.0)
                arrivals = [t for t, _ in recorder.since(start) if t <= start + 3.0]
                self.gz.pause_physics()
                rate = len(arrivals) / 3.0
                self.assertGreaterEqual(rate, 30.0, 'running' if running else 'paused')
                self.assertLessEqual(rate, 61.0, 'running' if running else 'paused')
        finally:
            recorder.close()

    def test_a_model_moved_while_paused_shows_in_pose_info_within_0_2_s(self):
        self.assertTrue(self.gz.spawn_urdf('box', BOX, pose(0, 0, 0.1)).success)
        recorder = Recorder('/gazebo/pose_info', LinkStates)
        try:
            self.assertIsNotNone(recorder.wait_for(lambda m: 'box::body' in m.name, 5))

            def box_x(m):
                return m.pose[m.name.index('box::body')].position.x if 'box::body' in m.name else None

            for x in (1.5, -0.5):
                start = time.monotonic()
                self.assertTrue(self.gz.set_state('box', pose(x, 0, 0.1)).success)
                seen = recorder.wait_for(lambda m, x=x: box_x(m) is not None and abs(box_x(m) - x) < 1e-9, 2.0,
                                         since=start)
                self.assertIsNotNone(seen, 'set_model_state to x=%g never showed in pose_info' % x)
                self.assertLess(seen[0] - start, 0.2)
            # A model spawned while paused too.
            start = time.monotonic()
            self.assertTrue(self.gz.spawn_urdf('late', BOX, pose(0, 3, 0.1)).success)
            seen = recorder.wait_for(lambda m: 'late::body' in m.name, 2.0, since=start)
            self.assertIsNotNone(seen)
            self.assertLess(seen[0] - start, 0.2)
        finally:
            recorder.close()

    # --- /gazebo/scene_info ----------------------------------------------------------------------

    def test_scene_info_is_latched_with_every_visual_in_its_link_frame(self):
        self.assertTrue(self.gz.spawn_urdf('pendulum', PENDULUM, pose(1, 0, 0)).success)
        time.sleep(0.3)
        # A subscriber that comes late still gets the scene at once: the topic is latched.
        scene = rospy.wait_for_message('/gazebo/scene_info', MarkerArray, timeout=2)
        self.assertEqual(scene.markers[0].action, Marker.DELETEALL)
        self.assertTrue(by_model(scene, 'ground_plane'))
        bob = by_model(scene, 'pendulum')
        self.assertEqual(len(bob), 1, bob)  # the bob's sphere; the pivot has no visual
        sphere = bob[0]
        self.assertEqual(sphere.header.frame_id, 'pendulum::bob')
        self.assertEqual(sphere.type, Marker.SPHERE)
        self.assertEqual(sphere.text, 'bob')  # the visual has no name: its link's
        self.assertAlmostEqual(sphere.scale.x, 0.06)
        # Relative to the link: the URDF's <visual><origin xyz="0 0 -0.25"/>, wherever the model stands.
        self.assertAlmostEqual(sphere.pose.position.x, 0.0, places=9)
        self.assertAlmostEqual(sphere.pose.position.z, -0.25, places=9)
        self.assertAlmostEqual(sphere.pose.orientation.w, 1.0, places=9)
        for model in {m.ns for m in scene.markers if m.ns}:
            ids = [m.id for m in by_model(scene, model)]
            self.assertEqual(len(ids), len(set(ids)), model)
        # Every frame a marker names is a link pose_info places.
        links = rospy.wait_for_message('/gazebo/pose_info', LinkStates, timeout=5).name
        for marker in scene.markers[1:]:
            self.assertIn(marker.header.frame_id, links)

    def test_scene_info_is_published_again_after_a_spawn_and_a_delete(self):
        recorder = Recorder('/gazebo/scene_info', MarkerArray)
        try:
            self.assertIsNotNone(recorder.wait_for(lambda s: True, 5))  # the latched one
            start = time.monotonic()
            self.assertTrue(self.gz.spawn_urdf('box', BOX, pose(0, 0, 1)).success)
            seen = recorder.wait_for(lambda s: by_model(s, 'box'), 2.0, since=start)
            self.assertIsNotNone(seen, 'no scene_info with the spawned box')
            box = by_model(seen[1], 'box')
            self.assertEqual([(m.type, m.header.frame_id, m.text) for m in box], [(Marker.CUBE, 'box::body', 'body')])
            self.assertAlmostEqual(box[0].pose.position.z, 0.0)  # in its link, not at z = 1
            start = time.monotonic()
            self.assertTrue(self.gz.delete_model(model_name='box').success)
            seen = recorder.wait_for(lambda s: not by_model(s, 'box'), 2.0, since=start)
            self.assertIsNotNone(seen, 'no scene_info without the deleted box')
            self.assertEqual(seen[1].markers[0].action, Marker.DELETEALL)
            # Not every step: while nothing is spawned or deleted, nothing more comes.
            self.gz.run_for(0.5)
            self.assertEqual(len(recorder.since(seen[0] + 0.01)), 0)
        finally:
            recorder.close()

    def test_scene_info_names_each_sensors_topic_for_the_client_to_draw(self):
        done = self.gz.spawn_urdf('mast', MAST, pose(2, 0, 0), namespace='mast_ns')
        self.assertTrue(done.success, done.status_message)
        time.sleep(0.3)
        scene = rospy.wait_for_message('/gazebo/scene_info', MarkerArray, timeout=2)
        mast = {m.text: m for m in by_model(scene, 'mast')}
        self.assertEqual(sorted(mast), ['camera:/mast_ns/front/image_raw', 'head', 'laser:/mast_ns/scan', 'pole'])
        self.assertEqual(mast['pole'].header.frame_id, 'mast::mast')
        self.assertAlmostEqual(mast['pole'].pose.position.z, 0.5)
        laser, camera = mast['laser:/mast_ns/scan'], mast['camera:/mast_ns/front/image_raw']
        for sensor in (laser, camera):
            self.assertEqual(sensor.type, Marker.LINE_LIST)
            self.assertEqual(sensor.points, [])
            self.assertEqual(sensor.header.frame_id, 'mast::head')
        # The sensors' <pose>s in their link, and how far each sees.
        self.assertAlmostEqual(laser.pose.position.x, 0.05)
        self.assertAlmostEqual(laser.pose.position.z, 0.04)
        self.assertAlmostEqual(laser.pose.orientation.z, math.sin(0.25))
        self.assertAlmostEqual(laser.scale.x, 4.0)
        self.assertAlmostEqual(camera.pose.position.x, 0.06)
        self.assertAlmostEqual(camera.pose.orientation.y, math.sin(0.1))
        self.assertAlmostEqual(camera.scale.x, 20.0)
        # The names are the topics the sensors really publish on.
        published = dict(rospy.get_published_topics())
        self.assertEqual(published.get('/mast_ns/scan'), 'sensor_msgs/LaserScan')
        self.assertEqual(published.get('/mast_ns/front/image_raw'), 'sensor_msgs/Image')

    # --- /gazebo/step_world and /gazebo/get_link_properties ---------------------------------------

    def test_step_world_runs_exactly_the_steps_asked_and_stays_paused(self):
        self.assertTrue(self.gz.spawn_urdf('pendulum', PENDULUM, pose()).success)
        self.gz.set_model_configuration(model_name='pendulum', urdf_param_name='', joint_names=['hinge'],
                                        joint_positions=[0.5])
        step_world = rospy.ServiceProxy('/gazebo/step_world', StepWorld)
        dt = self.gz.get_physics_properties().time_step
        start = self.gz.sim_time()
        reply = step_world(steps=1)
        self.assertTrue(reply.success, reply.status_message)
        self.assertAlmostEqual(reply.sim_time - start, dt, delta=1e-9)
        reply = step_world(steps=50)
        self.assertAlmostEqual(reply.sim_time - start, 51 * dt, delta=1e-9)
        # Gravity acted in those steps: from rest at 0.5 rad, the angle's acceleration is
        # -m g L sin(0.5) / I, so after t = 0.051 s the rate is that times t (the angle moves
        # 0.02 rad meanwhile: 2 % less; 10 % allowed).
        _, rate = self.joint('pendulum::hinge')
        expected = -PULL * math.sin(0.5) / INERTIA * 51 * dt
        self.assertGreater(rate, 1.1 * expected)
        self.assertLess(rate, 0.9 * expected)
        time.sleep(0.3)
        self.assertAlmostEqual(self.gz.sim_time(), reply.sim_time, delta=1e-9, msg="still paused")
        # A running world is paused first; 0 steps only pauses.
        self.gz.unpause_physics()
        time.sleep(0.2)
        reply = step_world(steps=0)
        self.assertTrue(self.gz.get_physics_properties().pause)
        self.assertAlmostEqual(self.gz.sim_time(), reply.sim_time, delta=1e-9)

    def test_get_link_properties_gives_the_inertial_the_urdf_wrote(self):
        self.assertTrue(self.gz.spawn_urdf('pendulum', PENDULUM, pose()).success)
        bob = self.gz.get_link_properties(link_name='pendulum::bob')
        self.assertTrue(bob.success, bob.status_message)
        self.assertAlmostEqual(bob.mass, MASS, delta=1e-12)
        self.assertAlmostEqual(bob.com.position.z, -ARM, delta=1e-12)
        self.assertAlmostEqual(bob.com.orientation.w, 1.0, delta=1e-12)
        for moment in (bob.ixx, bob.iyy, bob.izz):
            self.assertAlmostEqual(moment, 1e-4, delta=1e-12)
        self.assertEqual((bob.ixy, bob.ixz, bob.iyz), (0.0, 0.0, 0.0))
        self.assertTrue(bob.gravity_mode)
        self.assertAlmostEqual(self.gz.get_link_properties(link_name='pendulum::pivot').ixx, 0.01, delta=1e-12)
        for bad in ('pendulum::nose', 'pendulum', 'nobody::bob'):
            reply = self.gz.get_link_properties(link_name=bad)
            self.assertFalse(reply.success, bad)
            self.assertIn("[%s] does not exist" % bad, reply.status_message)

    # --- /gazebo/joint_cmd -----------------------------------------------------------------------

    def test_a_force_turns_the_joint_at_force_over_inertia_and_stays_until_reset(self):
        self.assertTrue(self.gz.spawn_urdf('table', PENDULUM, rolled(z=1.0)).success)
        torque = 0.05
        expected = torque / INERTIA  # rad/s^2, with no gravity moment about a vertical hinge
        self.send('table::hinge', force=torque)
        t = self.run_for(0.5)
        angle, rate = self.joint('table::hinge')
        self.assertGreater(angle, 0.0)  # the way the force turns
        for measured in (2 * angle / t ** 2, rate / t):
            self.assertGreater(measured, 0.8 * expected)
            self.assertLess(measured, 1.25 * expected)
        # Held every step: still accelerating at the same rate.
        t += self.run_for(0.5)
        _, rate = self.joint('table::hinge')
        self.assertAlmostEqual(rate / t, expected, delta=0.05 * expected)
        # Reset: no more torque, so the turntable keeps its speed.
        self.send('table::hinge', reset=True)
        _, before = self.joint('table::hinge')
        self.run_for(0.5)
        _, after = self.joint('table::hinge')
        self.assertAlmostEqual(after, before, delta=1e-3 * before)

    def test_a_position_target_is_held_by_the_pid_where_its_gains_say(self):
        self.assertTrue(self.gz.spawn_urdf('pendulum', PENDULUM, pose()).success)
        target, p, d = 0.5, 20.0, 2.0
        # P and D alone: the arm rests where p (target - angle) = m g L sin(angle).
        expected = target
        for _ in range(50):
            expected = target - PULL * math.sin(expected) / p
        self.send('pendulum::hinge', position=pid(target, p=p, d=d))
        self.run_for(2.0)  # damping ratio d / (2 sqrt((p + m g L) I)) ~ 0.85: settled in under 0.5 s
        angle, rate = self.joint('pendulum::hinge')
        self.assertAlmostEqual(angle, expected, delta=1e-3)
        self.assertLess(abs(rate), 1e-2)
        # With an integral term the target itself.
        self.send('pendulum::hinge', position=pid(target, p=p, i=40.0, d=d, i_max=5.0, i_min=-5.0))
        self.run_for(4.0)  # the integral's pole at about -2.6 per s
        angle, _ = self.joint('pendulum::hinge')
        self.assertAlmostEqual(angle, target, delta=1e-3)
        # Reset: nothing holds it; from rest at 0.5 rad it swings down (a quarter period is 0.25 s).
        self.send('pendulum::hinge', reset=True)
        self.run_for(0.2)
        angle, rate = self.joint('pendulum::hinge')
        self.assertLess(angle, 0.35)
        self.assertLess(rate, -0.5)

    def test_a_velocity_target_is_reached(self):
        self.assertTrue(self.gz.spawn_urdf('table', PENDULUM, rolled(z=1.0)).success)
        for target in (2.0, -1.5):
            self.send('table::hinge', velocity=pid(target, p=1.0))  # time constant I / p = 63 ms
            self.run_for(1.0)
            _, rate = self.joint('table::hinge')
            self.assertAlmostEqual(rate, target, delta=1e-3)

    def test_deleting_a_model_or_resetting_the_world_drops_its_commands(self):
        self.assertTrue(self.gz.spawn_urdf('table', PENDULUM, rolled(z=1.0)).success)
        self.send('table::hinge', force=0.05)
        self.assertTrue(self.gz.delete_model(model_name='table').success)
        self.assertTrue(self.gz.spawn_urdf('table', PENDULUM, rolled(z=1.0)).success)
        self.run_for(0.3)
        self.assertStill('table::hinge')
        self.send('table::hinge', force=0.05)
        self.gz.reset_world()
        self.run_for(0.3)
        self.assertStill('table::hinge')

    def test_a_command_for_an_unknown_joint_is_a_warning_and_the_node_runs_on(self):
        self.assertTrue(self.gz.spawn_urdf('pendulum', PENDULUM, pose()).success)
        log = Recorder('/rosout', Log)  # what nodes log; rostest runs no rosout to aggregate it
        try:
            time.sleep(0.5)
            for name, words in (('ghost::hinge', 'model [ghost] does not exist'),
                                ('pendulum::nope', 'model [pendulum] has no moving joint [nope]'),
                                ('hinge', "expected 'model::joint'")):
                self.send(name, force=1.0)
                def warned(m, name=name, words=words):
                    return m.level == Log.WARN and name in m.msg and words in m.msg

                seen = log.wait_for(warned, 5.0)
                self.assertIsNotNone(seen, 'no warning naming %s' % name)
                self.assertTrue(self.gz.alive())
            # Not a number: a warning naming the field, and nothing applied.
            self.send('pendulum::hinge', position=pid(float('nan'), p=10.0))
            self.assertIsNotNone(log.wait_for(lambda m: 'position.target: expected a finite number' in m.msg, 5.0))
            self.assertEqual(self.gz.get_world_properties().model_names, ['ground_plane', 'pendulum'])
            self.run_for(0.3)
            self.assertStill('pendulum::hinge')
        finally:
            log.close()


if __name__ == '__main__':
    rostest.rosrun('bullet_sim', 'test_studio_api', StudioApiTest)
