"""Topics: rqt's Topic Monitor and rostopic echo. Every topic the master knows, with its type and
publishers, refreshed every 2 s; a checkbox per topic measures its rate and bandwidth, and
choosing a topic echoes its newest message as a tree of fields.

Only the topics some page monitors or echoes are subscribed, and only while they are; the echoed
topic's newest message goes to the page at most 10 times a second. Nothing runs while no page is
open. (rostopic bw subscribes with rospy.AnyMsg to count bytes without decoding; in the studio's
process that would hand AnyMsg to other views' callbacks on the same topic, so the topic's own
class is used, and the size of a message is that of its serialization: subscription.py.)
"""
import asyncio
import logging
import time

import rosgraph
import rosgraph.names
import rospy

from sim_studio import subscription
from sim_studio.view import View
from sim_studio.views.topics.message_tree import message_tree
from sim_studio.views.topics.statistics import TopicStatistics

TICK = 0.1            # s: the view's clock; echo at most every tick
STATS_PERIOD = 1.0    # s between rate/bandwidth updates (rostopic prints every second)
LIST_PERIOD = 2.0     # s between the master's topic lists


class _Watch:
    """A topic subscribed because a page monitors or echoes it."""

    def __init__(self, topic, type_name, clock):
        self.topic = topic
        self.clock = clock
        self.stats = TopicStatistics()
        self.latest = None  # the newest message, as it arrived (decoded, or AnyMsg)
        self.seq = 0
        self.subscriber = subscription.subscribe(topic, type_name, self._received, queue_size=100)

    def _received(self, msg):  # rospy's thread: count and keep
        self.stats.add(self.clock.now(), time.time(), subscription.serialized_size(msg))
        self.latest = msg
        self.seq += 1


class _Page:
    def __init__(self):
        self.monitored = set()
        self.echo = None
        self.echo_seq = -1


