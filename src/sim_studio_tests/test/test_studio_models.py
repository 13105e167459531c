#!/usr/bin/env python3
"""The Models view in a real browser (studio_models.test, the dual arm world): the tree is the
simulator's, and insert, select and delete do to the simulator what they say.

- The tree lists get_world_properties' models, each with get_model_properties' links and joints;
  the World view has loaded every STL mesh the scene names.
- Insert a box at a typed position: the simulator has unit_box there (1 cm), the tree and the 3D
  view show it; a second box is unit_box_0.
- Insert a model the simulator refuses (broken_box, a box with two sizes): the simulator's
  status_message is shown and nothing is spawned.
- Select in the tree: the properties show the pose get_model_state gives (1 mm) and the box's mass,
  1 kg as Gazebo's inserted shapes have (get_link_properties). Delete: gone
  from the simulator, the tree and the 3D view.
"""
import os
import sys
import unittest

import rospy
import rostest
from selenium.webdriver.common.by import By
from selenium.webdriver.support.ui import Select
from visualization_msgs.msg import Marker, MarkerArray

from bullet_sim_testing.gazebo import Gazebo
from bullet_sim_testing.waiting import wait_until

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "browser"))
from studio_browser import click, open_browser, open_studio, studio_url, wait_for  # noqa: E402


class StudioModels(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node("test_studio_models")
        cls.gazebo = Gazebo(timeout=60.0)
        assert wait_until(lambda: "arm" in cls.gazebo.get_world_properties().model_names, 60.0), "no arm"
        cls.driver = open_browser()
        open_studio(cls.driver, studio_url())

    @classmethod
    def tearDownClass(cls):
        cls.driver.quit()

    def css(self, selector):
        return self.driver.find_element(By.CSS_SELECTOR, selector)

    def wait(self, script, timeout=10.0, what=None):
        return wait_for(self.driver, "return " + script, timeout, what)

    def tree(self):
        return self.driver.execute_script(
            "return [...document.querySelectorAll('#models-tree > li')].map((li) => [li.dataset.model, "
            "[...li.querySelectorAll('li.link')].map((e) => e.dataset.link), "
            "[...li.querySelectorAll('li.joint')].map((e) => e.dataset.joint)])")

    def names(self):
        return sorted(self.gazebo.get_world_properties().model_names)

    def status(self):
        return self.css("#models-status").text

    def test_1_the_tree_is_the_simulators(self):
        self.assertTrue(wait_until(lambda: sorted(m for m, _, _ in self.tree()) == self.names(), 10.0), self.tree())
        for model, links, joints in self.tree():
            props = self.gazebo.get_model_properties(model_name=model)
            self.assertEqual(links, list(props.body_names), model)
            self.assertEqual(joints, list(props.joint_names), model)
        scene = rospy.wait_for_message("/gazebo/scene_info", MarkerArray, timeout=10.0).markers
        meshes = [m for m in scene if m.type == Marker.MESH_RESOURCE]
        self.assertGreater(len(meshes), 0, "the arm's STL meshes")
        self.wait("window.studio.world.meshesLoaded() && window.studio.world.visualObjects() === %d"
                  % len([m for m in scene if m.action == Marker.ADD and m.type != Marker.LINE_LIST]), 15.0,
                  "every visual drawn, meshes loaded")
        errors = self.driver.execute_script(
            "const errors = []; window.studio.world.scene3d().scene.traverse((o) => { "
            "if (o.userData.error) errors.push(o.userData.error); }); return errors;")
        self.assertEqual(errors, [])

    def insert_box(self, x, y):
        if not self.css("#models-insert-section").get_attribute("open"):
            self.css("#models-insert-section summary").click()
        for axis, value in (("x", x), ("y", y)):
            field = self.css("#models-" + axis)
            field.clear()
            field.send_keys(str(value))
        self.css("button[data-shape='box']").click()

    def test_2_insert_a_box_and_a_model_the_simulator_refuses(self):
        visuals = self.driver.execute_script("return window.studio.world.visualObjects()")
        self.insert_box(1.5, 0.5)
        self.assertTrue(wait_until(lambda: "unit_box" in self.names(), 10.0), self.names())
        self.wait("document.getElementById('models-status').textContent === 'inserted unit_box'", 5.0)
        p = self.gazebo.state("unit_box").pose.position
        self.assertAlmostEqual(p.x, 1.5, delta=0.01)
        self.assertAlmostEqual(p.y, 0.5, delta=0.01)
        self.assertAlmostEqual(p.z, 0.5, delta=0.01)  # standing on the ground
        self.wait("document.querySelector(\"#models-tree li[data-model='unit_box']\")", 5.0, "unit_box in the tree")
        self.wait("window.studio.world.visualObjects() === %d" % (visuals + 1), 5.0, "unit_box drawn")
        self.insert_box(-1.5, 0.5)
        self.assertTrue(wait_until(lambda: "unit_box_0" in self.names(), 10.0), self.names())

        Select(self.css("#models-library")).select_by_visible_text("broken_box")
        before = self.names()
        self.css("#models-insert").click()
        self.wait("document.getElementById('models-status').classList.contains('error')", 10.0, "an error shown")
        self.assertIn("size", self.status())  # the simulator's own words about the box's size
        self.assertIn("SpawnModel", self.status())
        self.assertEqual(self.names(), before, "nothing spawned")

    def test_3_select_shows_the_pose_and_delete_removes(self):
        click(self.driver, "#models-tree li[data-model='unit_box'] .label")
        self.wait("window.studio.world.selected() === 'unit_box'", 5.0, "the World selects it too")
        self.wait("document.getElementById('models-position') && "
                  "document.getElementById('models-position').textContent.trim() !== ''", 5.0, "a pose shown")
        p = self.gazebo.state("unit_box").pose.position
        shown = [float(v) for v in self.css("#models-position").text.split()]
        for i, value in enumerate((p.x, p.y, p.z)):
            self.assertAlmostEqual(shown[i], value, delta=1e-3)
        mass = self.css("#models-links tr[data-link='link'] .mass").text
        self.assertAlmostEqual(float(mass), 1.0, delta=1e-3)
        visuals = self.driver.execute_script("return window.studio.world.visualObjects()")
        self.css("#models-delete").click()
        self.assertTrue(wait_until(lambda: "unit_box" not in self.names(), 10.0), self.names())
        self.wait("!document.querySelector(\"#models-tree li[data-model='unit_box']\")", 5.0, "gone from the tree")
        self.wait("window.studio.world.visualObjects() === %d" % (visuals - 1), 5.0, "gone from the 3D view")
        self.assertIn("deleted", self.status())


if __name__ == "__main__":
    rostest.rosrun("sim_studio", "studio_models", StudioModels)
