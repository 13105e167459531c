#!/usr/bin/env python3
"""The arm exercise runs headless and both arms track their commands: the RMS of each
controller's error (set point - position, from its stamped state messages) over two cycles."""
import math
import subprocess
import unittest

import rospy
import rostest
from control_msgs.msg import JointControllerState

JOINTS = ['joint1_1', 'joint1_2', 'joint2_1', 'joint2_2', 'joint3_1']
SECONDS = 8.0  # two 4 s exercise cycles


class ExerciseTest(unittest.TestCase):
    def test_both_arms_track_the_exercise(self):
        rospy.init_node('test_exercise')
        samples = {j: [] for j in JOINTS}
        for joint in JOINTS:
            rospy.Subscriber('/arm/%s_controller/state' % joint, JointControllerState,
                             lambda m, j=joint: samples[j].append((m.set_point, m.process_value)), queue_size=1000)
        # Wait until the exercise has started moving the shoulders, let the first cycle (the
        # controllers catching up from rest) go by, then record.
        deadline = rospy.Time.now() + rospy.Duration(60)
        while not any(abs(sp - 0.1) > 0.05 for sp, _ in samples['joint1_1']) and rospy.Time.now() < deadline:
            rospy.sleep(0.1)
        rospy.sleep(4.0)
        for s in samples.values():
            s.clear()
        t0 = rospy.get_time()
        while rospy.get_time() < t0 + SECONDS and not rospy.is_shutdown():
            rospy.sleep(0.1)
        report = []
        for joint in JOINTS:
            data = samples[joint]
            self.assertGreater(len(data), 100, 'too few states from %s_controller' % joint)
            rms = math.sqrt(sum((sp - pv) ** 2 for sp, pv in data) / len(data))
            travel = max(pv for _, pv in data) - min(pv for _, pv in data)
            report.append((joint, rms, travel))
        print('arm exercise tracking: ' + '; '.join('%s rms %.4f rad over %.2f rad of travel' % r for r in report))
        self.check_the_reports_commands()
        for joint, rms, travel in report:
            self.assertGreater(travel, 0.5, '%s barely moved' % joint)
            self.assertLess(rms, 0.05, '%s tracks poorly' % joint)


    def check_the_reports_commands(self):
        """The report's switch_controller and rostopic commands, as written (namespace /arm)."""
        def run(*argv):
            done = subprocess.run(list(argv), capture_output=True, text=True, timeout=60)
            self.assertEqual(done.returncode, 0, done.stdout + done.stderr)
            return done.stdout
        switch = '/arm/controller_manager/switch_controller'
        self.assertIn('ok: True', run('rosservice', 'call', switch,
                                      "{start_controllers: [], stop_controllers: ['joint1_1_controller'], strictness: 2}"))
        self.assertIn('ok: True', run('rosservice', 'call', switch,
                                      "{start_controllers: ['joint1_1_controller'], stop_controllers: [], strictness: 2}"))
        run('rostopic', 'pub', '-1', '/arm/joint1_1_controller/command', 'std_msgs/Float64', 'data: 1.57')


if __name__ == '__main__':
    rostest.rosrun('arm_control', 'test_exercise', ExerciseTest)
