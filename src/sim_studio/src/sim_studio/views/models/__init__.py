"""Models (left of the world, as Gazebo's World tab): the tree of models with their links and
joints, the selected model's properties (pose, twist, masses, joint positions), delete, and
insert (a model from the model paths, or a box, sphere or cylinder).

Everything goes through /gazebo services. The tree is read again when the model names change
(polled once a second while a page is open, and at once after an insert or delete here); the
page polls the selected model's state a few times a second, so nothing streams while no model
is selected.
"""
import asyncio
import logging
import math
import os

import rospkg
from gazebo_msgs.srv import (DeleteModel, GetJointProperties, GetLinkProperties, GetModelProperties,
                             GetModelState, GetWorldProperties, SpawnModel)
from geometry_msgs.msg import Pose

from sim_studio import request_fields
from sim_studio.gazebo import GazeboServices
from sim_studio.view import View
from sim_studio.views.models import model_library, primitives

log = logging.getLogger("sim_studio")
TREE_POLL_S = 1.0
JOINT_TYPES = {0: "revolute", 1: "continuous", 2: "prismatic", 3: "fixed", 4: "ball", 5: "universal"}


def roll_pitch_yaw(q):
    """Gazebo's pose display: fixed-axis roll, pitch, yaw (rad) of a quaternion."""
    roll = math.atan2(2 * (q.w * q.x + q.y * q.z), 1 - 2 * (q.x * q.x + q.y * q.y))
    pitch = math.asin(max(-1.0, min(1.0, 2 * (q.w * q.y - q.z * q.x))))
    yaw = math.atan2(2 * (q.w * q.z + q.x * q.y), 1 - 2 * (q.y * q.y + q.z * q.z))
    return [roll, pitch, yaw]


