#!/usr/bin/env python3
"""rqt's stand-ins in a real browser (studio_tools.test): the controls are clicked and typed in
headless Chromium, what they do is checked with rospy, and what the page shows is read back.

- Publisher: `sin(i/100)` on a std_msgs/Float64 at 10 Hz arrives as sin(k/100) for consecutive k
  (within 1e-9) at 10 Hz ± 15 %; a text in the float field, or a field the type lacks, is an error
  naming the field, and nothing is published.
- Plot: the values plotted are the values published (every one at 50 Hz; at 1 kHz a decimated
  subset, in order, within the points-per-second budget).
- Topics: the known talker's rate within ± 15 % of 20 Hz, its type and publisher count; its echo.
- Graph: the known talker, its topic and the listener, with the edges between them.
- Images: a synthetic rgb8 image's size and colours, and a 32FC1 depth image scaled as image_view.

With STUDIO_SCREENSHOTS set to a folder, the docs' screenshots are saved there.
"""
import math
import os
import sys
import threading
import time
import unittest

import numpy
import rospy
import rostest
from selenium.webdriver.common.by import By
from selenium.webdriver.support.ui import Select
from sensor_msgs.msg import Image
from std_msgs.msg import Float64

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "browser"))
from studio_browser import open_browser, open_studio, save_screenshot, studio_url, wait_for  # noqa: E402


class Collector:
    """A rospy subscriber that keeps (value, wall time of arrival) of every message."""

    def __init__(self, topic):
        self.items = []
        self._subscriber = rospy.Subscriber(topic, Float64, self._received, queue_size=1000)

    def _received(self, msg):
        self.items.append((msg.data, time.time()))

    def wait(self, count, timeout):
        deadline = time.time() + timeout
        while len(self.items) < count and time.time() < deadline:
            time.sleep(0.05)
        return list(self.items)

    def close(self):
        self._subscriber.unregister()


