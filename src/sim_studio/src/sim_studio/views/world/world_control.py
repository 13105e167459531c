"""The toolbar's commands through /gazebo services: play, pause, step, reset world, reset time
and the real-time factor target, and the physics state the toolbar shows.

Gazebo's step button runs one physics step of a paused world. The simulator has no step
service, so a step here is: pause (if running), slow the pace to STEP_RATE steps a second,
unpause, pause again as soon as sim time has moved, and restore the pace. The slow pace leaves
a quarter of a second for the pause to arrive; the simulator's loop runs its first two steps
after an unpause back to back (its pacing starts counting after the first), so a step here is
two physics steps.
"""
import asyncio
import time

from gazebo_msgs.srv import GetPhysicsProperties, GetWorldProperties, SetPhysicsProperties
from std_srvs.srv import Empty

STEP_RATE = 4.0         # steps per wall second while stepping
STEP_TIMEOUT_S = 2.0


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

    async def step(self):
        """Pause, then let the simulator run a step (two, see above); the sim time after it."""
        async with self._lock:
            await self.gazebo.request("pause_physics", Empty)
            props = await self.physics()
            before = await self.sim_time()
            await self._set_rate(props, STEP_RATE)
            try:
                await self.gazebo.request("unpause_physics", Empty)
                deadline = time.monotonic() + STEP_TIMEOUT_S
                now = before
                while now < before + props.time_step / 2 and time.monotonic() < deadline:
                    now = await self.sim_time()
                await self.gazebo.request("pause_physics", Empty)
            finally:
                await self._set_rate(props, props.max_update_rate)
            return await self.sim_time()