class TopicsView(View):
    title = "Topics"
    order = 10

    def __init__(self, studio):
        super().__init__(studio)
        self._pages = {}
        self._watches = {}
        self._task = None
        self._topics = []   # the last list from the master
        self._list_error = None

    # --- pages ------------------------------------------------------------------------------
    def connected(self, client):
        self._pages[client] = _Page()
        if self._task is None or self._task.done():
            self._task = asyncio.ensure_future(self._run())
        if self._topics:
            client.send_latest(("topics", "list"), self._list_message())

    def disconnected(self, client):
        self._pages.pop(client, None)
        self._unsubscribe_unwanted()
        if not self._pages and self._task is not None:
            self._task.cancel()
            self._task = None

    def stop(self):
        if self._task is not None:
            self._task.cancel()
        self._pages.clear()
        self._unsubscribe_unwanted()

    async def handle(self, client, message):
        page = self._pages.setdefault(client, _Page())
        kind = message["type"]
        if kind == "monitor":
            topic = _topic_name(message.get("topic"))
            (page.monitored.add if message.get("on", True) else page.monitored.discard)(topic)
            await self._update_subscriptions()
            client.reply(message, topic=topic, on=topic in page.monitored)
        elif kind == "echo":
            page.echo = None if message.get("topic") in (None, "") else _topic_name(message.get("topic"))
            page.echo_seq = -1
            await self._update_subscriptions()
            client.reply(message, topic=page.echo)
        elif kind == "refresh":
            await self._refresh_list()
            client.reply(message, **self._list_message())
        else:
            raise ValueError("topics: unknown request %r (monitor, echo, refresh)" % kind)

    # --- the view's clock -------------------------------------------------------------------
    async def _run(self):
        ticks = 0
        stats_every, list_every = round(STATS_PERIOD / TICK), round(LIST_PERIOD / TICK)
        while True:
            try:
                if ticks % list_every == 0:
                    await self._refresh_list()
                    for client in list(self._pages):
                        client.send_latest(("topics", "list"), self._list_message())
                if ticks % stats_every == 0:
                    self._send_stats()
                self._send_echoes()
            except Exception:  # a bug here must not stop the monitor for good
                logging.getLogger("sim_studio").exception("sim_studio: topics view")
            ticks += 1
            await asyncio.sleep(TICK)

    async def _refresh_list(self):
        try:
            state, types = await self.studio.blocking(_master_state)
        except Exception as e:  # the master went away: say so, keep the last list
            self._list_error = "cannot reach the ROS master: %s" % e
            return
        self._list_error = None
        publishers = {topic: nodes for topic, nodes in state[0]}
        subscribers = {topic: nodes for topic, nodes in state[1]}
        names = sorted(set(types) | set(publishers) | set(subscribers))
        self._topics = [{"name": n, "type": types.get(n, ""), "publishers": len(publishers.get(n, ())),
                         "subscribers": len(subscribers.get(n, ()))} for n in names]

    def _list_message(self):
        return {"view": self.name, "type": "list", "topics": self._topics, "error": self._list_error}

    def _send_stats(self):
        now = time.time()
        for client, page in list(self._pages.items()):
            stats = {topic: self._watches[topic].stats.summary(now) for topic in page.monitored
                     if topic in self._watches}
            client.send_latest(("topics", "stats"), {"view": self.name, "type": "stats", "stats": stats})

    def _send_echoes(self):
        decoded = {}  # one decode per topic per tick, however many pages echo it
        for client, page in list(self._pages.items()):
            watch = self._watches.get(page.echo)
            if watch is None or watch.latest is None or watch.seq == page.echo_seq:
                continue
            page.echo_seq = watch.seq
            if page.echo not in decoded:
                decoded[page.echo] = _decode(page.echo, watch.latest)
            client.send_latest(("topics", "echo"), dict(decoded[page.echo], view=self.name, type="echo",
                                                       count=watch.stats.count))

    def _wanted(self):
        wanted = set()
        for page in self._pages.values():
            wanted |= page.monitored
            if page.echo:
                wanted.add(page.echo)
        return wanted

    def _unsubscribe_unwanted(self):
        for topic in set(self._watches) - self._wanted():
            self._watches.pop(topic).subscriber.unregister()
            self.studio.clock.release()

    async def _update_subscriptions(self):
        self._unsubscribe_unwanted()
        new = self._wanted() - set(self._watches)
        types = {t["name"]: t["type"] for t in self._topics}
        if new - set(types):  # newer than the last list: ask the master now
            await self._refresh_list()
            types = {t["name"]: t["type"] for t in self._topics}
        for topic in new - set(self._watches):
            await self.studio.clock.acquire()  # rates count in ROS time, as rostopic hz
            if topic in self._watches:  # another page's request watched it meanwhile
                self.studio.clock.release()
                continue
            self._watches[topic] = _Watch(topic, types.get(topic, ""), self.studio.clock)


def _topic_name(topic):
    if not isinstance(topic, str) or not rosgraph.names.is_legal_name(topic) or not topic.startswith("/"):
        raise ValueError("topic: %r is not a global ROS topic name (e.g. /joint_states)" % (topic,))
    return topic


def _master_state():
    master = rosgraph.Master(rospy.get_name())
    return master.getSystemState(), dict(master.getTopicTypes())


def _decode(topic, msg):
    """The echo of one message: its tree, or an error saying why it cannot be shown."""
    msg_type = subscription.type_of(msg)
    echo = {"topic": topic, "msg_type": msg_type}
    try:
        decoded = subscription.typed(msg)
    except Exception as e:  # a publisher whose definition differs from ours
        echo["error"] = "cannot decode a %s: %s" % (msg_type, e)
        return echo
    if decoded is None:
        echo["error"] = "the message type %s is not installed here, so its fields cannot be shown" % msg_type
    else:
        echo["fields"] = message_tree(decoded)
    return echo


VIEW = TopicsView
