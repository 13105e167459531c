#!/usr/bin/env python3
"""The /gazebo API of bullet_sim_node, as a tutorial user calls it: spawn, state, pause,
delete, forces, and clear errors for bad input while the node keeps running.
The simulator starts paused (see gazebo_api.test), so nothing moves unless a test runs it."""
import math
import subprocess
import time
import unittest

import rospy
import rostest
import dynamic_reconfigure.client
from gazebo_msgs.msg import LinkState, ModelStates
from geometry_msgs.msg import Point, Wrench
from rosgraph_msgs.msg import Clock
from visualization_msgs.msg import Marker, MarkerArray

from bullet_sim_testing.gazebo import G, Gazebo, pose
from sim_test_utils import core_test_path, package_path, read, test_path

BOX = read('urdf', 'falling_box.urdf')
PENDULUM = read('package', 'urdf', 'pendulum.urdf')


def rosrun(*args, timeout=60):
    return subprocess.run(['rosrun', 'bullet_sim'] + list(args), capture_output=True, text=True, timeout=timeout)


class GazeboApiTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node('test_gazebo_api')
        cls.gz = Gazebo()

    def setUp(self):
        self.gz.pause_physics()
        for name in self.gz.get_world_properties().model_names:
            if name != 'ground_plane':
                self.gz.delete_model(model_name=name)

    def assertRejected(self, response, *fragments):
        self.assertFalse(response.success, response.status_message)
        for fragment in fragments:
            self.assertIn(fragment, response.status_message)
        self.assertTrue(self.gz.alive(), 'the simulator stopped answering after a bad request')

    # --- spawning, state, deleting -------------------------------------------------------------

    def test_world_properties_list_the_ground_plane(self):
        props = self.gz.get_world_properties()
        self.assertTrue(props.success)
        self.assertIn('ground_plane', props.model_names)

    def test_physics_properties_report_and_change_the_solver_sweeps_and_tolerance(self):
        physics = self.gz.get_physics_properties()
        self.assertAlmostEqual(physics.time_step, 0.001, places=9)  # empty.world
        self.assertEqual(physics.ode_config.sor_pgs_iters, 50)      # SDF's default iters
        self.assertAlmostEqual(physics.ode_config.sor_pgs_rms_error_tol, 1e-5, places=12)  # our early stop, m/s
        config = physics.ode_config
        config.sor_pgs_iters = 20
        config.sor_pgs_rms_error_tol = 2e-5
        done = self.gz.set_physics_properties(time_step=physics.time_step, max_update_rate=physics.max_update_rate,
                                              gravity=physics.gravity, ode_config=config)
        self.assertTrue(done.success, done.status_message)
        changed = self.gz.get_physics_properties().ode_config
        self.assertEqual(changed.sor_pgs_iters, 20)
        self.assertAlmostEqual(changed.sor_pgs_rms_error_tol, 2e-5, places=12)
        config.sor_pgs_iters = 50
        config.sor_pgs_rms_error_tol = 1e-5
        self.gz.set_physics_properties(time_step=physics.time_step, max_update_rate=physics.max_update_rate,
                                       gravity=physics.gravity, ode_config=config)

    def test_max_update_rate_sets_the_pace_as_in_gazebo(self):
        # empty.world: 1 ms steps at 1000 steps a second (real time) and real_time_factor 1, which,
        # as in Gazebo, does not cap the pace: 3000 steps a second is 3x real time.
        physics = self.gz.get_physics_properties()
        try:
            done = self.gz.set_physics_properties(time_step=physics.time_step, max_update_rate=3000.0,
                                                  gravity=physics.gravity, ode_config=physics.ode_config)
            self.assertTrue(done.success, done.status_message)
            t0, w0 = self.gz.sim_time(), time.monotonic()
            self.gz.run_for(3.0)
            factor = (self.gz.sim_time() - t0) / (time.monotonic() - w0)
            # At most the pace asked for (a little over: run_for's polling), and well above real time.
            self.assertGreater(factor, 1.8)
            self.assertLess(factor, 3.3)
        finally:
            self.gz.set_physics_properties(time_step=physics.time_step, max_update_rate=physics.max_update_rate,
                                           gravity=physics.gravity, ode_config=physics.ode_config)

    def test_set_then_get_model_state_round_trips(self):
        self.assertTrue(self.gz.spawn_urdf('box', BOX, pose(0, 0, 1)).success)
        target = pose(1.5, -2.0, 3.25, yaw=0.7)
        self.assertTrue(self.gz.set_state('box', target).success)
        got = self.gz.state('box')
        self.assertTrue(got.success, got.status_message)
        for field in ('x', 'y', 'z'):
            self.assertAlmostEqual(getattr(got.pose.position, field), getattr(target.position, field), places=9)
        for field in ('x', 'y', 'z', 'w'):
            self.assertAlmostEqual(getattr(got.pose.orientation, field), getattr(target.orientation, field), places=9)
        # Relative to another model, and set relative to it: the same place.
        self.assertTrue(self.gz.spawn_urdf('marker', BOX, pose(1, 0, 1)).success)
        relative = self.gz.state('box', relative='marker')
        self.assertAlmostEqual(relative.pose.position.x, 0.5, places=9)
        self.assertTrue(self.gz.set_state('box', pose(0, 1, 0), reference='marker').success)
        self.assertAlmostEqual(self.gz.state('box').pose.position.y, 1.0, places=9)

    def test_set_link_state_places_a_model_by_its_root_link_and_refuses_a_jointed_link(self):
        self.assertTrue(self.gz.spawn_urdf('pendulum', PENDULUM, pose(0, 0, 0)).success)
        root = self.gz.get_model_properties(model_name='pendulum').body_names[0]
        target = LinkState(link_name='pendulum::' + root, pose=pose(0.5, -0.25, 0.75, yaw=0.3))
        done = self.gz.set_link_state(link_state=target)
        self.assertTrue(done.success, done.status_message)
        got = self.gz.get_link_state(link_name='pendulum::' + root, reference_frame='world').link_state.pose
        self.assertAlmostEqual(got.position.x, 0.5, places=9)
        self.assertAlmostEqual(got.position.y, -0.25, places=9)
        self.assertAlmostEqual(got.position.z, 0.75, places=9)
        self.assertAlmostEqual(got.orientation.z, target.pose.orientation.z, places=9)
        # The topic does the same.
        publisher = rospy.Publisher('/gazebo/set_link_state', LinkState, queue_size=1, latch=True)
        publisher.publish(LinkState(link_name='pendulum::' + root, pose=pose(-1.0, 0, 0.5)))
        deadline = time.monotonic() + 5
        while self.gz.state('pendulum').pose.position.x > -0.99 and time.monotonic() < deadline:
            time.sleep(0.05)
        self.assertAlmostEqual(self.gz.get_link_state(link_name='pendulum::' + root).link_state.pose.position.x,
                               -1.0, places=9)
        # A link on a joint cannot be placed on its own in reduced coordinates: it says so.
        child = self.gz.get_model_properties(model_name='pendulum').body_names[1]
        self.assertRejected(self.gz.set_link_state(link_state=LinkState(link_name='pendulum::' + child, pose=pose(0, 0, 2))),
                            'hangs on joints', 'set_model_configuration')
        self.assertRejected(self.gz.set_link_state(link_state=LinkState(link_name='nothing::here', pose=pose())),
                            'link [nothing::here] does not exist')

    def test_dynamic_reconfigure_reads_and_sets_the_physics(self):
        client = dynamic_reconfigure.client.Client('/gazebo', timeout=10)
        config = client.get_configuration(timeout=10)
        physics = self.gz.get_physics_properties()
        self.assertAlmostEqual(config['time_step'], physics.time_step, places=12)
        self.assertAlmostEqual(config['gravity_z'], -9.8, places=9)
        self.assertAlmostEqual(config['contact_max_correcting_vel'], physics.ode_config.contact_max_correcting_vel)
        self.assertEqual(config['sor_pgs_iters'], physics.ode_config.sor_pgs_iters)
        try:
            changed = client.update_configuration({'time_step': 0.002, 'gravity_z': -1.62, 'sor_pgs_iters': 30})
            self.assertAlmostEqual(changed['time_step'], 0.002, places=12)
            now = self.gz.get_physics_properties()
            self.assertAlmostEqual(now.time_step, 0.002, places=12)
            self.assertAlmostEqual(now.gravity.z, -1.62, places=12)
            self.assertEqual(now.ode_config.sor_pgs_iters, 30)
            # Values outside upstream's ranges are clamped, as dynamic_reconfigure's servers do.
            self.assertEqual(client.update_configuration({'gravity_z': -500.0})['gravity_z'], -100.0)
        finally:
            client.update_configuration({'time_step': physics.time_step, 'gravity_z': physics.gravity.z,
                                         'sor_pgs_iters': physics.ode_config.sor_pgs_iters})
        self.assertAlmostEqual(self.gz.get_physics_properties().time_step, physics.time_step, places=12)

    def test_pause_stops_clock_and_motion_and_unpause_resumes(self):
        self.assertTrue(self.gz.spawn_urdf('box', BOX, pose(0, 0, 50)).success)
        clock_before = rospy.wait_for_message('/clock', Clock, timeout=5).clock
        z_before = self.gz.state('box').pose.position.z
        time.sleep(0.5)
        self.assertAlmostEqual(self.gz.sim_time(), clock_before.to_sec(), places=6)
        self.assertEqual(self.gz.state('box').pose.position.z, z_before)
        self.gz.unpause_physics()
        time.sleep(0.5)
        clock_running = rospy.wait_for_message('/clock', Clock, timeout=5).clock
        self.gz.pause_physics()
        self.assertGreater(clock_running, clock_before)
        self.assertLess(self.gz.state('box').pose.position.z, z_before - 0.01)

    def test_delete_removes_the_model(self):
        self.assertTrue(self.gz.spawn_urdf('doomed', BOX, pose(0, 0, 1)).success)
        deleted = self.gz.delete_model(model_name='doomed')
        self.assertTrue(deleted.success, deleted.status_message)
        self.assertNotIn('doomed', self.gz.get_world_properties().model_names)
        self.assertRejected(self.gz.state('doomed'), 'model [doomed] does not exist')
        self.assertRejected(self.gz.delete_model(model_name='doomed'), 'model [doomed] does not exist')

    def test_two_robots_spawn_and_move_independently(self):
        self.assertTrue(self.gz.spawn_urdf('left', PENDULUM, pose(0, -1, 0)).success)
        self.assertTrue(self.gz.spawn_urdf('right', PENDULUM, pose(0, 1, 0)).success)
        self.assertTrue(self.gz.set_model_configuration(model_name='left', joint_names=['hinge'],
                                                        joint_positions=[0.5]).success)
        self.gz.run_for(0.2)
        left = self.gz.get_link_state(link_name='left::bob', reference_frame='')
        right = self.gz.get_link_state(link_name='right::bob', reference_frame='')
        self.assertTrue(left.success and right.success)
        self.assertAlmostEqual(left.link_state.pose.position.y, -1.0, places=6)
        self.assertAlmostEqual(right.link_state.pose.position.y, 1.0, places=6)
        self.assertNotAlmostEqual(self.gz.get_joint_properties(joint_name='left::hinge').position[0], 0.0, places=2)
        self.assertAlmostEqual(self.gz.get_joint_properties(joint_name='right::hinge').position[0], 0.0, places=9)
        states = rospy.wait_for_message('/gazebo/model_states', ModelStates, timeout=5)
        self.assertIn('left', states.name)
        self.assertIn('right', states.name)

    def test_spawn_model_script_places_a_robot_from_xacro(self):
        done = rosrun('spawn_model', '-urdf', '-file', package_path('urdf', 'laser_post.urdf.xacro'),
                      '-model', 'scripted', '-x', '1', '-y', '2', '-Y', '0.5')
        self.assertEqual(done.returncode, 0, done.stdout + done.stderr)
        state = self.gz.state('scripted')
        self.assertTrue(state.success)
        self.assertAlmostEqual(state.pose.position.x, 1.0, places=6)
        self.assertAlmostEqual(state.pose.orientation.z, math.sin(0.25), places=6)

    def test_scene_markers_show_every_model_for_rviz(self):
        self.assertTrue(self.gz.spawn_urdf('box', BOX, pose(1, 2, 3)).success)
        markers = rospy.wait_for_message('/gazebo/scene_markers', MarkerArray, timeout=5).markers
        box = [m for m in markers if m.ns == 'box']
        self.assertEqual(len(box), 1)
        self.assertEqual(box[0].type, Marker.CUBE)
        self.assertEqual(box[0].header.frame_id, 'world')
        self.assertAlmostEqual(box[0].scale.x, 0.2)
        self.assertAlmostEqual(box[0].pose.position.y, 2.0)
        self.assertTrue(any(m.ns == 'ground_plane' for m in markers))

    # --- forces and reset -----------------------------------------------------------------------

    def test_body_wrench_lifts_and_joint_effort_turns(self):
        self.assertTrue(self.gz.spawn_urdf('box', BOX, pose(0, 0, 2)).success)
        self.assertTrue(self.gz.spawn_urdf('pendulum', PENDULUM, pose(3, 0, 0)).success)
        lift = Wrench()
        lift.force.z = 2 * 2.0 * G  # twice the box's weight: it accelerates up at g
        applied = self.gz.apply_body_wrench(body_name='box::body', reference_frame='', reference_point=Point(),
                                            wrench=lift, start_time=rospy.Time(0), duration=rospy.Duration(-1))
        self.assertTrue(applied.success, applied.status_message)
        pushed = self.gz.apply_joint_effort(joint_name='hinge', effort=1.0, start_time=rospy.Time(0),
                                            duration=rospy.Duration(0.5))
        self.assertTrue(pushed.success, pushed.status_message)
        self.gz.run_for(0.5)
        self.assertGreater(self.gz.state('box').pose.position.z, 2.0 + 0.5 * G * 0.5 ** 2 * 0.9)
        self.assertGreater(self.gz.get_joint_properties(joint_name='hinge').position[0], 0.05)

    def test_reset_world_restores_spawn_poses(self):
        self.assertTrue(self.gz.spawn_urdf('box', BOX, pose(0, 0, 5)).success)
        self.gz.run_for(0.3)
        self.assertLess(self.gz.state('box').pose.position.z, 4.9)
        time_before = self.gz.sim_time()
        self.gz.reset_world()
        self.assertAlmostEqual(self.gz.state('box').pose.position.z, 5.0, places=9)
        self.assertEqual(self.gz.sim_time(), time_before)
        self.gz.reset_simulation()
        self.assertEqual(self.gz.sim_time(), 0.0)

    # --- bad input: a clear error and the node stays up --------------------------------------

    def test_malformed_urdf(self):
        self.assertRejected(self.gz.spawn_urdf('bad', '<robot name="bad"><link name="a"></robot>'),
                            'malformed XML at line')

    def test_invalid_urdf_names_the_problem(self):
        xml = BOX.replace('</robot>', '<joint name="j" type="fixed"><parent link="body"/><child link="nowhere"/>'
                                      '</joint></robot>')
        self.assertRejected(self.gz.spawn_urdf('bad', xml), 'invalid URDF', 'nowhere')

    def test_missing_mesh_names_link_and_file(self):
        xml = BOX.replace('<collision><geometry><box size="0.2 0.2 0.2"/>',
                          '<collision><geometry><mesh filename="/nonexistent/part.stl"/>')
        self.assertRejected(self.gz.spawn_urdf('bad', xml), "<link name='body'>", '/nonexistent/part.stl')

    def test_malformed_sdf_names_the_element(self):
        sdf = ('<sdf version="1.6"><model name="m"><link name="l"><collision name="c"><geometry><cone/>'
               '</geometry></collision></link></model></sdf>')
        response = self.gz.spawn_sdf_model(model_name='bad', model_xml=sdf, robot_namespace='', initial_pose=pose(),
                                           reference_frame='')
        self.assertRejected(response, '<geometry>', 'expected one of box, cylinder, sphere, plane, mesh')

    def test_empty_model_xml(self):
        self.assertRejected(self.gz.spawn_urdf('bad', '   '), 'model_xml is empty')

    def test_duplicate_model_name(self):
        self.assertTrue(self.gz.spawn_urdf('twin', BOX).success)
        self.assertRejected(self.gz.spawn_urdf('twin', BOX), "a model named 'twin' already exists")

    def test_unknown_model_and_reference(self):
        self.assertRejected(self.gz.state('ghost'), 'model [ghost] does not exist')
        self.assertRejected(self.gz.set_state('ghost', pose()), 'model [ghost] does not exist')
        self.assertTrue(self.gz.spawn_urdf('box', BOX).success)
        self.assertRejected(self.gz.state('box', relative='nothing::here'), 'relative_entity_name [nothing::here]')
        self.assertRejected(self.gz.spawn_urdf_model(model_name='other', model_xml=BOX, robot_namespace='',
                                                     initial_pose=pose(), reference_frame='ghost'),
                            "reference_frame: entity 'ghost' does not exist")

    def test_nan_in_requests(self):
        self.assertTrue(self.gz.spawn_urdf('box', BOX, pose(0, 0, 1)).success)
        self.assertRejected(self.gz.set_state('box', pose(float('nan'), 0, 0)), 'expected finite numbers')
        self.assertRejected(self.gz.spawn_urdf('nan_box', BOX, pose(0, float('inf'), 0)), 'initial_pose',
                            'expected finite numbers')
        wrench = Wrench()
        wrench.force.x = float('nan')
        self.assertRejected(self.gz.apply_body_wrench(body_name='box::body', reference_frame='',
                                                      reference_point=Point(), wrench=wrench,
                                                      start_time=rospy.Time(0), duration=rospy.Duration(1)),
                            'expected finite numbers')
        self.assertRejected(self.gz.apply_joint_effort(joint_name='nothing', effort=float('nan'),
                                                       start_time=rospy.Time(0), duration=rospy.Duration(1)),
                            'effort: expected a finite number')
        self.assertAlmostEqual(self.gz.state('box').pose.position.z, 1.0, places=9)  # nothing was applied

    def test_malformed_xacro_through_spawn_model(self):
        done = rosrun('spawn_model', '-urdf', '-file', test_path('urdf', 'broken.urdf.xacro'), '-model', 'bad')
        self.assertNotEqual(done.returncode, 0)
        self.assertIn('xacro failed', done.stderr + done.stdout)
        self.assertIn('broken.urdf.xacro', done.stderr + done.stdout)
        self.assertTrue(self.gz.alive())

    def test_bad_world_file_exits_nonzero_with_the_reason(self):
        for world, fragment in (('unknown_geometry.world', 'expected one of box, cylinder, sphere, plane, mesh'),
                                ('unknown_model.world', 'model://'),
                                ('malformed.world', 'malformed.world')):
            done = rosrun('bullet_sim_node', core_test_path('data', 'bad', world), '__name:=bad_world_probe')
            self.assertEqual(done.returncode, 1, world + ': ' + done.stdout + done.stderr)
            self.assertIn(world, done.stderr)
            self.assertIn(fragment, done.stderr)
        self.assertTrue(self.gz.alive())


if __name__ == '__main__':
    rostest.rosrun('bullet_sim', 'test_gazebo_api', GazeboApiTest)
