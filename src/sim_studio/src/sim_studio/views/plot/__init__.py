"""Plot: rqt_plot. A page adds numeric fields of topics as rqt_plot takes them
(`/joint_states/position[0]`, `/sine/data`; topic_plot's parser), each a series against sim time
(the header stamp, else the ROS time it arrived, as rqt_plot and topic_plot do).

Every sample is kept here at full rate in a bounded buffer (the CSV export reads it); each page
gets, ten times a second, only what is new since its last send, decimated to about
POINTS_PER_SECOND points a second per series (decimation.py). One subscription per topic
however many series and pages use it; none once no page plots it.
"""
import asyncio
import csv
import io
import logging
import math
import time

import roslib.message
import rospy
from topic_plot.fields import FieldError, check_path, extract, message_time, parse_field_path, split_topic_field

from sim_studio import subscription
from sim_studio.view import View
from sim_studio.views.plot.completion import numeric_paths
from sim_studio.views.plot.decimation import SampleBuffer, budget, decimate

SEND_PERIOD = 0.1          # s between sends to a page
POINTS_PER_SECOND = 200    # per series to a page, at most (min/max pairs beyond)
MAX_SERIES = 32            # per page


class _Series:
    def __init__(self, path, topic, field):
        self.path, self.topic, self.field = path, topic, field
        self.steps = parse_field_path(field)
        self.buffer = SampleBuffer()
        self.error = None       # the last FieldError a message raised (an index not in this message)
        self.skipped = 0        # NaN and infinite values: not plotted, as rqt_plot leaves gaps


class _Page:
    def __init__(self):
        self.sent = {}          # path -> last sequence number sent
        self.start = {}         # path -> sequence number at add/clear: the CSV starts after it
        self.errors = {}        # path -> error text last sent
        self.last_send = time.monotonic()


