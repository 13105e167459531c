#!/usr/bin/env python3
"""The studio when pages and the simulator come and go (studio_reliability.test, an empty world
whose simulator respawns), two headless Chromium pages open on it:

- Two pages at once: both draw a crate where /gazebo/get_link_state has it (1 mm); a pause from
  one shows in the other (and in the simulator), and a play from the other likewise; the studio
  counts two pages (/status.json).
- A page reloads: it draws the world again, the studio still counts two pages (the old one
  forgotten), and both follow the crate when it is moved (1 mm).
- The simulator restarts (killed, respawned by roslaunch with a fresh world): both pages drop the
  crate, show the new sim time (below the old, and running on), draw a box spawned into the new
  simulator where it is (1 mm), and the toolbar's pause reaches the new simulator.
- ROS time in the studio is the new simulator's: a Message Publisher row publishing `t` at 10 Hz
  sends the sim time it is sent at (within 0.1 s of the receiver's, far below the wall clock's
  1.8e9 s), rising with it.
"""
import json
import os
import subprocess
import sys
import time
import unittest
import urllib.request

import rospy
import rostest
from geometry_msgs.msg import Pose
from std_msgs.msg import Float64
from selenium.webdriver.common.by import By

from bullet_sim_testing.gazebo import Gazebo
from bullet_sim_testing.waiting import wait_until

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "browser"))
from studio_browser import open_browser, open_studio, studio_url, wait_for  # noqa: E402

BOX = """<?xml version="1.0"?>
<sdf version="1.6"><model name="box"><link name="link">
  <inertial><mass>1</mass><inertia><ixx>0.01</ixx><iyy>0.01</iyy><izz>0.01</izz></inertia></inertial>
  <collision name="c"><geometry><box><size>0.2 0.2 0.2</size></box></geometry></collision>
  <visual name="v"><geometry><box><size>0.2 0.2 0.2</size></box></geometry></visual>
</link></model></sdf>"""
PLAYING = "document.getElementById('world-playpause').dataset.paused === '%s'"


def at(x, y, z=0.1):
    p = Pose()
    p.position.x, p.position.y, p.position.z = x, y, z
    p.orientation.w = 1.0
    return p


