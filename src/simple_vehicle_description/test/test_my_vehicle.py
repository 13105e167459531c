#!/usr/bin/env python3
"""my_vehicle_world.launch: the RE510 lecture's vehicle as Gazebo's model editor saves it (an SDF model
with joints, a lidar sensor and the skid-steer plugin) loads through a world's <include>, stands on its
wheels, its lidar publishes, it drives and turns on /cmd_vel; spawn_model -sdf spawns it too; and SDF
joints with mistakes are refused with messages naming the element while the simulator keeps running."""
import os
import subprocess
import time
import unittest

import rospkg
import rospy
import rostest
from gazebo_msgs.srv import DeleteModel, GetModelProperties, GetWorldProperties, SpawnModel
from geometry_msgs.msg import Pose
from sensor_msgs.msg import LaserScan

from vehicle_checks import VehicleChecks

MODEL_SDF = os.path.join(rospkg.RosPack().get_path('simple_vehicle_description'), 'models', 'my_vehicle', 'model.sdf')
WHEEL_JOINTS = ['front_left_wheel_joint', 'front_right_wheel_joint', 'back_left_wheel_joint', 'back_right_wheel_joint']


def two_links(joint):
    """A small SDF model whose only joint is `joint`."""
    link = ("<link name='%s'><pose>%s</pose><collision name='c'><geometry><sphere><radius>0.1</radius></sphere>"
            "</geometry></collision></link>")
    return ("<sdf version='1.6'><model name='broken'>" + link % ('a', '0 0 1 0 0 0') + link % ('b', '0.5 0 1 0 0 0') +
            joint + "</model></sdf>")


class MyVehicleTest(VehicleChecks, unittest.TestCase):
    MODEL = 'my_vehicle'
    CMD_VEL = '/cmd_vel'                 # the slide's plugin: <robotNamespace>/</robotNamespace>
    SCAN = '/my_vehicle/laser/scan'      # the slide's <topicName>
    WHEEL_LINKS = ['link_0', 'link_1', 'link_2', 'link_3']
    WHEEL_SEPARATION = 1.5  # the plugin's, which sets the wheels' speeds
    BASE_HEIGHT = 0.0                    # the model frame is on the ground; the body's link is at z 0.5

    def test_0_links_and_joints_are_the_model_editors(self):
        rospy.wait_for_service('/gazebo/get_model_properties', timeout=30)
        props = rospy.ServiceProxy('/gazebo/get_model_properties', GetModelProperties)(model_name=self.MODEL)
        self.assertTrue(props.success, props.status_message)
        self.assertEqual(sorted(props.body_names), ['link', 'link_0', 'link_1', 'link_2', 'link_3', 'link_4'])
        self.assertEqual(sorted(props.joint_names), sorted(WHEEL_JOINTS))
        body = self.link_state(link_name='my_vehicle::link')
        self.assertAlmostEqual(body.link_state.pose.position.z, 0.5, delta=0.01)  # its SDF link pose
        lidar = self.link_state(link_name='my_vehicle::link_4')
        self.assertAlmostEqual(lidar.link_state.pose.position.x, 0.8, delta=0.01)
        self.assertAlmostEqual(lidar.link_state.pose.position.z, 0.7, delta=0.01)

    def test_6_spawn_model_sdf_spawns_it_from_its_file(self):
        delete = rospy.ServiceProxy('/gazebo/delete_model', DeleteModel)
        self.assertTrue(delete(model_name=self.MODEL).success)
        spawned_at = rospy.get_time()
        done = subprocess.run(['rosrun', 'gazebo_ros', 'spawn_model', '-sdf', '-file', MODEL_SDF, '-model', self.MODEL,
                               '-x', '3', '-y', '-2'], stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                              timeout=60)
        self.assertEqual(done.returncode, 0, done.stdout)
        self.sleep_sim(1.0)
        pose = self.pose()
        self.assertAlmostEqual(pose.position.x, 3.0, delta=0.01)
        self.assertAlmostEqual(pose.position.y, -2.0, delta=0.01)
        self.assertAlmostEqual(pose.position.z, self.BASE_HEIGHT, delta=0.01)
        scan = rospy.wait_for_message(self.SCAN, LaserScan, timeout=30)
        self.assertGreater(scan.header.stamp.to_sec(), spawned_at)
        self.assertEqual(len(scan.ranges), 32)
        self.test_3_skid_steer_drives_it_forward_on_cmd_vel()

    def test_7_mistakes_in_sdf_joints_are_named_and_the_simulator_keeps_running(self):
        spawn = rospy.ServiceProxy('/gazebo/spawn_sdf_model', SpawnModel)
        cases = {
            "<joint name='j' type='revolute'><child>b</child></joint>":
                "<model name='broken'>/<joint name='j'>: missing required element <parent>",
            "<joint name='j' type='revolute'><parent>a</parent><child>wheel</child></joint>":
                "<model name='broken'>/<joint name='j'>/<child>: expected the name of a link of this model (a, b), "
                "got 'wheel'",
            "<joint name='j' type='revolute'><parent>a</parent><child>b</child><axis><xyz>0 one 0</xyz></axis></joint>":
                "<model name='broken'>/<joint name='j'>/<axis>/<xyz>: expected 3 numbers, got '0 one 0'",
            "<joint name='j' type='revolute'><parent>a</parent><child>b</child><axis><xyz>0 0 0</xyz></axis></joint>":
                "<model name='broken'>/<joint name='j'>/<axis>/<xyz>: expected a non-zero axis, got '0 0 0'",
        }
        for joint, message in cases.items():
            reply = spawn(model_name='broken', model_xml=two_links(joint), robot_namespace='', initial_pose=Pose(),
                          reference_frame='')
            self.assertFalse(reply.success, joint)
            self.assertIn(message, reply.status_message)
        world = rospy.ServiceProxy('/gazebo/get_world_properties', GetWorldProperties)()
        self.assertTrue(world.success)
        self.assertNotIn('broken', world.model_names)
        self.assertIn(self.MODEL, world.model_names)
        before = world.sim_time
        time.sleep(0.5)
        self.assertGreater(rospy.ServiceProxy('/gazebo/get_world_properties', GetWorldProperties)().sim_time, before)


if __name__ == '__main__':
    rostest.rosrun('simple_vehicle_description', 'my_vehicle', MyVehicleTest)
