"""One page's websocket: what goes out to it, in order, without letting a slow page hold up the
studio.

Two kinds of message go out. Events (a reply, a log line, a list) are queued and all sent.
Streams (model poses, a plot's newest points, an image) are sent by key: a newer value replaces
one not yet sent, so a page that cannot keep up sees fewer frames, never older ones, and the
server's memory stays flat however long the page stays open.
"""
import asyncio
import collections
import json

MAX_QUEUED_EVENTS = 1000


class Client:
    def __init__(self, websocket, name):
        self.name = name  # for log lines: the peer's address
        self._ws = websocket
        self._events = collections.deque(maxlen=MAX_QUEUED_EVENTS)
        self._latest = {}
        self._wake = asyncio.Event()
        self.closed = False

    def send(self, message):
        """Queue one event (a dict that json can encode)."""
        self._events.append(message)
        self._wake.set()

    def send_latest(self, key, message):
        """Queue a stream's newest value under `key`, replacing an older one not yet sent."""
        self._latest[key] = message
        self._wake.set()

    def reply(self, request, **fields):
        """An answer to a page's request: the same view, the request's id and type."""
        self.send(dict(fields, view=request.get("view"), type=request.get("type"), id=request.get("id")))

    def error(self, request, text):
        self.send({"view": request.get("view") if isinstance(request, dict) else None, "type": "error",
                   "id": request.get("id") if isinstance(request, dict) else None, "error": text})

    async def write_forever(self):
        """Runs for the connection's lifetime: sends what is queued as it comes."""
        while not self.closed:
            await self._wake.wait()
            self._wake.clear()
            while self._events or self._latest:
                if self._events:
                    message = self._events.popleft()
                else:
                    _, message = self._latest.popitem()
                try:
                    await self._ws.send_str(json.dumps(message, allow_nan=False, default=_plain))
                except (ConnectionResetError, RuntimeError):  # the page went away mid-send
                    self.closed = True
                    return
                except ValueError as e:  # NaN or infinity from a topic: say so, keep going
                    await self._ws.send_str(json.dumps({"view": message.get("view"), "type": "error",
                                                        "error": "could not encode a message: %s" % e}))


def _plain(value):
    """json for values ROS messages hold: numpy numbers and arrays, bytes."""
    if hasattr(value, "tolist"):
        return value.tolist()
    if isinstance(value, (bytes, bytearray)):
        return list(value)
    raise TypeError("%s is not JSON serializable" % type(value).__name__)