class StudioTools(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node("test_studio_tools")
        cls.driver = open_browser()
        open_studio(cls.driver, studio_url())

    @classmethod
    def tearDownClass(cls):
        cls.driver.quit()

    # --- helpers ----------------------------------------------------------------------------
    def show(self, view):
        self.driver.find_element(By.CSS_SELECTOR, "#tabs button[data-page='page-%s']" % view).click()

    def css(self, selector, within=None):
        return (within or self.driver).find_element(By.CSS_SELECTOR, selector)

    def type_into(self, selector, text, within=None):
        field = self.css(selector, within)
        field.clear()
        field.send_keys(text)
        return field

    def wait(self, script, timeout=10.0, what=None):
        return wait_for(self.driver, script, timeout, what)

    def add_publisher(self, topic, rate):
        self.show("publisher")
        # the type first: leaving the topic field fills an empty type with the topic's known one
        self.type_into("#publisher-type", "std_msgs/Float64")
        self.type_into("#publisher-topic", topic)
        self.type_into("#publisher-rate", str(rate))
        self.css("#publisher-add").click()
        try:
            self.wait("return document.querySelector('.publisher[data-topic=\"%s\"]')" % topic)
        except AssertionError as e:
            raise AssertionError("no publisher row for %s; the page says: %r (%s)"
                                 % (topic, self.css("#publisher-error").text, e)) from None
        return self.css('.publisher[data-topic="%s"]' % topic)

    # --- publisher --------------------------------------------------------------------------
    def test_publisher_sends_sin_i_over_100_at_10_hz(self):
        received = Collector("/studio_test/sine")
        row = self.add_publisher("/studio_test/sine", 10)
        self.type_into('input.publisher-expression[data-path="data"]', "sin(i/100)", row)
        self.css("input.publisher-enabled", row).click()
        items = received.wait(36, timeout=10.0)
        self.wait("return /\\d+ published at 10 Hz/.test(document.querySelector("
                  "'.publisher[data-topic=\"/studio_test/sine\"] .publisher-status').textContent)",
                  what="the row does not say it publishes")
        save_screenshot(self.driver, "publisher")
        self.css("input.publisher-enabled", row).click()  # stop
        received.close()
        self.assertGreaterEqual(len(items), 36, "only %d messages in 10 s at 10 Hz" % len(items))

        values = [v for v, _ in items]
        k0 = round(math.asin(values[0]) * 100)  # i stays below 157 here, where sin is monotonic
        self.assertGreaterEqual(k0, 1)  # rqt's i counts from 1
        for j, value in enumerate(values):
            self.assertAlmostEqual(value, math.sin((k0 + j) / 100.0), delta=1e-9,
                                   msg="message %d: %r is not sin(%d/100)" % (j, value, k0 + j))
        # the rate from arrival times, past the first messages (the connection's set-up)
        times = [t for _, t in items[5:]]
        rate = (len(times) - 1) / (times[-1] - times[0])
        self.assertGreater(rate, 10 * 0.85)
        self.assertLess(rate, 10 * 1.15)

    def test_publisher_bad_field_is_named_and_nothing_is_published(self):
        received = Collector("/studio_test/bad")
        row = self.add_publisher("/studio_test/bad", 10)
        pid = int(row.get_attribute("data-publisher"))
        self.type_into('input.publisher-expression[data-path="data"]', "'ten'", row)
        self.css("button.publisher-once", row).click()
        status = "document.querySelector('.publisher[data-topic=\"/studio_test/bad\"] .publisher-status')"
        text = self.wait("return %s.textContent.includes('expected a number') && %s.textContent" % (status, status),
                         what="no error for a text in a float64 field")
        self.assertIn("field 'data' (float64)", text)
        self.wait("return %s.classList.contains('tool-error')" % status)
        self.css("input.publisher-enabled", row).click()  # publishing at the rate: refused the same way
        # The refusal unchecks the box when the server's answer comes (the error class is still there from the
        # publish above, so wait for the box, not for the class).
        enabled = "document.querySelector('.publisher[data-topic=\"/studio_test/bad\"] .publisher-enabled')"
        self.wait("return !%s.checked && %s.classList.contains('tool-error') && !%s.textContent.includes('published')"
                  % (enabled, status, status), what="the box still checked after a refused publisher")
        self.assertFalse(self.css("input.publisher-enabled", row).is_selected())
        # a field std_msgs/Float64 does not have, sent as the view's controls send a publish
        error = self.driver.execute_async_script(
            "const done = arguments[arguments.length - 1];"
            "window.studio.publisher.request('once', {publisher: %d, fields: {data: '1.0', velocity: '2'}})"
            ".then(() => done('published'), (e) => done(e.message));" % pid)
        self.assertIn("field 'velocity': std_msgs/Float64 has no such field", error)
        time.sleep(1.0)  # a message would have arrived by now
        received.close()
        self.assertEqual(received.items, [])

    # --- plot -------------------------------------------------------------------------------
    def test_plot_shows_the_published_values(self):
        slow = rospy.Publisher("/studio_test/wave", Float64, queue_size=100)
        fast = rospy.Publisher("/studio_test/fast", Float64, queue_size=1000)
        published = {"wave": [], "fast": []}
        stop = threading.Event()

        def publish(publisher, key, rate, value):
            pace = rospy.Rate(rate)
            k = 0
            while not stop.is_set() and not rospy.is_shutdown():
                k += 1
                published[key].append(value(k))
                publisher.publish(Float64(value(k)))
                pace.sleep()
        threads = [threading.Thread(target=publish, args=(slow, "wave", 50, lambda k: math.sin(k / 10.0))),
                   threading.Thread(target=publish, args=(fast, "fast", 1000, lambda k: 0.5 * math.cos(k / 400.0)))]
        for thread in threads:
            thread.start()
        try:
            self.show("plot")
            wait_for_topic = time.time() + 10
            while not {"/studio_test/wave", "/studio_test/fast"} <= {t for t, _ in rospy.get_published_topics()}:
                self.assertLess(time.time(), wait_for_topic, "the test's publishers never registered")
                time.sleep(0.1)
            for path in ("/studio_test/wave/data", "/studio_test/fast/data"):
                self.type_into("#plot-path", path)
                self.css("#plot-add").click()
                self.wait("return document.querySelector('.plot-chip[data-path=\"%s\"]')" % path,
                          what="%s was not added: %s" % (path, self.css("#plot-error").text))
            self.type_into("#plot-window", "4")
            started = time.time()
            self.wait("const s = window.studio.plot.series();"
                      "return s['/studio_test/wave/data'].v.length >= 150 && s['/studio_test/fast/data'].v.length > 0",
                      timeout=15, what="the plot did not fill")
            elapsed = time.time() - started
            save_screenshot(self.driver, "plot")
            series = self.driver.execute_script("return window.studio.plot.series()")
            drawn = self.driver.execute_script("return window.studio.plot.drawn()")
            png = self.driver.execute_script("return window.studio.plot.png()")
            csv_text = self.driver.execute_async_script(
                "const done = arguments[arguments.length - 1];"
                "window.studio.plot.csv().then(done, (e) => done(String(e)));")
        finally:
            stop.set()
            for thread in threads:
                thread.join()

        # 50 Hz is under the budget: every value arrives, in order, at increasing times
        wave = series["/studio_test/wave/data"]
        k0 = published["wave"].index(wave["v"][0])
        self.assertEqual(wave["v"], published["wave"][k0:k0 + len(wave["v"])])
        self.assertTrue(all(b > a for a, b in zip(wave["t"], wave["t"][1:])))
        self.assertLess(abs(wave["t"][-1] - rospy.get_time()), 5.0)  # ROS time on the x axis
        # 1 kHz is decimated: published values only, in the order published, at most ~200 a second
        # (plus a min/max pair per send); each value is unique in this run, so it names its message
        fast = series["/studio_test/fast/data"]["v"]
        index = {v: k for k, v in enumerate(published["fast"])}
        self.assertTrue(all(v in index for v in fast), "a plotted value was never published")
        order = [index[v] for v in fast]
        self.assertEqual(order, sorted(set(order)))
        seconds = elapsed + 1.0
        self.assertLess(len(fast), 200 * seconds + 2 * 10 * seconds)
        self.assertGreater(len(published["fast"]), 3 * len(fast))
        self.assertGreater(len(fast), 100)
        # the chart draws them: its columns are time plus one per series
        self.assertEqual(len(drawn), 3)
        self.assertGreater(len(drawn[0]), 50)
        # PNG: the chart as drawn; CSV: every sample the server kept, at full rate
        self.assertTrue(png.startswith("data:image/png;base64,") and len(png) > 5000)
        rows = [line.split(",") for line in csv_text.strip().splitlines()]
        self.assertEqual(rows[0], ["field", "time", "value"])
        fast_rows = [float(r[2]) for r in rows[1:] if r[0] == "/studio_test/fast/data"]
        self.assertGreater(len(fast_rows), 2 * len(fast))  # not decimated
        k = index[fast_rows[0]]
        self.assertEqual(fast_rows, published["fast"][k:k + len(fast_rows)])

    # --- topics -----------------------------------------------------------------------------
    def test_topic_monitor_rate_type_and_echo(self):
        self.show("topics")
        row = 'tr[data-topic="/studio_test/rate"]'
        self.wait("return document.querySelector('%s')" % row, timeout=10,
                  what="the known talker's topic is not listed")
        self.css(row + " input.topics-monitor").click()
        self.css(row + " a.topics-name").click()
        time.sleep(3.0)  # 60 messages of the window
        rate = self.wait("return document.querySelector('%s').dataset.rate" % row, what="no rate")
        self.assertGreater(float(rate), 20 * 0.85)
        self.assertLess(float(rate), 20 * 1.15)
        self.assertEqual(self.css(row + " .topics-type").text, "std_msgs/Float64")
        self.assertEqual(self.css(row).get_attribute("data-publishers"), "1")
        bandwidth = float(self.css(row).get_attribute("data-bandwidth"))
        self.assertGreater(bandwidth, 8 * 20 * 0.7)  # a Float64 is 8 bytes
        self.assertLess(bandwidth, 8 * 20 * 1.3)
        self.wait("return document.querySelector('#topics-echo li[data-path=\"/data\"] .topics-value')"
                  "?.textContent === '2.5'", what="the echo does not show data: 2.5")
        save_screenshot(self.driver, "topics")
        # the same topic plotted while monitored: rospy shares one subscription per topic in a
        # process, so the monitor must not have made it one that hands the plot undecoded messages
        self.show("plot")
        self.type_into("#plot-path", "/studio_test/rate/data")
        self.css("#plot-add").click()
        values = self.wait("const s = window.studio.plot.series()['/studio_test/rate/data'];"
                           "return s && s.v.length >= 5 && s.v", what="the monitored topic is not plotted")
        self.assertEqual(set(values), {2.5})

    # --- graph ------------------------------------------------------------------------------
    def test_graph_lists_the_known_nodes_and_topic(self):
        self.show("graph")
        self.css("#graph-refresh").click()
        titles = self.wait("const t = [...document.querySelectorAll('#graph-svg svg g title')].map(e => e.textContent);"
                           "return t.includes('n:/known_talker') && t", what="the graph has no known_talker")
        for title in ("n:/known_listener", "t:/studio_test/rate", "n:/known_talker->t:/studio_test/rate",
                      "t:/studio_test/rate->n:/known_listener"):
            self.assertIn(title, titles)
        labels = self.driver.execute_script(
            "return [...document.querySelectorAll('#graph-svg svg text')].map(e => e.textContent)")
        self.assertIn("/studio_test/rate", labels)
        self.assertNotIn("/rosout", labels)  # hidden as debug, as rqt_graph hides it
        save_screenshot(self.driver, "graph")

    # --- images -----------------------------------------------------------------------------
    def test_images_show_colour_and_depth(self):
        colour = Image(height=240, width=320, encoding="rgb8", step=320 * 3)
        pixels = numpy.zeros((240, 320, 3), numpy.uint8)
        pixels[:180, :160] = (255, 0, 0)
        pixels[:180, 160:] = (0, 0, 255)
        pixels[180:] = numpy.linspace(0, 255, 320).astype(numpy.uint8)[None, :, None]  # a grey ramp
        colour.data = pixels.tobytes()
        depth = Image(height=30, width=40, encoding="32FC1", step=40 * 4)
        metres = numpy.full((30, 40), numpy.nan, numpy.float32)
        metres[:, :20] = 2.5  # image_view: 0 to 10 m onto 0 to 255, so 64
        depth.data = metres.tobytes()
        publishers = [rospy.Publisher(t, Image, queue_size=1, latch=True)
                      for t in ("/studio_test/camera", "/studio_test/depth")]
        publishers[0].publish(colour)
        publishers[1].publish(depth)
        time.sleep(0.5)  # registered with the master before the page lists image topics
        self.show("images")
        self.css("#images-refresh").click()
        self.wait("return [...document.querySelectorAll('#images-topic option')]"
                  ".some(o => o.value === '/studio_test/depth')", what="the image topics are not listed")

        Select(self.css("#images-topic")).select_by_value("/studio_test/camera")
        size = self.wait("const s = window.studio.images.size(); return s && s[0] === 320 && s",
                         what="no 320x240 image")
        self.assertEqual(size, [320, 240])
        self.assert_pixel(80, 90, (255, 0, 0))
        self.assert_pixel(240, 90, (0, 0, 255))
        self.assert_pixel(160, 220, (128, 128, 128))
        save_screenshot(self.driver, "images")

        Select(self.css("#images-topic")).select_by_value("/studio_test/depth")
        self.wait("const s = window.studio.images.size(); return s && s[0] === 40", what="no 40x30 depth image")
        self.assert_pixel(10, 15, (64, 64, 64))
        self.assert_pixel(30, 15, (0, 0, 0))  # NaN is black
        for publisher in publishers:
            publisher.unregister()

    def assert_pixel(self, x, y, rgb, tolerance=12):
        pixel = self.driver.execute_script("return window.studio.images.pixel(%d, %d)" % (x, y))
        for got, want in zip(pixel[:3], rgb):
            self.assertLessEqual(abs(got - want), tolerance, "pixel (%d, %d) is %s, expected %s" % (x, y, pixel, rgb))


if __name__ == "__main__":
    rostest.rosrun("sim_studio", "test_studio_tools", StudioTools)
