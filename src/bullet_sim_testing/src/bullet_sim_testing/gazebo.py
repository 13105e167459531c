"""The /gazebo services as a test meets them: proxies created once the simulator is up, and pose helpers."""
import math
import time

import rospy
from gazebo_msgs.msg import ModelState
from gazebo_msgs.srv import (ApplyBodyWrench, ApplyJointEffort, DeleteModel, GetJointProperties, GetLinkProperties,
                             GetLinkState,
                             GetModelProperties, GetModelState, GetPhysicsProperties, GetWorldProperties,
                             SetLinkState, SetModelConfiguration, SetModelState, SetPhysicsProperties, SpawnModel)
from geometry_msgs.msg import Pose
from std_srvs.srv import Empty

G = 9.8  # empty.world's gravity


def pose(x=0.0, y=0.0, z=0.0, yaw=0.0):
    p = Pose()
    p.position.x, p.position.y, p.position.z = x, y, z
    p.orientation.z, p.orientation.w = math.sin(yaw / 2), math.cos(yaw / 2)
    return p


class Gazebo:
    """Proxies for the /gazebo services, created once the simulator is up."""

    SERVICES = {
        'spawn_urdf_model': SpawnModel, 'spawn_sdf_model': SpawnModel, 'delete_model': DeleteModel,
        'get_model_state': GetModelState, 'set_model_state': SetModelState, 'get_link_state': GetLinkState,
        'get_world_properties': GetWorldProperties, 'get_physics_properties': GetPhysicsProperties,
        'set_physics_properties': SetPhysicsProperties, 'apply_joint_effort': ApplyJointEffort,
        'apply_body_wrench': ApplyBodyWrench, 'set_model_configuration': SetModelConfiguration,
        'get_joint_properties': GetJointProperties, 'get_model_properties': GetModelProperties,
        'get_link_properties': GetLinkProperties,
        'set_link_state': SetLinkState, 'pause_physics': Empty, 'unpause_physics': Empty,
        'reset_world': Empty, 'reset_simulation': Empty,
    }

    def __init__(self, timeout=30.0):
        for name, service_type in self.SERVICES.items():
            rospy.wait_for_service('/gazebo/' + name, timeout=timeout)
            setattr(self, name, rospy.ServiceProxy('/gazebo/' + name, service_type))

    def spawn_urdf(self, name, xml, at=None, namespace=''):
        return self.spawn_urdf_model(model_name=name, model_xml=xml, robot_namespace=namespace,
                                     initial_pose=at or pose(), reference_frame='')

    def alive(self):
        return self.get_world_properties().success

    def sim_time(self):
        return self.get_world_properties().sim_time

    def state(self, name, relative=''):
        return self.get_model_state(model_name=name, relative_entity_name=relative)

    def set_state(self, name, at, reference=''):
        state = ModelState(model_name=name, pose=at, reference_frame=reference)
        return self.set_model_state(model_state=state)

    def run_for(self, sim_seconds, wall_timeout=60.0):
        """Unpause until sim time has advanced by sim_seconds, then pause again."""
        start = self.sim_time()
        self.unpause_physics()
        wall_deadline = time.monotonic() + wall_timeout
        while self.sim_time() < start + sim_seconds and time.monotonic() < wall_deadline:
            time.sleep(0.01)
        self.pause_physics()


def set_real_time_factor(rtf):
    """The simulator's target real-time factor through /gazebo/set_physics_properties (0: as fast as
    it goes), its time step and gravity kept."""
    props = rospy.ServiceProxy('/gazebo/get_physics_properties', GetPhysicsProperties)()
    rospy.ServiceProxy('/gazebo/set_physics_properties', SetPhysicsProperties)(
        time_step=props.time_step, max_update_rate=rtf / props.time_step, gravity=props.gravity,
        ode_config=props.ode_config)
