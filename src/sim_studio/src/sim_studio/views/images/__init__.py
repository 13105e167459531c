"""Images: image_view. A page picks a sensor_msgs/Image or CompressedImage topic and sees it live:
the newest frame is decoded and encoded as JPEG here (OpenCV, conversion.py) at most MAX_FPS
times a second and sent as a stream, so a slow page gets fewer frames, never old ones.

Frames are converted and encoded once per topic however many pages watch it, off the server's
loop; a frame that arrives between two sends is only kept (rospy decodes it: an image's data is
one copy).
"""
import asyncio
import base64
import logging
import time

import cv2
import rosgraph
import rosgraph.names
import rospy
from sensor_msgs.msg import CompressedImage, Image

from sim_studio import subscription
from sim_studio.view import View
from sim_studio.views.images.conversion import ImageError, compressed_to_bgr, encode_jpeg, image_to_bgr

MAX_FPS = 15.0
IMAGE_TYPES = {Image._type: Image, CompressedImage._type: CompressedImage}


class _Camera:
    """A watched image topic: its newest serialized frame."""

    def __init__(self, topic, type_name):
        self.topic = topic
        self.latest = None
        self.seq = 0
        # a large buffer: rospy's default makes large images queue behind each other
        self.subscriber = subscription.subscribe(topic, type_name, self._received, queue_size=1, buff_size=1 << 24)

    def _received(self, msg):  # rospy's thread
        self.latest = msg
        self.seq += 1


class _Page:
    def __init__(self):
        self.topic = None
        self.dynamic = False
        self.sent_seq = 0


class ImagesView(View):
    title = "Images"
    order = 50

    def __init__(self, studio):
        super().__init__(studio)
        self._pages = {}
        self._cameras = {}
        self._task = None

    def connected(self, client):
        self._pages[client] = _Page()

    def disconnected(self, client):
        self._pages.pop(client, None)
        self._update()

    def stop(self):
        self._pages.clear()
        self._update()

    async def handle(self, client, message):
        page = self._pages.setdefault(client, _Page())
        kind = message["type"]
        if kind == "topics":
            types = await self.studio.blocking(_topic_types)
            client.reply(message, topics=[{"name": n, "type": t} for n, t in sorted(types.items()) if t in IMAGE_TYPES])
        elif kind == "watch":
            topic = message.get("topic")
            if topic in (None, ""):
                page.topic = None
            elif not isinstance(topic, str) or not rosgraph.names.is_legal_name(topic) or not topic.startswith("/"):
                raise ValueError("topic: %r is not a global ROS topic name (e.g. /camera/image_raw)" % (topic,))
            else:
                page.topic = topic
            page.dynamic = bool(message.get("dynamic", False))
            page.sent_seq = 0
            new = page.topic and page.topic not in self._cameras
            self._update(await self.studio.blocking(_topic_types) if new else {})
            client.reply(message, topic=page.topic, dynamic=page.dynamic)
        else:
            raise ValueError("images: unknown request %r (topics, watch)" % kind)

    def _update(self, types=None):
        wanted = {page.topic for page in self._pages.values() if page.topic}
        for topic in set(self._cameras) - wanted:
            self._cameras.pop(topic).subscriber.unregister()
        for topic in wanted - set(self._cameras):
            self._cameras[topic] = _Camera(topic, (types or {}).get(topic, ""))
        if wanted and (self._task is None or self._task.done()):
            self._task = asyncio.ensure_future(self._run())
        elif not wanted and self._task is not None:
            self._task.cancel()
            self._task = None

    async def _run(self):
        period = 1.0 / MAX_FPS
        while True:
            started = time.monotonic()
            try:
                await self._send_frames()
            except Exception:  # a bug here must not stop the images for good
                logging.getLogger("sim_studio").exception("sim_studio: images view")
            await asyncio.sleep(max(0.0, period - (time.monotonic() - started)))

    async def _send_frames(self):
        frames = {}  # (topic, dynamic) -> frame message, encoded once
        for client, page in list(self._pages.items()):
            camera = self._cameras.get(page.topic)
            if camera is None or camera.latest is None or camera.seq == page.sent_seq:
                continue
            page.sent_seq = camera.seq
            key = (page.topic, page.dynamic)
            if key not in frames:
                frames[key] = await self.studio.blocking(_frame, page.topic, camera.latest, page.dynamic)
            client.send_latest(("images", "frame"), dict(frames[key], view=self.name, type="frame", seq=camera.seq))


def _frame(topic, latest, dynamic):
    """The page's message for one frame: a JPEG, or an error saying why not."""
    msg_type = subscription.type_of(latest)
    frame = {"topic": topic, "msg_type": msg_type}
    cls = IMAGE_TYPES.get(msg_type)
    if cls is None:
        frame["error"] = "%s carries %s, not an image (sensor_msgs/Image or CompressedImage)" % (topic, msg_type)
        return frame
    try:
        msg = subscription.typed(latest, cls)
        image = image_to_bgr(msg, dynamic) if cls is Image else compressed_to_bgr(msg)
        frame["jpeg"] = base64.b64encode(encode_jpeg(image)).decode("ascii")
    except (ImageError, cv2.error, ValueError) as e:
        frame["error"] = str(e)
        return frame
    except Exception as e:  # a message that does not deserialize
        frame["error"] = "cannot decode a %s: %s" % (msg_type, e)
        return frame
    frame.update(width=int(image.shape[1]), height=int(image.shape[0]),
                 encoding=getattr(msg, "encoding", None) or getattr(msg, "format", ""),
                 stamp=msg.header.stamp.to_sec())
    return frame


def _topic_types():
    return dict(rosgraph.Master(rospy.get_name()).getTopicTypes())


VIEW = ImagesView
