#!/usr/bin/python3
"""What rqt's stand-ins in the studio cost (issue 35): the studio node's CPU while a page in
headless Chromium monitors, echoes and plots a 1 kHz topic.

  bench_studio_tools.py [--seconds S] [--rate HZ]      (after . scripts/env.sh)

Starts a roscore of its own, `roslaunch sim_studio studio.launch` (the views topics, plot,
publisher, graph, images) and publishes sensor_msgs/JointState (6 joints) on /bench/joints at
HZ (default 1000) from a thread of this script. A headless Chromium opens the page and, for S wall
seconds each (default 10), the studio's CPU is measured:
  idle      the page on the Topics tab, nothing monitored (the master's list every 2 s)
  monitor   /bench/joints ticked in Topics (subscribed, rate and bandwidth)
  echo      ... and echoed (its newest message to the page 10 times a second)
  plot      /bench/joints/position[0] on the Plot tab only (full-rate buffer, 200 points/s sent)
Output, one line per window: `<window>: studio X % of one core, Y us per message`, where the cost
per message is the CPU above idle over the messages published in the window.
Every process it starts is stopped at the end, also on errors and Ctrl-C.
"""
import argparse
import os
import sys
import threading
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(os.path.dirname(HERE), "src", "sim_studio", "test", "browser"))
from bench_node_rtf import launch_on_private_master, run_with_processes  # noqa: E402
from process_cpu import ProcessCpu  # noqa: E402


def studio_share(sampler):
    return next((p for n, p in sampler.shares() if n == "sim_studio"), 0.0)


def work(procs, args):
    launch_on_private_master(procs, "bench_studio_tools",
                             ["sim_studio", "studio.launch", "port:=0"])
    import rospy
    from selenium.webdriver.common.by import By
    from sensor_msgs.msg import JointState
    from studio_browser import open_browser, open_studio, studio_url, wait_for

    publisher = rospy.Publisher("/bench/joints", JointState, queue_size=100)
    count = [0]
    stop = threading.Event()

    def publish():
        msg = JointState(name=["joint%d" % k for k in range(6)], position=[0.0] * 6, velocity=[0.0] * 6,
                         effort=[0.0] * 6)
        period, due = 1.0 / args.rate, time.monotonic()
        while not stop.is_set():
            count[0] += 1
            msg.header.stamp = rospy.Time.now()
            msg.position[0] = (count[0] % 1000) / 1000.0
            publisher.publish(msg)
            due += period
            time.sleep(max(0.0, due - time.monotonic()))
    thread = threading.Thread(target=publish, daemon=True)
    thread.start()

    driver = open_browser()
    try:
        open_studio(driver, studio_url())
        css = lambda s: driver.find_element(By.CSS_SELECTOR, s)  # noqa: E731
        css("#tabs button[data-page='page-topics']").click()
        row = 'tr[data-topic="/bench/joints"]'
        wait_for(driver, "return document.querySelector('%s')" % row, 15, "the topic is not listed")

        def window(label, idle=None):
            sampler, first = ProcessCpu(procs.log_dir), count[0]
            time.sleep(args.seconds)
            share, messages = studio_share(sampler), count[0] - first
            per_message = "" if idle is None else ", %.0f us per message" % (
                (share - idle) / 100.0 * args.seconds / max(messages, 1) * 1e6)
            print("%-8s studio %5.1f %% of one core%s  (%d messages, %.0f Hz)"
                  % (label + ":", share, per_message, messages, messages / args.seconds), flush=True)
            return share

        idle = window("idle")
        css(row + " input.topics-monitor").click()
        time.sleep(1.0)
        window("monitor", idle)
        rate = wait_for(driver, "return document.querySelector('%s').dataset.rate" % row, 5, "no rate")
        print("          the monitor's rate: %.1f Hz" % float(rate))
        css(row + " a.topics-name").click()
        time.sleep(1.0)
        window("echo", idle)
        css(row + " input.topics-monitor").click()
        css(row + " a.topics-name").click()  # the echoed topic again: no echo
        css("#tabs button[data-page='page-plot']").click()
        css("#plot-path").send_keys("/bench/joints/position[0]")
        css("#plot-add").click()
        wait_for(driver, "return document.querySelector('.plot-chip')", 10, "the series was not added")
        time.sleep(1.0)
        window("plot", idle)
        points = driver.execute_script("return window.studio.plot.series()['/bench/joints/position[0]'].v.length")
        print("          the page holds %d points of the series" % points)
    finally:
        stop.set()
        driver.quit()


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seconds", type=float, default=10.0)
    parser.add_argument("--rate", type=float, default=1000.0)
    args = parser.parse_args()
    return run_with_processes("bench_studio_tools", lambda procs: work(procs, args))


if __name__ == "__main__":
    sys.exit(main())
