"""Joints (right of the world, as Gazebo's joint panel): for the selected model, per joint a
force, a position target with PID gains and a velocity target with PID gains, sent on
/gazebo/joint_cmd (bullet_sim_msgs/JointCmd) as Gazebo's panel sends msgs::JointCmd to the
model's JointController: the simulator holds each until it is changed or reset. The joints'
positions and velocities come from /gazebo/get_joint_properties, which the page polls a few
times a second while a model is selected."""
import rospy
from bullet_sim_msgs.msg import JointCmd
from gazebo_msgs.srv import GetJointProperties, GetModelProperties

from sim_studio import request_fields
from sim_studio.gazebo import GazeboServices
from sim_studio.view import View
from sim_studio.views.joints.joint_command import joint_cmd

JOINT_CMD_TOPIC = "/gazebo/joint_cmd"
JOINT_TYPES = {0: "revolute", 1: "continuous", 2: "prismatic", 3: "fixed", 4: "ball", 5: "universal"}


class JointsView(View):
    title = "Joints"
    slot = "right"
    order = 10

    def __init__(self, studio):
        super().__init__(studio)
        self.gazebo = GazeboServices(studio.blocking)
        self._publisher = None
        self._joints = {}  # model -> its joint names, as get_model_properties last said

    def start(self):
        self._publisher = rospy.Publisher(JOINT_CMD_TOPIC, JointCmd, queue_size=20)

    def stop(self):
        if self._publisher is not None:
            self._publisher.unregister()
        self.gazebo.close()

    async def handle(self, client, message):
        kind = message["type"]
        if kind == "joints":
            client.reply(message, **await self._describe(request_fields.name(message, "model")))
        elif kind == "positions":
            model = request_fields.name(message, "model")
            client.reply(message, model=model, joints=await self._positions(model, await self._joint_names(model)))
        elif kind == "command":
            model, joint = request_fields.name(message, "model"), request_fields.name(message, "joint")
            await self._check_joint(model, joint)
            self._publish(model, joint, message)
            client.reply(message, model=model, joint=joint)
        elif kind == "reset":
            model = request_fields.name(message, "model")
            for joint in await self._joint_names(model):
                self._publish(model, joint, {"reset": True})
            client.reply(message, model=model)
        else:
            raise ValueError("view joints takes joints, positions, command, reset; got %r" % kind)

    def _publish(self, model, joint, message):
        self._publisher.publish(joint_cmd(model, joint, message))

    async def _joint_names(self, model, fresh=True):
        if fresh or model not in self._joints:
            props = await self.gazebo.request("get_model_properties", GetModelProperties, model_name=model)
            self._joints[model] = list(props.joint_names)
        return self._joints[model]

    async def _check_joint(self, model, joint):
        names = await self._joint_names(model, fresh=False)
        if joint not in names:
            names = await self._joint_names(model)  # the model may have been spawned again since
        if joint not in names:
            raise ValueError("joint: model %r has no joint %r (it has: %s)" % (model, joint, ", ".join(names) or "none"))

    async def _positions(self, model, joints):
        found = {}
        for joint in joints:
            props = await self.gazebo.request("get_joint_properties", GetJointProperties, False,
                                              joint_name="%s::%s" % (model, joint))
            if props.success and props.position:
                found[joint] = {"type": JOINT_TYPES.get(props.type, "?"), "position": props.position[0],
                                "rate": props.rate[0] if props.rate else 0.0}
        return found

    async def _describe(self, model):
        names = await self._joint_names(model)
        positions = await self._positions(model, names)
        return {"model": model, "joints": [dict(positions.get(n, {"type": "?", "position": None, "rate": None}), name=n)
                                           for n in names]}


VIEW = JointsView
