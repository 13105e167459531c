// The drive plugins' <plugin> parameters: upstream's defaults, every parameter, and the errors a
// user sees; the namespaces and frames they resolve to.
#include <gtest/gtest.h>

#include <string>

#include "bullet_sim_core/description_error.h"
#include "bullet_sim_core/sdf_parser.h"
#include "bullet_sim_core/urdf_parser.h"
#include "bullet_sim_plugins/wheel_drive_config.h"
#include "bullet_sim_core/testing/error_of.h"

namespace bullet_sim {
namespace {

// A URDF robot with wheels of every joint type, and `gazebo_blocks`.
ModelDescription robot(const std::string& gazebo_blocks) {
  std::string xml = "<robot name='bot'><link name='base_link'/>";
  const auto joint = [&](const std::string& name, const std::string& type) {
    xml += "<link name='" + name + "_link'><inertial><mass value='1'/><inertia ixx='1' iyy='1' izz='1' ixy='0' "
           "ixz='0' iyz='0'/></inertial></link><joint name='" + name + "' type='" + type +
           "'><parent link='base_link'/><child link='" + name + "_link'/><limit lower='-1' upper='1' effort='1' "
           "velocity='1'/></joint>";
  };
  joint("left_wheel_joint", "continuous");
  joint("right_wheel_joint", "revolute");
  joint("caster_joint", "fixed");
  joint("lift", "prismatic");
  for (const char* wheel : {"lf", "rf", "lr", "rr"}) joint(wheel, "continuous");
  return parseUrdf(xml + "<gazebo reference='base_link'><mu1>1</mu1></gazebo>" + gazebo_blocks + "</robot>",
                   "bot.urdf", ResourceResolver(), "");
}

DiffDriveConfig diffDriveOf(const ModelDescription& m) { return parseDiffDrive(m.plugins.at(0), m); }
SkidSteerDriveConfig skidSteerOf(const ModelDescription& m) { return parseSkidSteerDrive(m.plugins.at(0), m); }

std::string diffDrive(const std::string& children) {
  return "<gazebo><plugin name='diff' filename='libgazebo_ros_diff_drive.so'>"
         "<leftJoint>left_wheel_joint</leftJoint><rightJoint>right_wheel_joint</rightJoint>" +
         children + "</plugin></gazebo>";
}

std::string skidSteer(const std::string& children) {
  return "<gazebo><plugin name='skid' filename='libgazebo_ros_skid_steer_drive.so'>"
         "<leftFrontJoint>lf</leftFrontJoint><rightFrontJoint>rf</rightFrontJoint>"
         "<leftRearJoint>lr</leftRearJoint><rightRearJoint>rr</rightRearJoint>" +
         children + "</plugin></gazebo>";
}

TEST(DiffDriveConfig, DefaultsAreUpstreams) {
  const auto c = diffDriveOf(robot(diffDrive("")));
  EXPECT_EQ(c.plugin_name, "diff");
  EXPECT_EQ(c.left_joint, "left_wheel_joint");
  EXPECT_EQ(c.right_joint, "right_wheel_joint");
  EXPECT_FALSE(c.robot_namespace_given);
  EXPECT_EQ(c.wheel_separation, 0.34);
  EXPECT_EQ(c.wheel_diameter, 0.15);
  EXPECT_EQ(c.wheel_torque, 5.0);
  EXPECT_EQ(c.wheel_acceleration, 0.0);
  EXPECT_EQ(c.command_topic, "cmd_vel");
  EXPECT_EQ(c.odometry_topic, "odom");
  EXPECT_EQ(c.odometry_frame, "odom");
  EXPECT_EQ(c.robot_base_frame, "base_footprint");
  EXPECT_EQ(c.odometry_source, OdometrySource::World);
  EXPECT_TRUE(c.publish_tf);
  EXPECT_TRUE(c.publish_odom_tf);
  EXPECT_FALSE(c.publish_wheel_tf);
  EXPECT_FALSE(c.publish_wheel_joint_state);
  EXPECT_FALSE(c.legacy_mode);
  EXPECT_EQ(c.update_rate, 100.0);
  EXPECT_EQ(c.cmd_timeout, 0.5);
}

TEST(DiffDriveConfig, ReadsEveryParameter) {
  const auto c = diffDriveOf(robot(diffDrive(
      "<robotNamespace>/r1</robotNamespace><wheelSeparation> 0.5 </wheelSeparation><wheelDiameter>0.2</wheelDiameter>"
      "<wheelTorque>20</wheelTorque><wheelAcceleration>1.5</wheelAcceleration><commandTopic>cmd</commandTopic>"
      "<odometryTopic>wheel_odom</odometryTopic><odometryFrame>/odom2</odometryFrame>"
      "<robotBaseFrame>base_link</robotBaseFrame><odometrySource>encoder</odometrySource>"
      "<publishTf>1</publishTf><publishOdomTF>false</publishOdomTF><publishWheelTF>True</publishWheelTF>"
      "<publishWheelJointState>true</publishWheelJointState><legacyMode>true</legacyMode>"
      "<updateRate>50</updateRate><cmdTimeout>0</cmdTimeout><rosDebugLevel>Debug</rosDebugLevel>")));
  EXPECT_TRUE(c.robot_namespace_given);
  EXPECT_EQ(c.robot_namespace, "/r1");
  EXPECT_EQ(c.wheel_separation, 0.5);
  EXPECT_EQ(c.wheel_diameter, 0.2);
  EXPECT_EQ(c.wheel_torque, 20.0);
  EXPECT_EQ(c.wheel_acceleration, 1.5);
  EXPECT_EQ(c.command_topic, "cmd");
  EXPECT_EQ(c.odometry_topic, "wheel_odom");
  EXPECT_EQ(c.odometry_frame, "/odom2");
  EXPECT_EQ(c.robot_base_frame, "base_link");
  EXPECT_EQ(c.odometry_source, OdometrySource::Encoder);
  EXPECT_TRUE(c.publish_tf);
  EXPECT_FALSE(c.publish_odom_tf);
  EXPECT_TRUE(c.publish_wheel_tf);
  EXPECT_TRUE(c.publish_wheel_joint_state);
  EXPECT_TRUE(c.legacy_mode);
  EXPECT_EQ(c.update_rate, 50.0);
  EXPECT_EQ(c.cmd_timeout, 0.0);
}

TEST(DiffDriveConfig, OlderTorqueIsUsedUnlessWheelTorqueIsGiven) {
  EXPECT_EQ(diffDriveOf(robot(diffDrive("<torque>12</torque>"))).wheel_torque, 12.0);
  EXPECT_EQ(diffDriveOf(robot(diffDrive("<torque>12</torque><wheelTorque>3</wheelTorque>"))).wheel_torque, 3.0);
}

TEST(DiffDriveConfig, OdometrySourceAlsoTakesUpstreamsEnumNumbers) {
  EXPECT_EQ(diffDriveOf(robot(diffDrive("<odometrySource>0</odometrySource>"))).odometry_source,
            OdometrySource::Encoder);
  EXPECT_EQ(diffDriveOf(robot(diffDrive("<odometrySource>1</odometrySource>"))).odometry_source,
            OdometrySource::World);
}

TEST(DiffDriveConfig, LegacyModeIsNotValidated) {
  // Noetic's plugin does not read it, so nothing it says can be wrong.
  EXPECT_FALSE(diffDriveOf(robot(diffDrive("<legacyMode>maybe</legacyMode>"))).legacy_mode);
}

TEST(DiffDriveConfig, SdfModelPluginIsReadToo) {
  const ModelDescription m = parseSdfModel(
      "<model name='bot'><link name='base'/><link name='l'/><link name='r'/>"
      "<joint name='lf' type='revolute'><parent>base</parent><child>l</child></joint>"
      "<joint name='rf' type='revolute'><parent>base</parent><child>r</child></joint>"
      "<plugin name='d' filename='/opt/lib/libgazebo_ros_diff_drive.so'><leftJoint>lf</leftJoint>"
      "<rightJoint>rf</rightJoint></plugin></model>",
      "bot.sdf", "", ResourceResolver());
  const DiffDriveConfig c = diffDriveOf(m);
  EXPECT_EQ(c.left_joint, "lf");
  EXPECT_EQ(c.where, "bot.sdf: <model name='bot'>/<plugin name='d' filename='/opt/lib/libgazebo_ros_diff_drive.so'>");
}

TEST(DiffDriveConfig, BadValuesNameSourcePathAndExpectation) {
  const std::string where = "bot.urdf: <gazebo>/<plugin name='diff' filename='libgazebo_ros_diff_drive.so'>";
  EXPECT_EQ(errorOf([] { diffDriveOf(robot(diffDrive("<wheelSeparation>wide</wheelSeparation>"))); }),
            where + "/<wheelSeparation>: expected a number > 0 (m), got 'wide'");
  EXPECT_EQ(errorOf([] { diffDriveOf(robot(diffDrive("<wheelDiameter>0</wheelDiameter>"))); }),
            where + "/<wheelDiameter>: expected a number > 0 (m), got '0'");
  EXPECT_EQ(errorOf([] { diffDriveOf(robot(diffDrive("<wheelTorque>-1</wheelTorque>"))); }),
            where + "/<wheelTorque>: expected a number >= 0 (N m), got '-1'");
  EXPECT_EQ(errorOf([] { diffDriveOf(robot(diffDrive("<updateRate>nan</updateRate>"))); }),
            where + "/<updateRate>: expected a number >= 0 (Hz; 0 for every step), got 'nan'");
  EXPECT_EQ(errorOf([] { diffDriveOf(robot(diffDrive("<cmdTimeout>1 s</cmdTimeout>"))); }),
            where + "/<cmdTimeout>: expected a number >= 0 (s; 0 for never), got '1 s'");
  EXPECT_EQ(errorOf([] { diffDriveOf(robot(diffDrive("<publishOdomTF>yes</publishOdomTF>"))); }),
            where + "/<publishOdomTF>: expected true, false, 1 or 0, got 'yes'");
  EXPECT_EQ(errorOf([] { diffDriveOf(robot(diffDrive("<odometrySource>gps</odometrySource>"))); }),
            where + "/<odometrySource>: expected world or encoder, got 'gps'");
}

TEST(DiffDriveConfig, WheelsMustBeRevoluteOrContinuousJointsOfTheModel) {
  const std::string where = "bot.urdf: <gazebo>/<plugin name='d' filename='libgazebo_ros_diff_drive.so'>";
  auto block = [](const std::string& children) {
    return "<gazebo><plugin name='d' filename='libgazebo_ros_diff_drive.so'>" + children + "</plugin></gazebo>";
  };
  EXPECT_EQ(errorOf([&] {
              diffDriveOf(robot(block("<leftJoint>nope</leftJoint><rightJoint>rf</rightJoint>")));
            }),
            where + "/<leftJoint>: expected a revolute or continuous joint of model 'bot', got 'nope'");
  EXPECT_EQ(errorOf([&] {
              diffDriveOf(robot(block("<leftJoint>lf</leftJoint><rightJoint>caster_joint</rightJoint>")));
            }),
            where + "/<rightJoint>: expected a revolute or continuous joint of model 'bot', got 'caster_joint' "
                    "(a fixed joint)");
  EXPECT_EQ(errorOf([&] { diffDriveOf(robot(block("<leftJoint>lift</leftJoint>"))); }),
            where + "/<leftJoint>: expected a revolute or continuous joint of model 'bot', got 'lift' "
                    "(a prismatic joint)");
  EXPECT_EQ(errorOf([&] { diffDriveOf(robot(block("<leftJoint>lf</leftJoint>"))); }),
            where + "/<rightJoint>: expected a revolute or continuous joint of model 'bot', got 'right_joint' "
                    "(the default, as <rightJoint> is missing)");
}

TEST(SkidSteerDriveConfig, DefaultsAreUpstreams) {
  const auto c = skidSteerOf(robot(skidSteer("")));
  EXPECT_EQ(c.left_front_joint, "lf");
  EXPECT_EQ(c.right_front_joint, "rf");
  EXPECT_EQ(c.left_rear_joint, "lr");
  EXPECT_EQ(c.right_rear_joint, "rr");
  EXPECT_EQ(c.wheel_separation, 0.4);
  EXPECT_EQ(c.wheel_diameter, 0.15);
  EXPECT_EQ(c.torque, 5.0);
  EXPECT_EQ(c.command_topic, "cmd_vel");
  EXPECT_EQ(c.odometry_topic, "odom");
  EXPECT_EQ(c.odometry_frame, "odom");
  EXPECT_EQ(c.robot_base_frame, "base_footprint");
  EXPECT_FALSE(c.broadcast_tf);
  EXPECT_EQ(c.update_rate, 100.0);
  EXPECT_EQ(c.covariance_x, 0.0001);
  EXPECT_EQ(c.covariance_y, 0.0001);
  EXPECT_EQ(c.covariance_yaw, 0.01);
  EXPECT_EQ(c.cmd_timeout, 0.5);
}

TEST(SkidSteerDriveConfig, ReadsParametersAndRejectsBadOnes) {
  const auto c = skidSteerOf(robot(skidSteer(
      "<torque>40</torque><broadcastTF>1</broadcastTF><covariance_x>0.5</covariance_x><covariance_yaw>2</covariance_yaw>"
      "<wheelSeparation>0.6</wheelSeparation><cmdTimeout>1</cmdTimeout><robotNamespace></robotNamespace>")));
  EXPECT_EQ(c.torque, 40.0);
  EXPECT_TRUE(c.broadcast_tf);
  EXPECT_EQ(c.covariance_x, 0.5);
  EXPECT_EQ(c.covariance_yaw, 2.0);
  EXPECT_EQ(c.wheel_separation, 0.6);
  EXPECT_EQ(c.cmd_timeout, 1.0);
  EXPECT_TRUE(c.robot_namespace_given);

  const std::string where = "bot.urdf: <gazebo>/<plugin name='skid' filename='libgazebo_ros_skid_steer_drive.so'>";
  EXPECT_EQ(errorOf([] { skidSteerOf(robot(skidSteer("<covariance_y>-1</covariance_y>"))); }),
            where + "/<covariance_y>: expected a number >= 0, got '-1'");
  EXPECT_EQ(errorOf([] {
              skidSteerOf(robot("<gazebo><plugin name='s' filename='libgazebo_ros_skid_steer_drive.so'>"
                                        "<leftFrontJoint>lf</leftFrontJoint><rightFrontJoint>rf</rightFrontJoint>"
                                        "<leftRearJoint>lr</leftRearJoint></plugin></gazebo>"));
            }),
            "bot.urdf: <gazebo>/<plugin name='s' filename='libgazebo_ros_skid_steer_drive.so'>/<rightRearJoint>: "
            "expected a revolute or continuous joint of model 'bot', got 'right_rear_joint' (the default, as "
            "<rightRearJoint> is missing)");
}

TEST(DriveNamespaces, FollowGazeboPlugins) {
  DiffDriveConfig diff;
  EXPECT_EQ(diffDriveNamespace(diff, "/", "bot"), "/");      // spawn_model's default: the caller's namespace
  EXPECT_EQ(diffDriveNamespace(diff, "/r2", "bot"), "/r2");
  EXPECT_EQ(diffDriveNamespace(diff, "", "bot"), "bot");     // e.g. from a .world file: the model name
  diff.robot_namespace_given = true;
  EXPECT_EQ(diffDriveNamespace(diff, "/r2", "bot"), "bot");  // empty <robotNamespace/>: the model name
  diff.robot_namespace = "/r1";
  EXPECT_EQ(diffDriveNamespace(diff, "/r2", "bot"), "/r1");  // the plugin's own wins

  SkidSteerDriveConfig skid;
  EXPECT_EQ(skidSteerNamespace(skid, "/r2"), "/r2");
  EXPECT_EQ(skidSteerNamespace(skid, ""), "");
  skid.robot_namespace_given = true;
  EXPECT_EQ(skidSteerNamespace(skid, "/r2"), "");  // empty <robotNamespace/>: global
  skid.robot_namespace = "r1";
  EXPECT_EQ(skidSteerNamespace(skid, "/r2"), "r1");
}

TEST(ResolveFrame, IsTfResolveWithoutLeadingSlash) {
  EXPECT_EQ(resolveFrame("", "odom"), "odom");
  EXPECT_EQ(resolveFrame("", "/odom"), "odom");
  EXPECT_EQ(resolveFrame("robot1", "odom"), "robot1/odom");
  EXPECT_EQ(resolveFrame("/robot1/", "base_footprint"), "robot1/base_footprint");
  EXPECT_EQ(resolveFrame("/robot1", "/map"), "map");
  EXPECT_EQ(resolveFrame("/", "odom"), "odom");
}

}  // namespace
}  // namespace bullet_sim
