"""Laser rays for the pages that ticked "lasers": the scan topics the scene names, subscribed
only while some page wants them, each page sent the newest scan of each topic at most
SCANS_PER_S times a second (newest-only: a slow page skips scans, never lags)."""
import math
import threading
import time

import rospy
from sensor_msgs.msg import LaserScan

from sim_studio.subscription import typed

SCANS_PER_S = 10.0
RANGE_DIGITS = 3  # mm


def scan_message(view, topic, scan):
    """A LaserScan as the page draws it: a miss (inf, nan, beyond range_max) is null."""
    ranges = [round(r, RANGE_DIGITS) if math.isfinite(r) and scan.range_min <= r <= scan.range_max else None
              for r in scan.ranges]
    return {"view": view, "type": "scan", "topic": topic, "angle_min": scan.angle_min,
            "angle_increment": scan.angle_increment, "range_max": scan.range_max, "ranges": ranges}


class LaserRays:
    def __init__(self, studio, view_name):
        self._studio = studio
        self._view = view_name
        self._pages = set()          # clients that want rays
        self._topics = set()         # the scene's laser topics
        self._subscribers = {}       # topic -> rospy.Subscriber
        self._last = {}              # topic -> wall time of the last scan handed on
        self._lock = threading.Lock()

    def set_topics(self, topics):
        """The scene changed: its laser topics now."""
        self._topics = set(topics)
        self._resubscribe()

    def want(self, client, on):
        (self._pages.add if on else self._pages.discard)(client)
        self._resubscribe()

    def drop(self, client):
        self.want(client, False)

    def stop(self):
        self._pages.clear()
        self._resubscribe()

    def _resubscribe(self):
        wanted = self._topics if self._pages else set()
        for topic in set(self._subscribers) - wanted:
            self._subscribers.pop(topic).unregister()
        for topic in wanted - set(self._subscribers):
            self._subscribers[topic] = rospy.Subscriber(topic, LaserScan, self._on_scan, callback_args=topic,
                                                        queue_size=1)

    def _on_scan(self, scan, topic):  # a rospy thread
        now = time.monotonic()
        with self._lock:
            if now - self._last.get(topic, 0.0) < 1.0 / SCANS_PER_S:
                return
            self._last[topic] = now
        scan = typed(scan, LaserScan)  # decoded here if another view subscribed it undecoded first
        self._studio.call_soon(self._send, topic, scan_message(self._view, topic, scan))

    def _send(self, topic, message):
        for client in list(self._pages):
            client.send_latest("%s/scan/%s" % (self._view, topic), message)
