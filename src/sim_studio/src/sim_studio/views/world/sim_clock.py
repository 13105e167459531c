"""The real-time factor as the toolbar shows it: sim time against wall time over the last
second or so, sampled a few times a second. Pure."""
import collections

WINDOW_S = 1.0


class RealTimeFactor:
    def __init__(self, window=WINDOW_S):
        self._window = window
        self._samples = collections.deque()  # (wall, sim)

    def add(self, wall, sim):
        """A sample; the factor over the window that ends with it (None until two samples).
        Sim time going back (reset_simulation) starts over."""
        if self._samples and sim < self._samples[-1][1]:
            self._samples.clear()
        self._samples.append((wall, sim))
        while len(self._samples) > 2 and wall - self._samples[1][0] >= self._window:
            self._samples.popleft()
        (wall0, sim0) = self._samples[0]
        if wall - wall0 <= 0:
            return None
        return (sim - sim0) / (wall - wall0)
