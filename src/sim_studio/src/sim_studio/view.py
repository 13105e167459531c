"""What a view is, on the server side.

A view is one folder under sim_studio/views/: `__init__.py` defines a `View` subclass named
`VIEW`, and `view.js` (plus any .css) is its page side, loaded by the page shell. The studio
makes one instance per view at start, passes each page's messages for it to `handle`, and
tells it when pages come and go. A view talks to ROS as any rospy code does; its callbacks run
on rospy's threads, so anything they send goes through `self.studio.call_soon` to the server's
event loop. docs/STUDIO.md walks through writing one.
"""


class View:
    name = ""         # the folder's name; messages carry it in "view"
    title = ""        # shown on the page
    slot = "tab"      # where the page shell puts it: "left", "center", "right" (the Simulation
                      # workspace, Gazebo's layout) or "tab" (a tab of its own, as rqt's plugins)
    order = 100       # left to right within a slot

    def __init__(self, studio):
        self.studio = studio

    def start(self):
        """Once, after every view is made and before the server listens: subscribe, advertise."""

    def stop(self):
        """Once, at shutdown."""

    def connected(self, client):
        """A page came: send it what it needs to draw the view now."""

    def disconnected(self, client):
        """A page went: forget what was kept for it."""

    def routes(self):
        """HTTP routes of the view's own, for what a websocket message cannot carry well (a
        mesh file for the browser's loader): [(method, path, handler)], served at
        /api/<name>/<path> behind the same token as every request. A handler is an aiohttp
        handler; it must serve only what the view itself names (never a path from the request)."""
        return []

    async def handle(self, client, message):
        """A message from a page for this view (a dict with "type"; "id" when it wants a reply).
        Raise ValueError with a clear text for a bad request: the page gets it as an error."""
        raise ValueError("view %s takes no messages (got type %r)" % (self.name, message.get("type")))

    def describe(self):
        return {"name": self.name, "title": self.title or self.name, "slot": self.slot, "order": self.order}
