"""World (the centre, as Gazebo's 3D view): every model's visuals in three.js, moving live,
with Gazebo's toolbar (sim time, real-time factor, play / pause / step, reset world and time,
the real-time factor target), laser rays on demand, selection and dragging a model.

What it reads, only while a page is open: /gazebo/scene_info (latched, republished when models
come or go: the visuals, each in its link's frame) and /gazebo/pose_info (every link's world
pose, at most 60 times a second). Each page gets poses when it asks for its next frame
(pose_stream.py). Mesh files are served at /api/world/mesh/<id>/<name>, only those the scene
names. Everything else goes through /gazebo services.
"""
import asyncio
import logging
import os
import time

import rospy
from aiohttp import web
from gazebo_msgs.msg import LinkStates, ModelState
from gazebo_msgs.srv import GetModelState, SetModelState
from visualization_msgs.msg import MarkerArray

from sim_studio import request_fields
from sim_studio.gazebo import GazeboServices
from sim_studio.subscription import typed
from sim_studio.view import View
from sim_studio.views.world import scene as scene_info
from sim_studio.views.world.laser_rays import LaserRays
from sim_studio.views.world.pose_stream import PageFrames, PoseFrames
from sim_studio.views.world.sim_clock import RealTimeFactor
from sim_studio.views.world.world_control import WorldControl, target_factor

log = logging.getLogger("sim_studio")
SCENE_TOPIC = "/gazebo/scene_info"
POSE_TOPIC = "/gazebo/pose_info"
STATUS_PERIOD_S = 0.25


