#!/usr/bin/env python3
"""The RE510 lecture's step: `rostopic pub -1 .../joint1_position_controller/command
std_msgs/Float64 "data: 1.5"` moves joint_1 there, settling within 2 % in under 2 s of sim time.
Figures (overshoot, settling time) come from the controller's own stamped state messages."""
import subprocess
import time
import unittest

import rospy
import rostest
from control_msgs.msg import JointControllerState
from controller_manager_msgs.srv import ListControllers

TARGET = 1.5
BAND = 0.02 * TARGET


def step_figures(samples, target, band):
    """(start time, overshoot in % of the step, settling time) from (stamp, set_point, value)
    samples; the step starts at the first sample whose set_point is the target."""
    start = next(t for t, sp, _ in samples if abs(sp - target) < 1e-9)
    after = [(t, v) for t, _, v in samples if t >= start]
    initial = next(v for t, sp, v in reversed(samples) if t < start) if samples[0][0] < start else after[0][1]
    peak = max(v for _, v in after) if target > initial else min(v for _, v in after)
    overshoot = 100.0 * max(0.0, (peak - target) / (target - initial))
    outside = [t for t, v in after if abs(v - target) > band]
    settled_at = outside[-1] if outside else start
    return start, overshoot, settled_at - start


class StepResponseTest(unittest.TestCase):
    def test_step_to_one_and_a_half_radians(self):
        rospy.init_node('test_step_response')
        list_controllers = rospy.ServiceProxy('/simple_model/controller_manager/list_controllers', ListControllers)
        rospy.wait_for_service('/simple_model/controller_manager/list_controllers', timeout=60)
        deadline = time.monotonic() + 60
        while time.monotonic() < deadline:
            states = {c.name: c.state for c in list_controllers().controller}
            if states.get('joint1_position_controller') == 'running':
                break
            time.sleep(0.1)
        self.assertEqual(states.get('joint1_position_controller'), 'running', states)

        samples = []
        rospy.Subscriber('/simple_model/joint1_position_controller/state', JointControllerState,
                         lambda m: samples.append((m.header.stamp.to_sec(), m.set_point, m.process_value)),
                         queue_size=1000)
        rospy.sleep(0.5)
        # The lecture's command, unchanged.
        done = subprocess.run(['rostopic', 'pub', '-1', '/simple_model/joint1_position_controller/command',
                               'std_msgs/Float64', 'data: 1.5'], capture_output=True, text=True, timeout=60)
        self.assertEqual(done.returncode, 0, done.stderr)
        t0 = rospy.get_time()
        while rospy.get_time() < t0 + 4.0 and not rospy.is_shutdown():
            rospy.sleep(0.1)

        self.assertTrue(any(abs(sp - TARGET) < 1e-9 for _, sp, _ in samples), 'the command never arrived')
        start, overshoot, settling = step_figures(samples, TARGET, BAND)
        final = samples[-1][2]
        print('simple_model joint_1 step to %.2f rad: overshoot %.1f %%, settles within 2 %% in %.3f s, final %.4f rad'
              % (TARGET, overshoot, settling, final))
        self.assertLess(abs(final - TARGET), BAND)
        self.assertLess(settling, 2.0)


if __name__ == '__main__':
    rostest.rosrun('simple_model_control', 'test_step_response', StepResponseTest)
