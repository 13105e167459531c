#!/usr/bin/env python3
"""The Joints view in a real browser (studio_joints.test, simple_model): values typed into the
panel's fields move joint_1 as the model's dynamics say they should.

joint_1 turns the arm (link_1, 1 kg, 0.6 x 0.05 x 0.05 m from 5 cm behind the axis, with the
lidar 'ray' fixed to it: 1 g, inertia 0.0167 kg m^2 about every axis) about the vertical, with
viscous damping b = 0.7 N m s/rad and no gravity along the axis. Its inertia about the axis:

    I = 1 * (0.6^2 + 0.05^2) / 12 + 1 * 0.25^2 + 0.0166667 + 0.001 * 0.5^2 = 0.109625 kg m^2

- Force: a torque tau held from rest turns the joint by tau/b * (t - T (1 - exp(-t/T))),
  T = I/b, in t seconds of sim time: checked within 5 % after 1 s, and the panel shows it.
- Reset drops the force: the arm coasts to rest (damped).
- Position: a target with P, I, D typed into the Position tab is reached within 0.01 rad.

With STUDIO_SCREENSHOTS set to a folder, docs/images' studio_joints.png is saved there.
"""
import math
import os
import sys
import time
import unittest

import rospy
import rostest
from selenium.webdriver.common.by import By
from selenium.webdriver.common.keys import Keys

from bullet_sim_testing.gazebo import Gazebo
from bullet_sim_testing.waiting import wait_until

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "browser"))
from studio_browser import click, open_browser, open_studio, save_screenshot, studio_url, wait_for  # noqa: E402

MODEL, JOINT = "simple_model", "joint_1"
INERTIA = 1.0 * (0.6 ** 2 + 0.05 ** 2) / 12 + 1.0 * 0.25 ** 2 + 0.0166667 + 0.001 * 0.5 ** 2
DAMPING = 0.7


def turned_by_torque(torque, t):
    """The angle a torque held from rest turns the damped joint in t seconds."""
    tau = INERTIA / DAMPING
    return torque / DAMPING * (t - tau * (1 - math.exp(-t / tau)))


class StudioJoints(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node("test_studio_joints")
        cls.gazebo = Gazebo(timeout=60.0)
        assert wait_until(lambda: MODEL in cls.gazebo.get_world_properties().model_names, 60.0), "no simple_model"
        cls.driver = open_browser()
        open_studio(cls.driver, studio_url())
        wait_for(cls.driver, "return window.studio.world.visualObjects() > 0", 15.0, "the scene drawn")
        # Select the model as a user would: its name in the Models tree, which the page fills from
        # the world's model list (on a busy machine after the ground plane is drawn).
        wait_for(cls.driver, "return document.querySelector(\"#models-tree li[data-model='%s'] .label\")" % MODEL,
                 15.0, "simple_model in the Models tree")
        click(cls.driver, "#models-tree li[data-model='%s'] .label" % MODEL)
        wait_for(cls.driver, "return document.querySelector('#joints-force input[data-joint=\"%s\"]')" % JOINT, 10.0,
                 "the Joints panel lists joint_1")

    @classmethod
    def tearDownClass(cls):
        cls.driver.quit()

    def joint(self):
        props = self.gazebo.get_joint_properties(joint_name="%s::%s" % (MODEL, JOINT))
        self.assertTrue(props.success, props.status_message)
        return props.position[0], props.rate[0]

    def tab(self, name):
        self.driver.find_element(By.CSS_SELECTOR, ".joint-tabs button[data-tab='%s']" % name).click()

    def type_into(self, tab, field, text):
        box = self.driver.find_element(By.CSS_SELECTOR, "#joints-%s input[data-joint='%s'][data-field='%s']"
                                       % (tab, JOINT, field))
        box.send_keys(Keys.CONTROL, "a")
        box.send_keys(text, Keys.ENTER)

    def applied(self, what):
        wait_for(self.driver, "return document.getElementById('joints-status').textContent.includes(%r)" % what, 5.0,
                 "the panel says %s" % what)

    def run_paused_for(self, sim_seconds):
        """Unpause, pause again once sim time has passed `sim_seconds`; the sim time run."""
        start = self.gazebo.sim_time()
        self.gazebo.unpause_physics()
        wait_until(lambda: self.gazebo.sim_time() >= start + sim_seconds, 30.0, step=0.01)
        self.gazebo.pause_physics()
        return self.gazebo.sim_time() - start

    def test_1_force_turns_the_joint_as_its_inertia_and_damping_say(self):
        self.assertTrue(self.gazebo.get_physics_properties().pause, "the world starts paused")
        start, rate = self.joint()
        self.assertAlmostEqual(rate, 0.0, delta=1e-6)
        torque = 0.35
        self.tab("force")
        self.type_into("force", "force", str(torque))
        self.applied("force %g applied" % torque)
        ran = self.run_paused_for(1.0)
        turned, rate = self.joint()
        turned -= start
        expected = turned_by_torque(torque, ran)
        self.assertGreater(turned, 0.95 * expected, "turned %.4f rad in %.3f s, expected %.4f" % (turned, ran, expected))
        self.assertLess(turned, 1.05 * expected, "turned %.4f rad in %.3f s, expected %.4f" % (turned, ran, expected))
        terminal = torque / DAMPING * (1 - math.exp(-ran * DAMPING / INERTIA))
        self.assertAlmostEqual(rate, terminal, delta=0.05 * terminal)
        wait_for(self.driver, "return Math.abs(Number(document.querySelector("
                              "'#joints-force .current[data-joint=\"%s\"]').textContent) - %f) < 1e-3"
                              % (JOINT, turned + start), 5.0, "the panel shows the joint's position")

        self.driver.find_element(By.ID, "joints-reset").click()
        self.applied("commands reset")
        self.run_paused_for(1.5)  # ten time constants: the damping stops it
        _, rate = self.joint()
        self.assertLess(abs(rate), 0.01, "without the force the arm comes to rest")

    def test_2_position_target_reached(self):
        target = 1.0
        self.tab("position")
        self.type_into("position", "p", "10")
        self.type_into("position", "i", "0")
        self.type_into("position", "d", "1")
        self.type_into("position", "target", str(target))
        self.applied("position target %g applied" % target)
        # With P 10, D 1 on I = 0.11, b = 0.7 the error decays as exp(-7.7 t): settled within 2 s.
        self.run_paused_for(2.0)
        position, rate = self.joint()
        self.assertAlmostEqual(position, target, delta=0.01)
        self.assertLess(abs(rate), 0.05)
        time.sleep(0.6)  # the panel's next poll
        save_screenshot(self.driver, "joints")
        self.driver.find_element(By.ID, "joints-reset").click()
        self.applied("commands reset")


if __name__ == "__main__":
    rostest.rosrun("sim_studio", "studio_joints", StudioJoints)
