"""The ROS time the studio's views stamp with: sim time from /clock under /use_sim_time, else the
wall clock.

rospy follows /clock in every node from init_node on, a Python callback per message: up to a
thousand a second from a simulator running fast, 7-9 % of a core for a studio nobody looks at.
The studio starts rospy with that off (init_node(disable_rostime=True): rospy's own time is the
wall clock) and subscribes /clock here only while a view needs ROS time: a monitored topic's
rate (rostopic hz counts in ROS time), a plot's times, a publisher's `t`.
"""
import asyncio
import threading
import time

import rospy
from rosgraph_msgs.msg import Clock

FIRST_CLOCK_WAIT_S = 1.0  # a simulator publishes /clock every 0.1 s of wall time even when paused


class RosClock:
    def __init__(self, use_sim_time):
        self.use_sim_time = use_sim_time
        self._lock = threading.Lock()
        self._holders = 0
        self._subscriber = None
        self._latest = None  # s: the last /clock since subscribing

    async def acquire(self):
        """A view starts needing ROS time (pair with release()): under sim time, /clock is
        subscribed and its first message awaited (up to a second; rospy's time is 0 until then
        too)."""
        if not self.use_sim_time:
            return
        with self._lock:
            self._holders += 1
            if self._subscriber is None:
                self._latest = None
                self._subscriber = rospy.Subscriber("/clock", Clock, self._on_clock, queue_size=1)
        deadline = time.monotonic() + FIRST_CLOCK_WAIT_S
        while self._latest is None and time.monotonic() < deadline:
            await asyncio.sleep(0.01)

    def release(self):
        if not self.use_sim_time:
            return
        with self._lock:
            self._holders = max(0, self._holders - 1)
            if self._holders == 0 and self._subscriber is not None:
                self._subscriber.unregister()
                self._subscriber = None

    def now(self):
        """ROS time in seconds: the latest /clock (0 before the first) under sim time, else the wall clock."""
        if not self.use_sim_time:
            return time.time()
        latest = self._latest
        return 0.0 if latest is None else latest

    def _on_clock(self, message):
        self._latest = message.clock.to_sec()
