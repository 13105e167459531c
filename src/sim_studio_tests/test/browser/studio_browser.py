"""The browser side of the studio's tests: Debian's headless Chromium driven by Selenium, on the
page a running studio node serves. Test-only (not installed)."""
import os
import time

import rospy
from selenium import webdriver
from selenium.common.exceptions import StaleElementReferenceException
from selenium.webdriver.chrome.options import Options
from selenium.webdriver.common.by import By
from selenium.webdriver.chrome.service import Service

CHROMIUM = "/usr/bin/chromium"
CHROMEDRIVER = "/usr/bin/chromedriver"


def studio_url(node="/sim_studio", timeout=30.0):
    """The URL the studio node printed (its ~url parameter), once it serves."""
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        if rospy.has_param(node + "/url"):
            return rospy.get_param(node + "/url")
        time.sleep(0.1)
    raise AssertionError("the studio (%s) did not start serving within %.0f s" % (node, timeout))


def open_browser(width=1280, height=800):
    """Headless Chromium with WebGL on the CPU (SwiftShader): no display, no GPU needed. The page
    is composited in software (Skia, only what changed), not through SwiftShader's GL, which
    drew the whole window for every change: a 4 Hz status line cost 0.13 cores, a WebGL frame
    34 ms of CPU instead of 22 (bench/bench_studio_world.py)."""
    options = Options()
    options.binary_location = CHROMIUM
    for flag in ("--headless=new", "--no-sandbox", "--disable-dev-shm-usage", "--window-size=%d,%d" % (width, height),
                 "--use-angle=swiftshader", "--enable-unsafe-swiftshader", "--disable-gpu-compositing",
                 "--disable-gpu-vsync", "--disable-background-timer-throttling", "--disable-renderer-backgrounding"):
        options.add_argument(flag)
    options.set_capability("goog:loggingPrefs", {"browser": "ALL"})
    return webdriver.Chrome(service=Service(CHROMEDRIVER), options=options)


def open_studio(driver, url, timeout=20.0):
    """Load the page and wait until every view is mounted and the websocket is up."""
    driver.get(url)
    wait_for(driver, "return window.studioReady === true && "
                     "document.getElementById('status').textContent === 'connected'", timeout,
             "the studio page did not load and connect")


def wait_for(driver, script, timeout=10.0, what=None):
    """Poll a JavaScript expression (a `return ...` statement) until it is truthy; its value."""
    deadline = time.monotonic() + timeout
    while True:
        value = driver.execute_script(script)
        if value:
            return value
        if time.monotonic() > deadline:
            raise AssertionError("%s (waited %.0f s for: %s); browser log: %s"
                                 % (what or "timed out", timeout, script, browser_errors(driver)))
        time.sleep(0.05)


def click(driver, css, timeout=5.0):
    """Click the element `css` selects, found afresh if the page redrew it between the find and
    the click (the Models tree is rebuilt when the world's model list comes in), as a user's
    click lands on what is on the screen."""
    deadline = time.monotonic() + timeout
    while True:
        try:
            driver.find_element(By.CSS_SELECTOR, css).click()
            return
        except StaleElementReferenceException:
            if time.monotonic() > deadline:
                raise
            time.sleep(0.05)


def browser_errors(driver):
    try:
        return [e["message"] for e in driver.get_log("browser") if e["level"] in ("SEVERE", "ERROR")]
    except Exception:  # the log is a help for failures, never a failure of its own
        return []


def save_screenshot(driver, name):
    """A screenshot for the docs (docs/images/studio_<name>.png) when STUDIO_SCREENSHOTS is set to
    the docs' images folder; tests take them where they show what a user would see."""
    folder = os.environ.get("STUDIO_SCREENSHOTS")
    if folder:
        driver.save_screenshot(os.path.join(folder, "studio_%s.png" % name))