class StudioReliability(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node("test_studio_reliability")
        cls.gazebo = Gazebo(timeout=60.0)
        cls.url = studio_url()
        cls.pages = [open_browser(), open_browser()]
        for page in cls.pages:
            open_studio(page, cls.url)

    @classmethod
    def tearDownClass(cls):
        for page in cls.pages:
            page.quit()

    # --- helpers ----------------------------------------------------------------------------------
    def spawn(self, name, x, y):
        reply = self.gazebo.spawn_sdf_model(model_name=name, model_xml=BOX, robot_namespace="", initial_pose=at(x, y),
                                            reference_frame="")
        self.assertTrue(reply.success, reply.status_message)

    def where(self, link):
        state = self.gazebo.get_link_state(link_name=link, reference_frame="world")
        self.assertTrue(state.success, state.status_message)
        p = state.link_state.pose.position
        return p.x, p.y, p.z

    def assertDrawnWhereItIs(self, page, link):
        """The page draws `link` where the simulator has it (1 mm), once both have settled."""
        def matches():
            shown = page.execute_script("return window.studio.world.linkPosition(%r)" % link)
            return shown is not None and all(abs(a - b) < 1e-3 for a, b in zip(shown, self.where(link)))
        self.assertTrue(wait_until(matches, 10.0), "%s: drawn at %s, simulated at %s" % (
            link, page.execute_script("return window.studio.world.linkPosition(%r)" % link), self.where(link)))

    def page_count(self):
        with urllib.request.urlopen(self.url.split("?")[0].rstrip("/") + "/status.json", timeout=5) as reply:
            return json.load(reply)["pages"]

    def drawn_models(self, page):
        # one script: the tree is rebuilt when the models change, so elements found first may be gone
        return sorted(page.execute_script(
            "return [...document.querySelectorAll('#models-tree > li')].map((li) => li.dataset.model)"))

    def shown_sim_time(self, page):
        return float(page.execute_script("return document.getElementById('world-simtime').dataset.seconds || 'nan'"))

    # --- the tests ----------------------------------------------------------------------------------
    def test_1_two_pages_at_once(self):
        first, second = self.pages
        self.spawn("crate", 1.0, 0.5)
        for page in self.pages:
            self.assertDrawnWhereItIs(page, "crate::link")
        self.assertEqual(self.page_count(), 2)

        first.find_element(By.ID, "world-playpause").click()
        wait_for(second, "return " + PLAYING % "true", 5.0, "the other page should show the pause")
        self.assertTrue(self.gazebo.get_physics_properties().pause)
        second.find_element(By.ID, "world-playpause").click()
        wait_for(first, "return " + PLAYING % "false", 5.0, "the first page should show play")
        self.assertFalse(self.gazebo.get_physics_properties().pause)

    def test_2_a_page_reloads(self):
        first, second = self.pages
        second.refresh()
        open_studio(second, self.url)
        self.assertDrawnWhereItIs(second, "crate::link")
        self.assertTrue(wait_until(lambda: self.page_count() == 2, 5.0), "pages: %d" % self.page_count())
        self.assertTrue(self.gazebo.set_state("crate", at(-1.0, 1.5)).success)
        for page in self.pages:
            self.assertAlmostEqual(self.where("crate::link")[0], -1.0, delta=0.01)
            self.assertDrawnWhereItIs(page, "crate::link")

    def test_3_the_simulator_restarts(self):
        before = max(self.shown_sim_time(page) for page in self.pages)
        self.assertGreater(before, 0.0)
        subprocess.run(["rosnode", "kill", "/gazebo"], check=True, capture_output=True, timeout=30)
        # The respawned simulator: a fresh world (no crate), its time from zero.
        fresh = lambda: "crate" not in self.gazebo.get_world_properties().model_names  # noqa: E731
        self.assertTrue(wait_until(lambda: self._answers() and fresh(), 60.0), "the simulator did not come back")
        restarted = self.gazebo.sim_time()
        self.assertLess(restarted, before)
        for page in self.pages:
            self.assertTrue(wait_until(lambda: "crate" not in self.drawn_models(page), 10.0), self.drawn_models(page))
            wait_for(page, "return !window.studio.world.linkPosition('crate::link')", 10.0, "the crate undrawn")
            self.assertTrue(wait_until(lambda: self.shown_sim_time(page) < before, 10.0),
                            "shown %.3f s, before the restart %.3f s" % (self.shown_sim_time(page), before))
        shown = self.shown_sim_time(self.pages[0])
        self.assertTrue(wait_until(lambda: self.shown_sim_time(self.pages[0]) > shown + 0.5, 10.0), "time runs on")

        self.spawn("after_restart", 0.5, -0.5)
        for page in self.pages:
            self.assertDrawnWhereItIs(page, "after_restart::link")
        self.pages[0].find_element(By.ID, "world-playpause").click()
        wait_for(self.pages[1], "return " + PLAYING % "true", 5.0, "the pause shown on the other page")
        self.assertTrue(self.gazebo.get_physics_properties().pause, "the pause reached the new simulator")

    def test_4_ros_time_is_the_simulators(self):
        self.gazebo.unpause_physics()
        received = []
        subscriber = rospy.Subscriber("/studio_sim_t", Float64, lambda m: received.append((m.data, rospy.get_time())))
        page = self.pages[0]
        request = ("const done = arguments[arguments.length - 1];"
                   "window.studio.publisher.request(%s).then((r) => done(r), (e) => done({error: e.message}));")
        added = page.execute_async_script(request % "'add', {topic: '/studio_sim_t', msg_type: 'std_msgs/Float64'}")
        self.assertNotIn("error", added)
        started = page.execute_async_script(request % ("'set', {publisher: %d, fields: {data: 't'}, rate: 10, "
                                                        "enabled: true}" % added["publisher"]))
        self.assertNotIn("error", started)
        self.assertTrue(wait_until(lambda: len(received) >= 20, 10.0), "%d messages" % len(received))
        page.execute_async_script(request % ("'remove', {publisher: %d}" % added["publisher"]))
        subscriber.unregister()
        for sent, arrived in received[2:]:
            self.assertAlmostEqual(sent, arrived, delta=0.1)
            self.assertLess(sent, 1000.0)
        values = [sent for sent, _ in received]
        self.assertEqual(values, sorted(values))
        self.assertGreater(values[-1] - values[0], 1.0)  # 20 messages at 10 Hz: about 2 s of sim time

    def _answers(self):
        try:
            self.gazebo = Gazebo(timeout=1.0)
            return self.gazebo.alive()
        except Exception:  # not up yet: the old proxies point at the killed node
            return False


if __name__ == "__main__":
    rostest.rosrun("sim_studio_tests", "studio_reliability", StudioReliability)
