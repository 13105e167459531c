"""A topic's rate and bandwidth, measured as `rostopic hz` and `rostopic bw` measure them and
rqt's Topic Monitor shows them (a window of the last 100 messages for both). No ROS.

Rate (rostopic hz): the arrival times in ROS time (sim time under /use_sim_time), the rate being
1 / the mean interval between consecutive arrivals in the window. ROS time going back (a
simulator reset) or reading zero starts the measurement again, as rostopic does.

Bandwidth (rostopic bw): the arrival times in wall time and the serialized sizes; the bandwidth
is the window's bytes / (now - the window's oldest arrival), so it falls when messages stop.
"""
import collections
import threading

WINDOW = 100


class TopicStatistics:
    def __init__(self, window=WINDOW):
        self._lock = threading.Lock()  # rospy's receive threads add, the server reads
        self._ros_times = collections.deque(maxlen=window)
        self._wall_times = collections.deque(maxlen=window)
        self._sizes = collections.deque(maxlen=window)
        self.count = 0

    def add(self, ros_time, wall_time, size):
        """One message of `size` bytes arrived at ROS time `ros_time` and wall time `wall_time` (s)."""
        with self._lock:
            self.count += 1
            if ros_time <= 0 or (self._ros_times and ros_time < self._ros_times[-1]):
                self._ros_times.clear()  # time reset: intervals across it mean nothing
            if ros_time > 0:
                self._ros_times.append(ros_time)
            self._wall_times.append(wall_time)
            self._sizes.append(size)

    def rate(self):
        """Messages per second of ROS time, or None before two messages (or with no time passing)."""
        with self._lock:
            n = len(self._ros_times)
            if n < 2:
                return None
            span = self._ros_times[-1] - self._ros_times[0]
            return (n - 1) / span if span > 0 else None  # the mean interval's inverse

    def bandwidth(self, wall_now):
        """Bytes per wall second over the window, or None before two messages."""
        with self._lock:
            if len(self._wall_times) < 2:
                return None
            elapsed = wall_now - self._wall_times[0]
            return sum(self._sizes) / elapsed if elapsed > 0 else None

    def summary(self, wall_now):
        """What the page shows: rate (Hz), bandwidth (B/s), mean size (B), message count and the
        wall seconds since the last message."""
        with self._lock:
            last = self._wall_times[-1] if self._wall_times else None
            mean_size = sum(self._sizes) / len(self._sizes) if self._sizes else None
        return {"rate": self.rate(), "bandwidth": self.bandwidth(wall_now), "size": mean_size,
                "count": self.count, "age": None if last is None else max(0.0, wall_now - last)}
