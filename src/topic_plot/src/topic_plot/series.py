"""Recording field values per topic, and writing them as a PNG plot or a CSV file."""
import csv

from topic_plot.fields import FieldError, extract, message_time, parse_field_path


class Series(object):
    """The samples of one field spec: times (s) and values."""

    def __init__(self, label, topic, field):
        self.label = label
        self.topic = topic
        self.field = field
        self.steps = parse_field_path(field)
        self.times = []
        self.values = []
        self.error = None  # the first FieldError a message raised, if any


class Recorder(object):
    """Adds samples to every series of a topic from each message on that topic."""

    def __init__(self):
        self.series = []
        self._by_topic = {}

    def add(self, label, topic, field):
        s = Series(label, topic, field)
        self.series.append(s)
        self._by_topic.setdefault(topic, []).append(s)
        return s

    def topics(self):
        return list(self._by_topic)

    def on_message(self, topic, msg, receipt_time):
        """Record msg's fields; the time is its header stamp, or receipt_time without one."""
        t = message_time(msg, receipt_time)
        for s in self._by_topic.get(topic, ()):
            try:
                value = extract(msg, s.steps)
            except FieldError as e:
                if s.error is None:
                    s.error = str(e)
                continue
            s.times.append(t)
            s.values.append(value)

    def start_time(self):
        """The earliest sample time (the plots' zero), or None without samples."""
        firsts = [s.times[0] for s in self.series if s.times]
        return min(firsts) if firsts else None


def write_csv(path, recorder, t0=None):
    """Long format, one row per sample: field,time,value (time in s, from t0 if given)."""
    t0 = recorder.start_time() if t0 is None else t0
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["field", "time", "value"])
        for s in recorder.series:
            for t, v in zip(s.times, s.values):
                w.writerow([s.label, "%.6f" % (t - (t0 or 0.0)), repr(v)])


def write_png(path, recorder, title=None, t0=None, xlabel="time [s]"):
    """One line per field, with a legend. Uses matplotlib's Agg backend (no display)."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    t0 = recorder.start_time() if t0 is None else t0
    fig, ax = plt.subplots(figsize=(10, 5), dpi=100)
    for s in recorder.series:
        ax.plot([t - (t0 or 0.0) for t in s.times], s.values, label="%s (%d)" % (s.label, len(s.values)))
    ax.set_xlabel(xlabel)
    ax.grid(True, alpha=0.3)
    if title:
        ax.set_title(title)
    if recorder.series:
        ax.legend(loc="best", fontsize="small")
    fig.tight_layout()
    fig.savefig(path)
    plt.close(fig)
