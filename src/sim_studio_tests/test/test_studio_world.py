#!/usr/bin/env python3
"""The World view in a real browser (studio_world.test, the Katana world): what the page draws is
checked against the simulator, and the toolbar and a drag are checked through /gazebo and /clock.

- The scene: one object per visual /gazebo/scene_info lists, each link where
  /gazebo/get_link_state says it is (1 mm); the Models tree names get_world_properties' models.
- Pause: two /clock reads 0.5 s of wall time apart are equal (1 ms); step moves sim time by exactly
  one physics step (a tenth of a step); play: sim time runs at the target pace again (0.6-1.4x; 2x when the target
  typed into the toolbar is 2).
- Click on a can: the World, Models and Joints views select it. Drag it (the view's drag path
  without the mouse): /gazebo/get_model_state has it there within 1 cm, on the table.
- Lasers ticked: rays from the arm's laser are drawn.

With STUDIO_SCREENSHOTS set to a folder, docs/images' studio_world.png is saved there.
"""
import os
import sys
import time
import unittest

import rospy
import rostest
from gazebo_msgs.srv import GetLinkState
from rosgraph_msgs.msg import Clock
from selenium.webdriver.common.actions.action_builder import ActionBuilder
from selenium.webdriver.common.by import By
from selenium.webdriver.common.keys import Keys
from visualization_msgs.msg import Marker, MarkerArray

from bullet_sim_testing.gazebo import Gazebo
from bullet_sim_testing.waiting import wait_until

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "browser"))
from studio_browser import click, open_browser, open_studio, save_screenshot, studio_url, wait_for  # noqa: E402

MODELS = {"ground_plane", "katana", "table", "can_1", "can_2", "can_3"}
DRAWN = (Marker.CUBE, Marker.SPHERE, Marker.CYLINDER, Marker.MESH_RESOURCE)


def clock():
    return rospy.wait_for_message("/clock", Clock, timeout=5.0).clock.to_sec()


def sim_rate(wall_seconds):
    """Sim seconds per wall second over `wall_seconds`, from /clock."""
    start_sim, start_wall = clock(), time.monotonic()
    time.sleep(wall_seconds)
    return (clock() - start_sim) / (time.monotonic() - start_wall)


