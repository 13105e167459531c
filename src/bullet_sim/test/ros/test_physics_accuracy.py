#!/usr/bin/env python3
"""bullet_sim_node against analytic mechanics, observed through ROS as a user would:
a pendulum's small-angle period and a body's free-fall drop."""
import math
import time
import unittest

import numpy as np
import rospy
import rostest
from gazebo_msgs.msg import LinkStates

from bullet_sim_testing.gazebo import G, Gazebo, pose
from sim_test_utils import read

PENDULUM = read('package', 'urdf', 'pendulum.urdf')
BOX = read('urdf', 'falling_box.urdf')
L, M, I_BOB = 0.1, 1.0, 1e-4  # pendulum.urdf with a 0.1 m rod


class PhysicsAccuracyTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node('test_physics_accuracy')
        cls.gz = Gazebo()

    def test_pendulum_period_matches_small_angle_theory(self):
        self.gz.pause_physics()
        # A shorter rod than the demo's, for more swings per second.
        xml = PENDULUM.replace('xyz="0 0 -0.25"', 'xyz="0 0 -%g"' % L)
        self.assertTrue(self.gz.spawn_urdf('pendulum', xml).success)
        self.assertTrue(self.gz.set_model_configuration(model_name='pendulum', joint_names=['hinge'],
                                                        joint_positions=[0.05]).success)
        # (sim time, swing angle): link_states stamped with the /clock time at receipt. The
        # simulator runs at 0.4 of real time meanwhile, so that a busy machine delays a
        # sample by a fraction of a step; queue_size 1 drops stale states rather than stamping
        # them late, and the median half-period ignores the odd delayed crossing.
        samples = []

        def on_states(msg):
            i = msg.name.index('pendulum::bob')
            q = msg.pose[i].orientation
            samples.append((rospy.get_time(), 2 * math.atan2(q.y, q.w)))

        physics = self.gz.get_physics_properties()
        self.set_update_rate(physics, 400.0)
        sub = rospy.Subscriber('/gazebo/link_states', LinkStates, on_states, queue_size=1, buff_size=1 << 20,
                               tcp_nodelay=True)
        deadline = time.monotonic() + 10.0
        while not samples and time.monotonic() < deadline:  # states come at 10 Hz while paused
            time.sleep(0.05)
        self.gz.run_for(4.0)
        sub.unregister()
        self.set_update_rate(physics, physics.max_update_rate)

        crossings = []
        for (t0, a0), (t1, a1) in zip(samples, samples[1:]):
            if a0 != 0 and (a0 < 0) != (a1 < 0) and t1 >= t0:
                crossings.append(t0 + (t1 - t0) * a0 / (a0 - a1))
        self.assertGreaterEqual(len(crossings), 6, 'the pendulum did not swing: %d samples' % len(samples))
        period = 2 * float(np.median(np.diff(crossings)))
        expected = 2 * math.pi * math.sqrt((I_BOB + M * L * L) / (M * G * L))
        print('pendulum period %.5f s, small-angle theory %.5f s, error %.3f%% (%d half swings)'
              % (period, expected, 100 * abs(period - expected) / expected, len(crossings) - 1))
        self.assertAlmostEqual(period, expected, delta=0.01 * expected)

    def set_update_rate(self, physics, rate):
        done = self.gz.set_physics_properties(time_step=physics.time_step, max_update_rate=rate,
                                              gravity=physics.gravity, ode_config=physics.ode_config)
        self.assertTrue(done.success, done.status_message)

    def test_free_fall_drop_after_one_second(self):
        self.gz.pause_physics()
        self.assertTrue(self.gz.spawn_urdf('faller', BOX, pose(5, 5, 20)).success)
        t0 = self.gz.sim_time()
        self.gz.run_for(1.0)
        state = self.gz.state('faller')
        elapsed = state.header.stamp.to_sec() - t0
        drop = 20.0 - state.pose.position.z
        expected = 0.5 * G * elapsed ** 2
        print('free fall: %.6f m in %.3f s, 1/2 g t^2 = %.6f m, error %.3f%%'
              % (drop, elapsed, expected, 100 * abs(drop - expected) / expected))
        self.assertGreaterEqual(elapsed, 1.0)
        self.assertAlmostEqual(drop, expected, delta=0.002 * expected)


if __name__ == '__main__':
    rostest.rosrun('bullet_sim', 'test_physics_accuracy', PhysicsAccuracyTest)
