"""The toolbar's commands through /gazebo services: play, pause, step, reset world, reset time
and the real-time factor target, and the physics state the toolbar shows.

Gazebo's step button pauses the world and runs one physics step; the simulator does that on
/gazebo/step_world (bullet_sim_msgs/StepWorld, docs/SIMULATOR.md), which upstream gazebo_ros
has no counterpart for.
"""
import asyncio

from gazebo_msgs.srv import GetPhysicsProperties, GetWorldProperties, SetPhysicsProperties
from bullet_sim_msgs.srv import StepWorld
from std_srvs.srv import Empty

def target_factor(properties):
    """The real-time factor the simulator paces to: max_update_rate steps of time_step each
    wall second; 0 = as fast as it goes."""
    return properties.max_update_rate * properties.time_step


class WorldControl:
    def __init__(self, gazebo):
        self.gazebo = gazebo
        self._lock = asyncio.Lock()  # one command at a time, from any page: a step is several calls

    async def physics(self):
        return await self.gazebo.request("get_physics_properties", GetPhysicsProperties)

    async def sim_time(self):
        return (await self.gazebo.request("get_world_properties", GetWorldProperties)).sim_time

    async def pause(self):
        async with self._lock:
            await self.gazebo.request("pause_physics", Empty)

    async def play(self):
        async with self._lock:
            await self.gazebo.request("unpause_physics", Empty)

    async def reset_world(self):
        async with self._lock:
            await self.gazebo.request("reset_world", Empty)

    async def reset_time(self):
        async with self._lock:
            await self.gazebo.request("reset_simulation", Empty)

    async def set_target(self, factor):
        """Pace the simulator to `factor` times real time (0: as fast as it goes)."""
        if factor < 0:
            raise ValueError("real-time factor target: expected a number >= 0 (0: as fast as possible), got %g" % factor)
        async with self._lock:
            props = await self.physics()
            await self._set_rate(props, factor / props.time_step)

    async def _set_rate(self, props, rate):
        await self.gazebo.request("set_physics_properties", SetPhysicsProperties, time_step=props.time_step,
                                  max_update_rate=rate, gravity=props.gravity, ode_config=props.ode_config)

    async def step(self, steps=1):
        """Pause and run `steps` physics steps; the sim time after them."""
        async with self._lock:
            return (await self.gazebo.request("step_world", StepWorld, steps=steps)).sim_time