class ModelsView(View):
    title = "Models"
    slot = "left"
    order = 10

    def __init__(self, studio):
        super().__init__(studio)
        self.gazebo = GazeboServices(studio.blocking)
        self._tree = None         # [{"name", "links", "joints", "static"}]; None until read
        self._tree_names = None   # the model names it was read for
        self._tree_lock = None
        self._poller = None

    # --- lifetime ----------------------------------------------------------------------------
    def start(self):
        self._tree_lock = asyncio.Lock()
        self._poller = asyncio.ensure_future(self._poll_tree())

    def stop(self):
        if self._poller is not None:
            self._poller.cancel()
        self.gazebo.close()

    def connected(self, client):
        if self._tree is not None:
            client.send(self._tree_message())

    # --- the tree ----------------------------------------------------------------------------
    def _tree_message(self, error=None):
        return {"view": self.name, "type": "tree", "models": self._tree or [], "error": error}

    async def _poll_tree(self):
        was_down = False
        while True:
            if self.studio.clients:
                try:
                    await self._refresh_tree()
                    was_down = False
                except ValueError as e:  # the simulator is gone (restarting?): say so once
                    if not was_down:
                        self._tree, self._tree_names = None, None
                        self.studio.broadcast(self._tree_message(str(e)))
                    was_down = True
            await asyncio.sleep(TREE_POLL_S)

    async def _refresh_tree(self, force=False):
        async with self._tree_lock:
            world = await self.gazebo.request("get_world_properties", GetWorldProperties)
            names = list(world.model_names)
            if names == self._tree_names and not force:
                return
            models = []
            for name in names:
                try:
                    props = await self.gazebo.request("get_model_properties",
                                                       GetModelProperties, model_name=name)
                except ValueError:  # deleted between the two calls: the next poll sees it gone
                    continue
                models.append({"name": name, "links": list(props.body_names), "joints": list(props.joint_names),
                               "static": bool(props.is_static)})
            self._tree, self._tree_names = models, names
            self.studio.broadcast(self._tree_message())

    def _model(self, name):
        for model in self._tree or []:
            if model["name"] == name:
                return model
        raise ValueError("model: no model named %r in the simulator (there are: %s)"
                         % (name, ", ".join(m["name"] for m in self._tree or []) or "none"))

    # --- requests ----------------------------------------------------------------------------
    async def handle(self, client, message):
        kind = message["type"]
        if kind == "tree":
            await self._refresh_tree(force=True)
            client.reply(message, models=self._tree)
        elif kind == "details":
            client.reply(message, **await self._details(request_fields.name(message, "model")))
        elif kind == "state":
            client.reply(message, **await self._state(request_fields.name(message, "model")))
        elif kind == "delete":
            client.reply(message, **await self._delete(request_fields.name(message, "model")))
        elif kind == "library":
            models = await self.studio.blocking(self._library)
            client.reply(message, models=[{"key": m["key"], "name": m["name"], "description": m["description"]}
                                          for m in models], shapes=list(primitives.SHAPES))
        elif kind == "insert":
            client.reply(message, **await self._insert(message))
        else:
            raise ValueError("view models takes tree, details, state, delete, library, insert; got %r" % kind)

    async def _details(self, name):
        """What does not change while a model lives: links with their masses, joints with
        their types."""
        model = self._model(name)
        masses = {}
        # The simulator may lack get_link_properties; one question to the master, not a 2 s wait per link.
        has_masses = await self.gazebo.offered("get_link_properties")
        for link in model["links"] if has_masses else []:
            props = await self.gazebo.request("get_link_properties", GetLinkProperties,
                                               False, link_name="%s::%s" % (name, link))
            masses[link] = props.mass if props.success else None
        joints = []
        for joint in model["joints"]:
            props = await self.gazebo.request("get_joint_properties", GetJointProperties, False,
                                               joint_name="%s::%s" % (name, joint))
            joints.append({"name": joint, "type": JOINT_TYPES.get(props.type, "?") if props.success else "?"})
        return {"model": name, "static": model["static"],
                "links": [{"name": link, "mass": masses.get(link)} for link in model["links"]],
                "masses": has_masses, "joints": joints}

    async def _state(self, name):
        """What moves: the model's pose and twist, its joints' positions."""
        model = self._model(name)
        state = await self.gazebo.request("get_model_state", GetModelState,
                                           model_name=name, relative_entity_name="world")
        p, q, tw = state.pose.position, state.pose.orientation, state.twist
        positions = {}
        for joint in model["joints"]:
            props = await self.gazebo.request("get_joint_properties", GetJointProperties, False,
                                               joint_name="%s::%s" % (name, joint))
            positions[joint] = props.position[0] if props.success and props.position else None
        return {"model": name, "position": [p.x, p.y, p.z], "rpy": roll_pitch_yaw(q),
                "linear": [tw.linear.x, tw.linear.y, tw.linear.z], "angular": [tw.angular.x, tw.angular.y, tw.angular.z],
                "joints": positions}

    async def _delete(self, name):
        response = await self.gazebo.request("delete_model", DeleteModel, model_name=name)
        await self._refresh_tree(force=True)
        return {"model": name, "status": response.status_message}

    def _library(self):
        packages = rospkg.RosPack()
        folders = model_library.model_folders(os.environ.get("GAZEBO_MODEL_PATH", ""), os.path.expanduser("~"),
                                              [packages.get_path(p) for p in sorted(packages.list())])
        return model_library.find_models(folders)

    async def _insert(self, message):
        """A model from the library (`key`) or a shape (`shape`) at x, y, z (z defaults to
        standing on the ground for a shape, 0 for a model), under a name not yet taken."""
        x = request_fields.number(message, "x", 0.0)
        y = request_fields.number(message, "y", 0.0)
        if message.get("shape") is not None:
            shape = message["shape"]
            base = primitives.shape_model_name(shape)
            z = request_fields.number(message, "z", primitives.resting_height(shape))
            make_sdf = lambda name: primitives.shape_sdf(shape, name)  # noqa: E731
        else:
            key = request_fields.name(message, "key")
            found = [m for m in await self.studio.blocking(self._library) if m["key"] == key]
            if not found:  # only what the library lists: a page never names a file to read
                raise ValueError("key: no model %r in the model paths (GAZEBO_MODEL_PATH, ~/.gazebo/models, "
                                 "the packages' models/ folders)" % key)
            # named as model:// names it (the folder), not by model.config's display name
            base, z = os.path.basename(found[0]["folder"]), request_fields.number(message, "z", 0.0)
            text = await self.studio.blocking(model_library.read_sdf, found[0])
            make_sdf = lambda name: text  # noqa: E731  (spawn_sdf_model's model_name names it)
        world = await self.gazebo.request("get_world_properties", GetWorldProperties)
        name = model_library.unique_name(base, set(world.model_names))
        pose = Pose()
        pose.position.x, pose.position.y, pose.position.z = x, y, z
        pose.orientation.w = 1.0
        response = await self.gazebo.request("spawn_sdf_model", SpawnModel, model_name=name,
                                              model_xml=make_sdf(name), robot_namespace="", initial_pose=pose,
                                              reference_frame="world")
        await self._refresh_tree(force=True)
        return {"model": name, "status": response.status_message}


VIEW = ModelsView
