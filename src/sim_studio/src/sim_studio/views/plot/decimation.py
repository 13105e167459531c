"""Full-rate samples kept on the server, and what of them goes to a page. No ROS.

A series keeps every sample it receives in a bounded buffer (the newest MAX_SAMPLES; the CSV
export reads it). A page is sent only the samples newer than the last ones it got, and at most
about `points_per_second` of them per series for each second since its last send: when more
arrived, they are cut into buckets of consecutive samples and each bucket sends its smallest and
its largest value, in time order. So a 1 kHz signal reaches the page at 200 points a second
with its peaks intact: every plotted point is a sample that was received, and every received
sample lies between its bucket's two plotted values.
"""
import threading

import numpy

MAX_SAMPLES = 200000  # per series: 200 s at 1 kHz


class SampleBuffer:
    """A series' samples, (time, value), each with a sequence number that says what is new.
    A ring of float64 pairs: 16 bytes a sample (3.2 MB for a full buffer), not Python tuples."""

    def __init__(self, capacity=MAX_SAMPLES):
        self._lock = threading.Lock()  # rospy's thread appends, the server reads
        self._ring = numpy.empty((capacity, 2))
        self._next_seq = 0  # the number the next sample gets

    def append(self, t, value):
        with self._lock:
            self._ring[self._next_seq % len(self._ring)] = (t, value)
            self._next_seq += 1

    @property
    def last_seq(self):
        """The sequence number of the newest sample (-1 while empty)."""
        return self._next_seq - 1

    def since(self, seq):
        """The samples numbered after `seq` that are still held, oldest first, as [(t, v)]."""
        with self._lock:
            first = max(seq + 1, self._next_seq - len(self._ring), 0)
            if first >= self._next_seq:
                return []
            rows = numpy.arange(first, self._next_seq) % len(self._ring)
            return [tuple(row) for row in self._ring[rows].tolist()]

    def all(self):
        return self.since(-1)


def budget(points_per_second, elapsed):
    """How many points a series may send for `elapsed` seconds since its last send (at least 2,
    so one min/max pair always fits)."""
    return max(2, int(points_per_second * max(elapsed, 0.0)))


def decimate(samples, max_points):
    """`samples` [(t, v)] if they fit in `max_points`, else each of max_points // 2 buckets of
    consecutive samples as its minimum and maximum, in the order they came."""
    if len(samples) <= max_points:
        return list(samples)
    buckets = max(1, max_points // 2)
    out = []
    for b in range(buckets):
        bucket = samples[len(samples) * b // buckets: len(samples) * (b + 1) // buckets]
        if not bucket:
            continue
        low = min(range(len(bucket)), key=lambda k: bucket[k][1])
        high = max(range(len(bucket)), key=lambda k: bucket[k][1])
        for k in sorted({low, high}):
            out.append(bucket[k])
    return out