class PlotView(View):
    title = "Plot"
    order = 20

    def __init__(self, studio):
        super().__init__(studio)
        self._series = {}       # path -> _Series, shared by the pages that plot it
        self._by_topic = {}     # topic -> tuple of _Series (replaced whole: rospy's thread reads it)
        self._subscribers = {}  # topic -> rospy.Subscriber
        self._pages = {}
        self._task = None

    def connected(self, client):
        self._pages[client] = _Page()
        if self._task is None or self._task.done():
            self._task = asyncio.ensure_future(self._run())

    def disconnected(self, client):
        self._pages.pop(client, None)
        self._forget_unused()
        if not self._pages and self._task is not None:
            self._task.cancel()
            self._task = None

    def stop(self):
        if self._task is not None:
            self._task.cancel()
        self._pages.clear()
        self._forget_unused()

    async def handle(self, client, message):
        page = self._pages.setdefault(client, _Page())
        kind = message["type"]
        if kind == "add":
            series = await self._add(page, message.get("path"))
            client.reply(message, path=series.path, topic=series.topic, field=series.field)
        elif kind == "remove":
            path = message.get("path")
            for table in (page.sent, page.start, page.errors):
                table.pop(path, None)
            self._forget_unused()
            client.reply(message, path=path)
        elif kind == "clear":
            for path in page.sent:
                page.sent[path] = page.start[path] = self._series[path].buffer.last_seq
            client.reply(message)
        elif kind == "csv":
            client.reply(message, csv=self._csv(page))
        elif kind == "fields":
            client.reply(message, paths=await self.studio.blocking(_plottable_paths))
        else:
            raise ValueError("plot: unknown request %r (add, remove, clear, csv, fields)" % kind)

    # --- series -----------------------------------------------------------------------------
    async def _add(self, page, path):
        if not isinstance(path, str) or not path.strip():
            raise ValueError("name a topic field to plot, e.g. /joint_states/position[0] or /sine/data")
        path = "/" + path.strip().lstrip("/")
        if path in page.sent:
            raise ValueError("%s is already plotted" % path)
        if len(page.sent) >= MAX_SERIES:
            raise ValueError("at most %d series on one plot" % MAX_SERIES)
        series = self._series.get(path)
        if series is None:
            series = await self._new_series(path)
        seq = series.buffer.last_seq  # rqt_plot starts a series when it is added
        page.sent[path] = page.start[path] = seq
        return series

    async def _new_series(self, path):
        topics = dict(await self.studio.blocking(rospy.get_published_topics))
        if path in topics:
            raise ValueError("%s is a topic: name one of its numeric fields too, e.g. %s/data" % (path, path))
        split = split_topic_field(path, topics)
        if split is None:
            raise ValueError("%s: no published topic is a prefix of it (is its publisher running? published: %s)"
                             % (path, ", ".join(sorted(topics)[:30]) or "none"))
        topic, field = split
        cls = roslib.message.get_message_class(topics[topic])
        if cls is None:
            raise ValueError("%s: its type %s is not installed here" % (path, topics[topic]))
        try:
            check_path(cls, parse_field_path(field))
        except FieldError as e:
            raise ValueError("%s: %s" % (path, e))
        series = self._series.get(path)  # another page may have added it meanwhile
        if series is None:
            series = self._series[path] = _Series(path, topic, field)
            self._by_topic[topic] = self._by_topic.get(topic, ()) + (series,)
            if topic not in self._subscribers:
                await self.studio.clock.acquire()  # the times of messages without a header
                if topic in self._subscribers:  # another series of the topic subscribed meanwhile
                    self.studio.clock.release()
                else:
                    self._subscribers[topic] = rospy.Subscriber(topic, cls, self._received,
                                                                callback_args=(topic, cls), queue_size=1000)
        return series

    def _received(self, msg, topic_class):  # rospy's thread
        topic, cls = topic_class
        msg = subscription.typed(msg, cls)  # an AnyMsg when another part of the process subscribed so first
        t = message_time(msg, self.studio.clock.now())
        for series in self._by_topic.get(topic, ()):
            try:
                value = extract(msg, series.steps)
            except FieldError as e:
                series.error = str(e)
                continue
            if math.isfinite(value):
                series.buffer.append(t, value)
            else:
                series.skipped += 1

    def _forget_unused(self):
        used = set()
        for page in self._pages.values():
            used |= set(page.sent)
        for path in set(self._series) - used:
            series = self._series.pop(path)
            remaining = tuple(s for s in self._by_topic.get(series.topic, ()) if s is not series)
            if remaining:
                self._by_topic[series.topic] = remaining
            else:
                self._by_topic.pop(series.topic, None)
                self._subscribers.pop(series.topic).unregister()
                self.studio.clock.release()

    # --- sending ----------------------------------------------------------------------------
    async def _run(self):
        while True:
            try:
                self._send_all()
            except Exception:  # a bug here must not stop every plot for good
                logging.getLogger("sim_studio").exception("sim_studio: plot view")
            await asyncio.sleep(SEND_PERIOD)

    def _send_all(self):
        now = time.monotonic()
        for client, page in list(self._pages.items()):
            allowed = budget(POINTS_PER_SECOND, now - page.last_send)
            page.last_send = now
            data, errors = {}, {}
            for path, last in page.sent.items():
                series = self._series[path]
                new = series.buffer.since(last)
                if new:
                    page.sent[path] = series.buffer.last_seq
                    points = decimate(new, allowed)
                    data[path] = {"t": [p[0] for p in points], "v": [p[1] for p in points],
                                  "received": len(new)}
                if series.error and page.errors.get(path) != series.error:
                    errors[path] = page.errors[path] = series.error
            if data or errors:
                client.send({"view": self.name, "type": "data", "series": data, "errors": errors})

    def _csv(self, page):
        """Every sample held since each series was added (or cleared), long format as
        topic_plot's CSV: field,time,value."""
        out = io.StringIO()
        writer = csv.writer(out)
        writer.writerow(["field", "time", "value"])
        for path, start in page.start.items():
            for t, v in self._series[path].buffer.since(start):
                writer.writerow([path, "%.9f" % t, repr(v)])
        return out.getvalue()


def _plottable_paths():
    """Every numeric field of every published topic, for the page's completion list."""
    paths = []
    for topic, type_name in sorted(rospy.get_published_topics()):
        cls = roslib.message.get_message_class(type_name)
        if cls is not None:
            paths.extend(topic + "/" + p for p in numeric_paths(cls))
        if len(paths) > 5000:
            break
    return paths


VIEW = PlotView
