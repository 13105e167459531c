"""The studio's web server (aiohttp): the page shell, the views' page modules, the browser
libraries, and one websocket per page carrying every view's messages as JSON
({"view": name, "type": ..., "id": ...}).

Only GET and HEAD reach files, only files under the studio's own folders are served, and a
token guards everything off loopback (access.py). A malformed or oversized websocket message
gets an error back and the node stays up.
"""
import asyncio
import json
import logging
import mimetypes
import os
import time

from aiohttp import WSMsgType, web

from sim_studio import access
from sim_studio.client import Client
from sim_studio.registry import view_folders

log = logging.getLogger("sim_studio")
MAX_MESSAGE_BYTES = 1 << 20  # a page's message: a publish, a plot request; never more than this
VIEW_FILE_TYPES = (".js", ".css", ".svg", ".png", ".html")
mimetypes.add_type("text/javascript", ".js")  # module scripts need it; some systems map .js otherwise


class WallClock:
    """ROS time where there is no sim time: the wall clock (ros_clock.RosClock's interface)."""
    use_sim_time = False

    async def acquire(self):
        pass

    def release(self):
        pass

    def now(self):
        return time.time()


class Studio:
    """The server and the views' shared services. `roots` maps URL prefixes to folders:
    {"": www, "vendor/three": /usr/share/javascript/three, ...}; `clock` gives the views ROS
    time (the node passes a ros_clock.RosClock)."""

    def __init__(self, host, port, token, roots, clock=None):
        self.host, self.port, self.token = host, port, token
        self.roots = roots
        self.clock = clock or WallClock()
        self.views = {}
        self.clients = set()
        self.loop = None
        self._runner = None

    # --- for views --------------------------------------------------------------------------
    def call_soon(self, function, *args):
        """Run `function(*args)` on the server's loop: how a rospy callback sends to pages."""
        if self.loop is not None and not self.loop.is_closed():
            self.loop.call_soon_threadsafe(function, *args)

    async def blocking(self, function, *args):
        """Run a blocking call (a ROS service) off the loop and wait for its result."""
        return await asyncio.get_running_loop().run_in_executor(None, function, *args)

    def broadcast(self, message):
        for client in list(self.clients):
            client.send(message)

    def broadcast_latest(self, key, message):
        for client in list(self.clients):
            client.send_latest(key, message)

    # --- the server -------------------------------------------------------------------------
    def add_views(self, views):
        for view in views:
            self.views[view.name] = view

    def app(self):
        app = web.Application(middlewares=[self._guard], client_max_size=MAX_MESSAGE_BYTES)
        app.router.add_route("GET", "/ws", self._websocket)
        app.router.add_route("GET", "/views.json", self._view_list)
        app.router.add_route("GET", "/status.json", self._status)
        for view in self.views.values():
            for method, path, handler in view.routes():
                app.router.add_route(method, "/api/%s/%s" % (view.name, path.lstrip("/")), handler)
        app.router.add_route("*", "/{path:.*}", self._file)
        return app

    async def start(self):
        self.loop = asyncio.get_running_loop()
        self._runner = web.AppRunner(self.app(), access_log=None)
        await self._runner.setup()
        site = web.TCPSite(self._runner, self.host, self.port)
        try:
            await site.start()
        except OSError:  # the port is taken: the node says so, or tries the next
            await self._runner.cleanup()
            self._runner = None
            raise
        if self.port == 0:
            self.port = self._runner.addresses[0][1]

    async def stop(self):
        for view in self.views.values():
            view.stop()
        for client in list(self.clients):
            client.closed = True
        if self._runner is not None:
            await self._runner.cleanup()

    @web.middleware
    async def _guard(self, request, handler):
        offered = (request.query.get("token"), request.cookies.get(access.TOKEN_COOKIE),
                   request.headers.get("X-Studio-Token"))
        if not access.token_accepted(self.token, *offered):
            return web.Response(status=403, text="403: this studio needs its token: open the URL it printed "
                                                 "(http://HOST:PORT/?token=...)\n")
        response = await handler(request)
        if self.token and request.query.get("token") and isinstance(response, web.StreamResponse):
            # the page's own requests (modules, the websocket) then carry it without the query
            response.set_cookie(access.TOKEN_COOKIE, self.token, httponly=True, samesite="Strict")
        return response

    async def _view_list(self, request):
        return web.json_response([v.describe() for v in self.views.values()])

    async def _status(self, request):
        """How many pages are attached (each websocket is one page)."""
        return web.json_response({"pages": len(self.clients)})

    async def _file(self, request):
        if request.method not in ("GET", "HEAD"):
            return web.Response(status=405, text="405: %s is not allowed; the studio serves files with GET\n"
                                                 % request.method, headers={"Allow": "GET, HEAD"})
        path = self._resolve(request.match_info["path"])
        if path is None:
            return web.Response(status=404, text="404: no such file in the studio: /%s\n" % request.match_info["path"])
        return web.FileResponse(path, headers={"Cache-Control": "no-cache"})

    def _resolve(self, url_path):
        if url_path in ("", "index.html"):
            url_path = "index.html"
        if url_path.startswith("views/"):
            parts = url_path.split("/", 2)
            folder = view_folders().get(parts[1]) if len(parts) == 3 and parts[1] in self.views else None
            if folder is None or not parts[2].endswith(VIEW_FILE_TYPES):
                return None
            return access.file_under(folder, parts[2])
        for prefix in sorted(self.roots, key=len, reverse=True):
            if prefix and not url_path.startswith(prefix + "/"):
                continue
            return access.file_under(self.roots[prefix], url_path[len(prefix):].lstrip("/"))
        return None

    async def _websocket(self, request):
        ws = web.WebSocketResponse(max_msg_size=MAX_MESSAGE_BYTES, heartbeat=30.0)
        await ws.prepare(request)
        client = Client(ws, request.remote or "?")
        self.clients.add(client)
        writer = asyncio.ensure_future(client.write_forever())
        client.send({"view": None, "type": "hello", "views": [v.describe() for v in self.views.values()]})
        for view in self.views.values():
            self._safely(view.connected, client)
        try:
            async for frame in ws:
                if frame.type == WSMsgType.TEXT:
                    await self._dispatch(client, frame.data)
                elif frame.type == WSMsgType.BINARY:
                    client.error({}, "binary websocket messages are not understood; send JSON text")
                elif frame.type == WSMsgType.ERROR:  # e.g. larger than MAX_MESSAGE_BYTES: aiohttp closes
                    log.warning("sim_studio: websocket from %s closed: %s", client.name, ws.exception())
        finally:
            client.closed = True
            client._wake.set()
            self.clients.discard(client)
            for view in self.views.values():
                self._safely(view.disconnected, client)
            writer.cancel()
        return ws

    async def _dispatch(self, client, text):
        try:
            message = json.loads(text)
        except ValueError as e:
            client.error({}, "not JSON: %s" % e)
            return
        if not isinstance(message, dict) or not isinstance(message.get("type"), str):
            client.error({}, 'a message is a JSON object with a "view" and a "type" (string)')
            return
        view = self.views.get(message.get("view"))
        if view is None:
            client.error(message, "no view named %r (there are: %s)" % (message.get("view"), ", ".join(self.views)))
            return
        try:
            await view.handle(client, message)
        except ValueError as e:
            client.error(message, str(e))
        except Exception as e:  # a view's bug must not take the studio down
            log.exception("sim_studio: view %s failed on %s", view.name, message.get("type"))
            client.error(message, "view %s failed: %s: %s" % (view.name, type(e).__name__, e))

    @staticmethod
    def _safely(function, *args):
        try:
            function(*args)
        except Exception:
            log.exception("sim_studio: %s failed", getattr(function, "__qualname__", function))


def default_roots(package_dir):
    """The page shell, our vendored browser libraries, and Debian's three.js."""
    return {
        "": os.path.join(package_dir, "www"),
        "vendor": os.path.join(package_dir, "vendor"),
        "vendor/three": "/usr/share/javascript/three",
    }
