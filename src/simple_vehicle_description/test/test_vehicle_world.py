#!/usr/bin/env python3
"""vehicle_world.launch: the xacro vehicle is spawned, stands still on its four wheels, its lidar
publishes the lecture's 32-beam vertical fan, and its skid steer drive moves it on cmd_vel, turns
it on the spot without tipping it, and holds it still when no command comes."""
import math
import unittest

import rospy
import rostest

from vehicle_checks import VehicleChecks


class VehicleWorldTest(VehicleChecks, unittest.TestCase):
    MODEL = 'simple_vehicle'
    CMD_VEL = '/simple_vehicle/cmd_vel'
    SCAN = '/simple_vehicle/scan'
    WHEEL_LINKS = ['front_left_wheel', 'front_right_wheel', 'back_left_wheel', 'back_right_wheel']
    WHEEL_SEPARATION = 1.55  # the plugin's, which sets the wheels' speeds
    BASE_HEIGHT = 0.0  # base_link is the footprint

    def test_5_wheel_motors_hold_it_against_the_lecture_torque(self):
        # As in Gazebo: the skid-steer plugin drives the wheel joints with velocity motors
        # bounded by <torque> (20 N m), so 20 N m applied to a wheel at rest does not move it.
        start = self.pose()
        for side in ('left', 'right'):
            for end in ('front', 'back'):
                done = self.apply_effort(joint_name='%s_%s_wheel_joint' % (end, side), effort=10.0,
                                         start_time=rospy.Time(0), duration=rospy.Duration(1.0))
                self.assertTrue(done.success, done.status_message)
        self.sleep_sim(1.5)
        after = self.pose()
        moved = math.hypot(after.position.x - start.position.x, after.position.y - start.position.y)
        print('10 N m a wheel against the stopped drive for 1 s: moved %.4f m' % moved)
        self.assertLess(moved, 0.05)


if __name__ == '__main__':
    rostest.rosrun('simple_vehicle_description', 'vehicle_world', VehicleWorldTest)
