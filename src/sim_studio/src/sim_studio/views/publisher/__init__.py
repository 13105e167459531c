"""Publisher: rqt's Message Publisher. A page adds publishers (topic, type, rate), writes one
expression per field (`sin(i/100)`), and publishes once or at the rate. Every message is built
and checked before it goes out (message_fields.py): a field that does not fit stops that
publisher with an error naming the field, and nothing is published for it.

Publishers belong to the page that made them and stop when it goes, as rqt's stop with its
window."""
import asyncio
import itertools

import rosgraph
import rosgraph.names
import rosmsg
import rospkg
import rospy

from sim_studio.view import View
from sim_studio.views.publisher import message_fields
from sim_studio.views.publisher.schedule import Schedule, check_rate

STATUS_PERIOD = 0.25  # s between a running publisher's count updates to its page


class _Publisher:
    """One row of the page's publisher list."""

    def __init__(self, pid, client, topic, cls):
        self.pid, self.client, self.topic, self.cls = pid, client, topic, cls
        self.counter = 0          # rqt's `i`: incremented before each message is built
        self.compiled = []
        self.rate = 1.0
        self.enabled = False
        self.handle = None        # the loop's timer while enabled
        self.schedule = None
        self.last_status = 0.0
        # rqt's queue size; latched so that "publish once" reaches a subscriber that is still connecting
        self.ros = rospy.Publisher(topic, cls, queue_size=100, latch=True)


class PublisherView(View):
    title = "Publisher"
    order = 30

    def __init__(self, studio):
        super().__init__(studio)
        self._publishers = {}
        self._ids = itertools.count(1)
        self._types = None

    def stop(self):
        for pid in list(self._publishers):
            self._remove(pid)

    def disconnected(self, client):
        for pid, pub in list(self._publishers.items()):
            if pub.client is client:
                self._remove(pid)

    async def handle(self, client, message):
        kind = message["type"]
        if kind == "types":
            if self._types is None:
                self._types = await self.studio.blocking(_installed_message_types)
            client.reply(message, types=self._types)
        elif kind == "topics":
            topics = await self.studio.blocking(_topic_types)
            client.reply(message, topics=[{"name": n, "type": t} for n, t in sorted(topics.items())])
        elif kind == "describe":
            cls = message_fields.message_class(message.get("msg_type"))
            client.reply(message, msg_type=cls._type, fields=message_fields.describe(cls))
        elif kind == "add":
            client.reply(message, **await self._add(client, message))
        elif kind == "set":
            pub = self._own(client, message)
            self._set(pub, message)
            client.reply(message, **self._status(pub))
        elif kind == "once":
            pub = self._own(client, message)
            if "fields" in message:
                pub.compiled = message_fields.compile_expressions(pub.cls, message["fields"])
            self._publish(pub)
            client.reply(message, **self._status(pub))
        elif kind == "remove":
            self._remove(self._own(client, message).pid)
            client.reply(message, publisher=message.get("publisher"))
        else:
            raise ValueError("publisher: unknown request %r (types, topics, describe, add, set, once, remove)" % kind)

    # --- requests ---------------------------------------------------------------------------
    async def _add(self, client, message):
        topic = message.get("topic")
        if not isinstance(topic, str) or not topic.strip() or not rosgraph.names.is_legal_name(topic.strip()):
            raise ValueError("topic: %r is not a legal ROS topic name (e.g. /command)" % (topic,))
        topic = rospy.resolve_name(topic.strip())
        cls = message_fields.message_class(message.get("msg_type"))
        existing = (await self.studio.blocking(_topic_types)).get(topic)
        if existing and existing != cls._type:
            raise ValueError("topic %s already carries %s; a %s publisher would reach none of its subscribers"
                             % (topic, existing, cls._type))
        await self.studio.clock.acquire()  # for `t`, held while the publisher lives
        if client.closed:  # the page went meanwhile
            self.studio.clock.release()
            raise ValueError("the page closed")
        try:
            pub = _Publisher(next(self._ids), client, topic, cls)
        except rospy.ROSException as e:  # this process already has the topic with another type
            self.studio.clock.release()
            raise ValueError("topic %s: %s" % (topic, e))
        self._publishers[pub.pid] = pub
        return dict(self._status(pub), fields=message_fields.describe(cls))

    def _set(self, pub, message):
        """New expressions, rate and on/off together: checked in full (a first message is built)
        before anything changes, so a bad field leaves the publisher as it was."""
        compiled = message_fields.compile_expressions(pub.cls, message.get("fields", {}))
        enabled = bool(message.get("enabled", pub.enabled))
        rate = check_rate(message["rate"]) if message.get("rate") not in (None, "") else pub.rate
        if enabled:
            message_fields.build(pub.cls, compiled, self._variables(pub.counter + 1))
        pub.compiled, pub.rate = compiled, rate
        self._stop_timer(pub)
        pub.enabled = enabled
        if enabled:
            loop = asyncio.get_running_loop()
            pub.schedule = Schedule(rate, loop.time())
            pub.handle = loop.call_soon(self._tick, pub)

    def _tick(self, pub):
        if pub.pid not in self._publishers or not pub.enabled:
            return
        loop = asyncio.get_running_loop()
        try:
            self._publish(pub)
        except ValueError as e:
            pub.enabled = False
            pub.handle = None
            pub.client.send(dict(self._status(pub), view=self.name, type="status", error=str(e)))
            return
        now = loop.time()
        pub.handle = loop.call_at(pub.schedule.next_after(now), self._tick, pub)
        if now - pub.last_status >= STATUS_PERIOD:
            pub.last_status = now
            pub.client.send_latest(("publisher", pub.pid), dict(self._status(pub), view=self.name, type="status"))

    def _publish(self, pub):
        msg = message_fields.build(pub.cls, pub.compiled, self._variables(pub.counter + 1))
        pub.counter += 1  # only a message that was built counts, so i has no gaps
        pub.ros.publish(msg)

    # --- helpers ----------------------------------------------------------------------------
    def _variables(self, i):
        return {"i": i, "t": self.studio.clock.now()}

    def _own(self, client, message):
        pub = self._publishers.get(message.get("publisher"))
        if pub is None or pub.client is not client:
            raise ValueError("no publisher %r on this page (it was removed, or the page reloaded)"
                             % (message.get("publisher"),))
        return pub

    @staticmethod
    def _status(pub):
        return {"publisher": pub.pid, "topic": pub.topic, "msg_type": pub.cls._type, "rate": pub.rate,
                "enabled": pub.enabled, "count": pub.counter}

    def _stop_timer(self, pub):
        if pub.handle is not None:
            pub.handle.cancel()
            pub.handle = None

    def _remove(self, pid):
        pub = self._publishers.pop(pid, None)
        if pub is not None:
            pub.enabled = False
            self._stop_timer(pub)
            pub.ros.unregister()
            self.studio.clock.release()


def _topic_types():
    """{topic: type} of every topic the master knows (published or subscribed)."""
    return dict(rosgraph.Master(rospy.get_name()).getTopicTypes())


def _installed_message_types():
    """Every message type of every package on the package path, as rqt's type list offers."""
    rospack = rospkg.RosPack()
    types = []
    for package, _ in rosmsg.iterate_packages(rospack, rosmsg.MODE_MSG):
        types.extend(rosmsg.list_types(package, mode=rosmsg.MODE_MSG, rospack=rospack))
    return sorted(set(types))


VIEW = PublisherView
