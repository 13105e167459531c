"""When a publisher at a rate sends its next message. No ROS.

Like rqt_publisher's QTimer, the rate is in wall time (a publisher keeps going while the
simulation is paused). Ticks are anchored to the start (start + k / rate), so the rate does not
drift with the time each publish takes; after a stall longer than a period (the machine was
busy) the schedule starts again from now instead of sending a burst to catch up.
"""

MAX_RATE = 1000.0  # Hz; faster is a flood, not a command


def check_rate(rate):
    """The rate as a float, or ValueError saying why it is not one a publisher can run at."""
    if isinstance(rate, bool) or not isinstance(rate, (int, float)):
        raise ValueError("rate: expected a number of messages per second, got %r" % (rate,))
    rate = float(rate)
    if not 0 < rate <= MAX_RATE:
        raise ValueError("rate: %g Hz is outside (0, %g] Hz" % (rate, MAX_RATE))
    return rate


class Schedule:
    def __init__(self, rate, now):
        self.period = 1.0 / rate
        self._start = now
        self._k = 0

    def next_after(self, now):
        """The time of the next tick after the one just done at `now`."""
        self._k += 1
        due = self._start + self._k * self.period
        if due < now - self.period:  # more than a period behind: no burst
            self._start, self._k = now, 1
            due = now + self.period
        return due
