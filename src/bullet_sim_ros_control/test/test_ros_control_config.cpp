// What libgazebo_ros_control.so reads: its parameters and the URDF's transmissions.
#include <gtest/gtest.h>

#include <string>

#include "bullet_sim_core/description_error.h"
#include "bullet_sim_core/resource_resolver.h"
#include "bullet_sim_core/urdf_parser.h"
#include "bullet_sim_ros_control/ros_control_config.h"
#include "bullet_sim_core/testing/error_of.h"

namespace bullet_sim {
namespace {

ModelDescription robot(const std::string& extra) {
  const std::string xml = R"(<robot name="arm">
    <link name="base"/>
    <link name="upper"><inertial><mass value="1"/><inertia ixx="1" iyy="1" izz="1" ixy="0" ixz="0" iyz="0"/></inertial></link>
    <link name="lower"><inertial><mass value="1"/><inertia ixx="1" iyy="1" izz="1" ixy="0" ixz="0" iyz="0"/></inertial></link>
    <joint name="shoulder" type="revolute"><parent link="base"/><child link="upper"/>
      <limit lower="-1" upper="1" effort="10" velocity="1"/></joint>
    <joint name="elbow" type="continuous"><parent link="upper"/><child link="lower"/></joint>)" +
                          extra + "</robot>";
  return parseUrdf(xml, "arm.urdf", ResourceResolver(), "");
}

TEST(RosControlConfig, DefaultsAreGazeboRosControls) {
  const ModelDescription m = robot("<gazebo><plugin name='c' filename='libgazebo_ros_control.so'/></gazebo>");
  ASSERT_EQ(m.plugins.size(), 1u);
  const RosControlConfig c = parseRosControlConfig(m.plugins[0], m.name);
  EXPECT_EQ(c.robot_namespace, "arm");  // the model's name
  EXPECT_EQ(c.control_period, 0.0);     // every step
  EXPECT_EQ(c.robot_param, "robot_description");
}

TEST(RosControlConfig, ReadsItsParametersAndNamesABadPeriod) {
  const ModelDescription m = robot(
      "<gazebo><plugin name='c' filename='libgazebo_ros_control.so'><robotNamespace>/rrbot</robotNamespace>"
      "<controlPeriod>0.002</controlPeriod><robotParam>arm_description</robotParam></plugin></gazebo>");
  const RosControlConfig c = parseRosControlConfig(m.plugins[0], m.name);
  EXPECT_EQ(c.robot_namespace, "/rrbot");
  EXPECT_EQ(c.control_period, 0.002);
  EXPECT_EQ(c.robot_param, "arm_description");
  const ModelDescription bad =
      robot("<gazebo><plugin name='c' filename='libgazebo_ros_control.so'><controlPeriod>-1</controlPeriod>"
            "</plugin></gazebo>");
  EXPECT_EQ(errorOf([&] { parseRosControlConfig(bad.plugins[0], bad.name); }),
            "arm.urdf: <gazebo>/<plugin name='c' filename='libgazebo_ros_control.so'>/<controlPeriod>: "
            "expected a number >= 0 (s), got '-1'");
}

TEST(RosControlConfig, TransmissionsGiveJointsAndInterfacesInBothSpellings) {
  const ModelDescription m = robot(R"(
    <transmission name="t1"><type>transmission_interface/SimpleTransmission</type>
      <joint name="shoulder"><hardwareInterface>hardware_interface/EffortJointInterface</hardwareInterface></joint>
      <actuator name="m1"><mechanicalReduction>50</mechanicalReduction></actuator></transmission>
    <transmission name="t2" type="transmission_interface/SimpleTransmission">
      <joint name="elbow"/>
      <actuator name="m2"><hardwareInterface>PositionJointInterface</hardwareInterface></actuator></transmission>)");
  const std::vector<TransmissionJoint> joints = transmissionJoints(m);
  ASSERT_EQ(joints.size(), 2u);
  EXPECT_EQ(joints[0].joint, "shoulder");
  EXPECT_EQ(joints[0].interface, sim_control::InterfaceType::Effort);
  EXPECT_EQ(joints[1].joint, "elbow");  // the interface on the actuator, as older tutorials write it
  EXPECT_EQ(joints[1].interface, sim_control::InterfaceType::Position);
  EXPECT_EQ(m.transmissions[0].actuators[0].mechanical_reduction, 50.0);
}

TEST(RosControlConfig, BadTransmissionsNameTheElement) {
  EXPECT_EQ(errorOf([] {
              transmissionJoints(robot("<transmission name='t'><type>transmission_interface/DifferentialTransmission"
                                       "</type><joint name='shoulder'/></transmission>"));
            }),
            "arm.urdf: <transmission name='t'>/<type>: expected transmission_interface/SimpleTransmission, got "
            "'transmission_interface/DifferentialTransmission'");
  EXPECT_EQ(errorOf([] {
              transmissionJoints(robot("<transmission name='t'><type>SimpleTransmission</type><joint name='elbow'>"
                                       "<hardwareInterface>TorqueInterface</hardwareInterface></joint></transmission>"));
            }),
            "arm.urdf: <transmission name='t'>/<joint name='elbow'>/<hardwareInterface>: expected "
            "EffortJointInterface, PositionJointInterface or VelocityJointInterface (with or without "
            "'hardware_interface/'), got 'TorqueInterface'");
}

}  // namespace
}  // namespace bullet_sim