class StudioWorld(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node("test_studio_world")
        cls.gazebo = Gazebo(timeout=60.0)
        assert wait_until(lambda: MODELS <= set(cls.gazebo.get_world_properties().model_names), 60.0), \
            "the Katana world did not spawn its models"
        cls.driver = open_browser()
        open_studio(cls.driver, studio_url())
        cls.link_state = rospy.ServiceProxy("/gazebo/get_link_state", GetLinkState)

    @classmethod
    def tearDownClass(cls):
        cls.driver.quit()

    def js(self, script):
        return self.driver.execute_script("return " + script)

    def wait(self, script, timeout=10.0, what=None):
        return wait_for(self.driver, "return " + script, timeout, what)

    def click(self, element_id):
        self.driver.find_element(By.ID, element_id).click()

    def test_1_the_page_draws_every_visual_where_the_simulator_has_it(self):
        scene = rospy.wait_for_message("/gazebo/scene_info", MarkerArray, timeout=10.0).markers
        visuals = [m for m in scene if m.type in DRAWN and m.action == Marker.ADD]
        self.wait("window.studio.world.visualObjects() === %d && window.studio.world.meshesLoaded()" % len(visuals),
                  15.0, "the page should draw the %d visuals of scene_info" % len(visuals))
        self.assertEqual(self.js("window.studio.world.visualCount()"), len(visuals))
        for link in ("table::table_link", "can_1::can_link", "katana::katana_motor1_pan_link"):
            state = self.link_state(link_name=link, reference_frame="world")
            self.assertTrue(state.success, state.status_message)
            p = state.link_state.pose.position
            shown = self.wait("window.studio.world.linkPosition(%r)" % link, 5.0, "%s drawn" % link)
            for i, value in enumerate((p.x, p.y, p.z)):
                self.assertAlmostEqual(shown[i], value, delta=1e-3, msg="%s %s" % (link, "xyz"[i]))
        names = lambda: sorted(e.get_attribute("data-model") for e in self.driver.find_elements(  # noqa: E731
            By.CSS_SELECTOR, "#models-tree > li"))
        self.assertTrue(wait_until(lambda: names() == sorted(self.gazebo.get_world_properties().model_names), 10.0),
                        names())

    def test_2_pause_step_and_play_from_the_toolbar(self):
        playing = "document.getElementById('world-playpause').dataset.paused === 'false'"
        self.wait(playing, 10.0, "the toolbar should show the world running")
        self.click("world-playpause")
        self.wait("document.getElementById('world-playpause').dataset.paused === 'true'", 5.0, "paused")
        self.assertTrue(self.gazebo.get_physics_properties().pause)
        first = clock()
        time.sleep(0.5)
        self.assertAlmostEqual(clock(), first, delta=0.001, msg="sim time must stand still while paused")

        step = self.gazebo.get_physics_properties().time_step
        self.click("world-step")
        self.wait("document.getElementById('world-status').textContent.startsWith('stepped')", 5.0, "a step")
        self.assertTrue(self.gazebo.get_physics_properties().pause, "still paused after a step")
        self.assertAlmostEqual(clock() - first, step, delta=step / 10, msg="one physics step")
        self.assertEqual(self.gazebo.get_physics_properties().max_update_rate, 1000.0, "the pace is untouched")

        self.click("world-playpause")
        self.wait(playing, 5.0, "playing again")
        rate = sim_rate(2.0)
        self.assertGreater(rate, 0.6)
        self.assertLess(rate, 1.4)
        shown = float(self.driver.find_element(By.ID, "world-simtime").get_attribute("data-seconds"))
        self.assertAlmostEqual(shown, clock(), delta=1.0)

        target = self.driver.find_element(By.ID, "world-target")
        target.send_keys(Keys.CONTROL, "a")
        target.send_keys("2", Keys.ENTER)
        self.assertTrue(wait_until(lambda: abs(self._target() - 2.0) < 1e-9, 5.0), self._target())
        rate = sim_rate(2.0)
        self.assertGreater(rate, 1.4)
        self.assertLess(rate, 2.6)
        target.send_keys(Keys.CONTROL, "a")
        target.send_keys("1", Keys.ENTER)
        self.assertTrue(wait_until(lambda: abs(self._target() - 1.0) < 1e-9, 5.0), self._target())

    def _target(self):
        props = self.gazebo.get_physics_properties()
        return props.max_update_rate * props.time_step

    def test_3_click_selects_and_drag_moves_a_can(self):
        self.wait("window.studio.world.screenPosition('can_1')", 10.0, "can_1 on screen")
        x, y = self.js("window.studio.world.screenPosition('can_1')")
        mouse = ActionBuilder(self.driver)
        mouse.pointer_action.move_to_location(int(x), int(y))
        mouse.pointer_action.click()
        mouse.perform()
        self.wait("window.studio.world.selected() === 'can_1'", 5.0, "a click on can_1 selects it")
        self.wait("window.studio.models.selected() === 'can_1' && window.studio.joints.model() === 'can_1'", 5.0,
                  "Models and Joints follow the selection")

        before = self.gazebo.state("can_1").pose.position
        goal = (0.45, -0.35)  # on the table (x -0.35..0.65, y -0.5..0.5), clear of the arm
        reply = self.driver.execute_async_script(
            "const done = arguments[arguments.length - 1];"
            "window.studio.world.dragTo('can_1', %f, %f).then(done, (e) => done({error: String(e)}));" % goal)
        self.assertNotIn("error", reply)
        time.sleep(0.5)
        after = self.gazebo.state("can_1").pose.position
        self.assertAlmostEqual(after.x, goal[0], delta=0.01)
        self.assertAlmostEqual(after.y, goal[1], delta=0.01)
        self.assertAlmostEqual(after.z, before.z, delta=0.01, msg="still standing on the table")
        self.wait("Math.hypot(window.studio.world.linkPosition('can_1::can_link')[0] - %f, "
                  "window.studio.world.linkPosition('can_1::can_link')[1] - %f) < 0.01" % goal, 5.0,
                  "the page draws the can where it was dragged")
        # The docs' picture: the arm selected in the tree, its joints in the Joints panel.
        click(self.driver, "#models-tree li[data-model='katana'] .label")
        self.wait("document.querySelectorAll('#joints-force .joint-row').length > 0", 5.0, "the arm's joints")
        time.sleep(0.6)
        save_screenshot(self.driver, "world")

    def test_4_laser_rays_when_ticked(self):
        self.assertEqual(self.js("window.studio.world.rayCount()"), 0)
        self.click("world-lasers")
        count = self.wait("window.studio.world.rayCount()", 10.0, "rays from the Katana's laser")
        self.assertGreater(count, 10)
        self.click("world-lasers")
        self.wait("window.studio.world.rayCount() === 0", 5.0, "rays hidden again")


if __name__ == "__main__":
    rostest.rosrun("sim_studio", "studio_world", StudioWorld)