class WorldView(View):
    title = "World"
    slot = "center"
    order = 10

    def __init__(self, studio):
        super().__init__(studio)
        self.gazebo = GazeboServices(studio.blocking)
        self.control = WorldControl(self.gazebo)
        self.frames = PoseFrames()
        self.lasers = LaserRays(studio, "world")
        self.rtf = RealTimeFactor()
        self._pages = {}        # client -> PageFrames
        self._scene = None      # the scene message pages get
        self._meshes = {}       # mesh id -> path: the only files routes() serves
        self._subscribers = []
        self._status_task = None

    # --- lifetime ----------------------------------------------------------------------------
    def start(self):
        self._status_task = asyncio.ensure_future(self._status_loop())

    def stop(self):
        if self._status_task is not None:
            self._status_task.cancel()
        self._unsubscribe()
        self.gazebo.close()

    def connected(self, client):
        self._pages[client] = PageFrames()
        if len(self._pages) == 1:
            self._subscribers = [rospy.Subscriber(SCENE_TOPIC, MarkerArray, self._on_scene, queue_size=1),
                                 rospy.Subscriber(POSE_TOPIC, LinkStates, self._on_poses, queue_size=1,
                                                  tcp_nodelay=True)]
        if self._scene is not None:
            client.send(self._scene)

    def disconnected(self, client):
        self._pages.pop(client, None)
        self.lasers.drop(client)
        if not self._pages:
            self._unsubscribe()

    def _unsubscribe(self):
        for subscriber in self._subscribers:
            subscriber.unregister()
        self._subscribers = []
        self.lasers.stop()
        # pose_info starts again from scratch for the next page: it must be sent every link
        self.frames = PoseFrames()

    # --- the scene and the poses (rospy threads hand over to the server's loop) ---------------
    # typed(): another view may have subscribed the topic first with rospy.AnyMsg (subscription.py)
    def _on_scene(self, markers):
        markers = typed(markers, MarkerArray)
        scene, meshes = scene_info.read_scene(markers.markers)
        for text in scene["skipped"]:
            log.warning("sim_studio world: %s", text)
        self.studio.call_soon(self._scene_arrived, scene, meshes)

    def _scene_arrived(self, scene, meshes):
        self._meshes = meshes
        self._scene = dict(scene, view=self.name, type="scene")
        self.lasers.set_topics(s["topic"] for s in scene["sensors"] if s["kind"] == "laser")
        self.studio.broadcast(self._scene)

    def _on_poses(self, states):
        states = typed(states, LinkStates)
        self.studio.call_soon(self._poses_arrived, states.name, states.pose)

    def _poses_arrived(self, names, poses):
        self.frames.update(names, poses)
        for client, page in self._pages.items():
            if page.waiting:
                self._send_frame(client, page)

    def _send_frame(self, client, page):
        frame = page.next_frame(self.frames)
        if frame is not None:  # else the page waits for the next change
            page.waiting = False
            client.send(dict(frame, view=self.name, type="poses"))

    # --- the toolbar's status ----------------------------------------------------------------
    async def _status_loop(self):
        while True:
            await asyncio.sleep(STATUS_PERIOD_S)
            if self._pages:
                self.studio.broadcast_latest("world/status", await self._status())

    async def _status(self):
        status = {"view": self.name, "type": "status"}
        try:
            props = await self.control.physics()
            sim = await self.control.sim_time()  # the simulator's word: no /clock to follow (ros_clock.py)
            if props.pause:  # the factor starts again on resume, not averaged over the pause
                self.rtf = RealTimeFactor()
            status.update(sim_time=sim, paused=props.pause, target=target_factor(props), time_step=props.time_step,
                          rtf=None if props.pause else self.rtf.add(time.monotonic(), sim))
        except ValueError as e:
            status["error"] = str(e)
        return status

    # --- requests ----------------------------------------------------------------------------
    async def handle(self, client, message):
        kind = message["type"]
        page = self._pages.get(client)
        if kind == "frame":
            if page is not None:
                page.waiting = True
                self._send_frame(client, page)
        elif kind == "scene":
            client.reply(message, scene=self._scene)
        elif kind in ("pause", "play", "reset_world", "reset_time"):
            await getattr(self.control, kind)()
            client.reply(message)
            self.studio.broadcast_latest("world/status", await self._status())
        elif kind == "step":
            client.reply(message, sim_time=await self.control.step())
        elif kind == "target":
            await self.control.set_target(request_fields.number(message, "rtf", low=0.0))
            client.reply(message)
        elif kind == "lasers":
            self.lasers.want(client, message.get("on") is True)
            client.reply(message)
        elif kind == "model_pose":
            client.reply(message, **await self._model_pose(request_fields.name(message, "model")))
        elif kind == "move":
            client.reply(message, **await self._move(message))
        else:
            raise ValueError("view world takes frame, scene, pause, play, step, reset_world, reset_time, target, "
                             "lasers, model_pose, move; got %r" % kind)

    async def _model_pose(self, model):
        state = await self.gazebo.request("get_model_state", GetModelState, model_name=model,
                                          relative_entity_name="world")
        p = state.pose.position
        return {"model": model, "position": [p.x, p.y, p.z]}

    async def _move(self, message):
        """Where a drag ends (and, now and then, where it is): the model at x, y on the ground
        plane, its height and orientation kept, at rest."""
        model = request_fields.name(message, "model")
        x, y = request_fields.number(message, "x"), request_fields.number(message, "y")
        state = await self.gazebo.request("get_model_state", GetModelState, model_name=model,
                                          relative_entity_name="world")
        pose = state.pose
        pose.position.x, pose.position.y = x, y
        response = await self.gazebo.request("set_model_state", SetModelState, model_state=ModelState(
            model_name=model, pose=pose, reference_frame="world"))
        return {"model": model, "position": [x, y, pose.position.z], "status": response.status_message}

    # --- mesh files --------------------------------------------------------------------------
    def routes(self):
        return [("GET", "mesh/{id}/{name}", self._mesh)]

    async def _mesh(self, request):
        path = self._meshes.get(request.match_info["id"])
        if path is None or not os.path.isfile(path):
            return web.Response(status=404, text="404: no such mesh in the simulator's scene\n")
        return web.FileResponse(path, headers={"Cache-Control": "no-cache"})


VIEW = WorldView
