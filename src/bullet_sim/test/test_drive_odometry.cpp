// The ROS-free part of the drive plugins: wheel speeds, the acceleration ramp and command timeout,
// encoder odometry against analytic poses, and the <plugin> parameters (defaults and errors).
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "bullet_sim/description_error.h"
#include "bullet_sim/drive_odometry.h"

namespace bullet_sim {
namespace {

constexpr double kPi = 3.14159265358979323846;

// ---------------------------------------------------------------------------------------------
// Wheel speeds
// ---------------------------------------------------------------------------------------------

TEST(WheelSpeeds, StraightDrivesBothWheelsAtSpeedOverRadius) {
  const WheelSpeeds w = wheelSpeeds(1.0, 0.0, 0.34, 0.15);
  EXPECT_NEAR(w.left, 1.0 / 0.075, 1e-12);
  EXPECT_NEAR(w.right, 1.0 / 0.075, 1e-12);
  const WheelSpeeds back = wheelSpeeds(-0.5, 0.0, 0.34, 0.15);
  EXPECT_NEAR(back.left, -0.5 / 0.075, 1e-12);
  EXPECT_NEAR(back.right, -0.5 / 0.075, 1e-12);
}

TEST(WheelSpeeds, TurnInPlaceCounterClockwiseRunsTheRightWheelForward) {
  const WheelSpeeds w = wheelSpeeds(0.0, 1.0, 0.34, 0.15);
  EXPECT_NEAR(w.left, -0.17 / 0.075, 1e-12);
  EXPECT_NEAR(w.right, 0.17 / 0.075, 1e-12);
  const WheelSpeeds cw = wheelSpeeds(0.0, -2.0, 0.4, 0.2);
  EXPECT_NEAR(cw.left, 0.4 / 0.1, 1e-12);
  EXPECT_NEAR(cw.right, -0.4 / 0.1, 1e-12);
}

TEST(WheelSpeeds, ArcGivesTheRimSpeedsOfTheTwoRadii) {
  // v = 0.5 m/s, w = 0.25 rad/s: a 2 m radius; the wheels run on radii 2 -/+ 0.17 m.
  const WheelSpeeds w = wheelSpeeds(0.5, 0.25, 0.34, 0.15);
  EXPECT_NEAR(w.left * 0.075, 0.25 * (2.0 - 0.17), 1e-12);
  EXPECT_NEAR(w.right * 0.075, 0.25 * (2.0 + 0.17), 1e-12);
}

// ---------------------------------------------------------------------------------------------
// Ramp and timeout
// ---------------------------------------------------------------------------------------------

TEST(Ramp, StepsTowardTheTargetWithoutOvershoot) {
  EXPECT_DOUBLE_EQ(rampToward(0.0, 10.0, 1.0), 1.0);
  EXPECT_DOUBLE_EQ(rampToward(0.0, -10.0, 1.0), -1.0);
  EXPECT_DOUBLE_EQ(rampToward(9.5, 10.0, 1.0), 10.0);
  EXPECT_DOUBLE_EQ(rampToward(-9.5, -10.0, 1.0), -10.0);
  EXPECT_DOUBLE_EQ(rampToward(3.0, -3.0, INFINITY), -3.0);
  EXPECT_DOUBLE_EQ(rampToward(3.0, -3.0, 0.0), 3.0);
  EXPECT_DOUBLE_EQ(rampToward(3.0, -3.0, NAN), 3.0);
}

TEST(DriveCommand, AccelerationLimitsEachWheelsRimSpeed) {
  // 0.5 m/s^2 at the rim: 1 m/s takes 2 s, in 100 Hz updates.
  DriveCommand command(0.34, 0.15, 0.5, 0.0);
  command.setTwist(1.0, 0.0, 0.0);
  double t = 0.0;
  for (int i = 1; i <= 100; ++i) {
    t = i * 0.01;
    const WheelSpeeds w = command.update(t, 0.01);
    ASSERT_NEAR(w.left * 0.075, 0.5 * t, 1e-9) << "at " << t << " s";
    ASSERT_NEAR(w.right * 0.075, 0.5 * t, 1e-9);
  }
  for (int i = 101; i <= 300; ++i) command.update(i * 0.01, 0.01);
  EXPECT_NEAR(command.current().left * 0.075, 1.0, 1e-9);  // reached, and stays
  // Braking is limited too.
  command.setTwist(0.0, 0.0, 3.0);
  const WheelSpeeds w = command.update(3.01, 0.01);
  EXPECT_NEAR(w.left * 0.075, 1.0 - 0.005, 1e-9);
}

TEST(DriveCommand, WithoutAccelerationLimitTheTargetIsImmediate) {
  DriveCommand command(0.34, 0.15, 0.0, 0.0);
  EXPECT_EQ(command.update(0.0, 0.01).left, 0.0);  // no command yet: at rest
  command.setTwist(0.3, -0.6, 0.0);
  const WheelSpeeds expected = wheelSpeeds(0.3, -0.6, 0.34, 0.15);
  const WheelSpeeds w = command.update(0.01, 0.01);
  EXPECT_DOUBLE_EQ(w.left, expected.left);
  EXPECT_DOUBLE_EQ(w.right, expected.right);
}

TEST(DriveCommand, StopsWhenTheCommandIsOlderThanTheTimeout) {
  DriveCommand command(0.34, 0.15, 0.0, 0.5);
  EXPECT_FALSE(command.timedOut(10.0));  // no command: nothing to time out
  command.setTwist(1.0, 0.0, 1.0);
  EXPECT_GT(command.update(1.5, 0.01).left, 0.0);  // exactly 0.5 s old: still on
  EXPECT_FALSE(command.timedOut(1.5));
  EXPECT_TRUE(command.timedOut(1.51));
  EXPECT_EQ(command.update(1.51, 0.01).left, 0.0);
  EXPECT_EQ(command.update(1.51, 0.01).right, 0.0);
  command.setTwist(1.0, 0.0, 2.0);  // a new command drives again
  EXPECT_FALSE(command.timedOut(2.2));
  EXPECT_GT(command.update(2.2, 0.01).left, 0.0);
  command.reset();
  EXPECT_EQ(command.update(2.21, 0.01).left, 0.0);
  EXPECT_FALSE(command.timedOut(100.0));
}

TEST(DriveCommand, TimeoutZeroKeepsTheLastCommandForever) {
  DriveCommand command(0.34, 0.15, 0.0, 0.0);
  command.setTwist(1.0, 0.0, 0.0);
  EXPECT_FALSE(command.timedOut(1e6));
  EXPECT_NEAR(command.update(1e6, 0.01).left, 1.0 / 0.075, 1e-12);
}

TEST(DriveCommand, TimeoutBrakesThroughTheRamp) {
  DriveCommand command(0.34, 0.15, 1.0, 0.5);
  command.setTwist(0.2, 0.0, 0.0);
  for (int i = 1; i <= 50; ++i) command.update(i * 0.01, 0.01);
  EXPECT_NEAR(command.current().left * 0.075, 0.2, 1e-9);
  const WheelSpeeds w = command.update(0.51, 0.01);  // timed out: decelerate at 1 m/s^2
  EXPECT_NEAR(w.left * 0.075, 0.19, 1e-9);
}

// ---------------------------------------------------------------------------------------------
// Encoder odometry
// ---------------------------------------------------------------------------------------------

struct Pose2 {
  double x, y, heading;
};

// Feeds `seconds` of a constant twist to the odometry as wheel rotations in steps of `dt`.
void drive(EncoderOdometry& odometry, double linear, double angular, double seconds, double dt,
           double separation = 0.34, double diameter = 0.15) {
  const WheelSpeeds w = wheelSpeeds(linear, angular, separation, diameter);
  const int steps = static_cast<int>(std::round(seconds / dt));
  for (int i = 0; i < steps; ++i) odometry.integrate(w.left * dt, w.right * dt);
}

// Where a constant twist takes a pose in `seconds` (exact circular arc).
Pose2 analytic(Pose2 p, double linear, double angular, double seconds) {
  if (std::abs(angular) < 1e-12) return {p.x + linear * seconds * std::cos(p.heading),
                                         p.y + linear * seconds * std::sin(p.heading), p.heading};
  const double r = linear / angular;
  const double h = p.heading + angular * seconds;
  return {p.x + r * (std::sin(h) - std::sin(p.heading)), p.y - r * (std::cos(h) - std::cos(p.heading)), h};
}

void expectPose(const EncoderOdometry& o, const Pose2& p, double tolerance, const std::string& what) {
  EXPECT_NEAR(o.x(), p.x, tolerance) << what;
  EXPECT_NEAR(o.y(), p.y, tolerance) << what;
  EXPECT_NEAR(o.heading(), p.heading, tolerance) << what;
}

TEST(EncoderOdometry, SequenceOfStraightTurnAndArcMatchesTheAnalyticPose) {
  for (double dt : {0.001, 0.01, 0.1}) {
    EncoderOdometry odometry(0.34, 0.15);
    Pose2 expected{0, 0, 0};
    const std::string at = "dt " + std::to_string(dt);

    drive(odometry, 1.0, 0.0, 2.0, dt);  // 1 m/s for 2 s
    expected = analytic(expected, 1.0, 0.0, 2.0);
    expectPose(odometry, expected, 1e-9, "after the straight, " + at);
    EXPECT_NEAR(odometry.x(), 2.0, 1e-9);

    drive(odometry, 0.0, 1.0, 1.5, dt);  // turn in place: 1.5 rad
    expected = analytic(expected, 0.0, 1.0, 1.5);
    expectPose(odometry, expected, 1e-9, "after the turn, " + at);

    drive(odometry, 0.5, 0.25, 4.0, dt);  // arc of radius 2 m through 1 rad
    expected = analytic(expected, 0.5, 0.25, 4.0);
    expectPose(odometry, expected, 1e-9, "after the arc, " + at);

    drive(odometry, -0.3, -0.4, 2.0, dt);  // backwards, turning clockwise
    expected = analytic(expected, -0.3, -0.4, 2.0);
    expectPose(odometry, expected, 1e-9, "after reversing, " + at);

    EXPECT_NEAR(odometry.distance(), 2.0 + 0.0 + 2.0 - 0.6, 1e-9) << at;
  }
}

TEST(EncoderOdometry, OutAndBackReturnsToTheStart) {
  EncoderOdometry odometry(0.4, 0.2);
  drive(odometry, 0.7, 0.0, 3.0, 0.001, 0.4, 0.2);
  drive(odometry, 0.0, -0.5, 2.0 * kPi, 0.001 * kPi, 0.4, 0.2);  // half a turn, clockwise
  drive(odometry, 0.7, 0.0, 3.0, 0.001, 0.4, 0.2);
  EXPECT_NEAR(odometry.x(), 0.0, 1e-9);
  EXPECT_NEAR(odometry.y(), 0.0, 1e-9);
  EXPECT_NEAR(odometry.heading(), -kPi, 1e-9);
}

TEST(EncoderOdometry, UpdateTakesTheFirstAnglesAsReference) {
  EncoderOdometry odometry(0.34, 0.15);
  odometry.update(100.0, -50.0);  // wherever the wheels happen to be
  EXPECT_EQ(odometry.x(), 0.0);
  odometry.update(100.0 + 1.0 / 0.075, -50.0 + 1.0 / 0.075);  // both wheels 1 m forward
  EXPECT_NEAR(odometry.x(), 1.0, 1e-12);
  EXPECT_NEAR(odometry.y(), 0.0, 1e-12);
  odometry.reset();
  odometry.resetReference();
  odometry.update(0.0, 0.0);
  odometry.update(-0.17 / 0.075 * kPi, 0.17 / 0.075 * kPi);  // half a turn in place
  EXPECT_NEAR(odometry.heading(), kPi, 1e-12);
  EXPECT_NEAR(odometry.x(), 0.0, 1e-12);
  EXPECT_NEAR(odometry.distance(), 0.0, 1e-12);
}

// ---------------------------------------------------------------------------------------------
// Configuration
// ---------------------------------------------------------------------------------------------

JointDescription joint(const std::string& name, JointType type) {
  JointDescription j;
  j.name = name;
  j.type = type;
  j.parent = "base_link";
  j.child = name + "_link";
  return j;
}

ModelDescription robot(const std::string& gazebo_block) {
  ModelDescription m;
  m.name = "bot";
  m.source = "bot.urdf";
  m.joints = {joint("left_wheel_joint", JointType::Continuous), joint("right_wheel_joint", JointType::Revolute),
              joint("caster_joint", JointType::Fixed),          joint("lift", JointType::Prismatic),
              joint("lf", JointType::Continuous),               joint("rf", JointType::Continuous),
              joint("lr", JointType::Continuous),               joint("rr", JointType::Continuous)};
  m.extensions = {GazeboExtension{"base_link", "<gazebo reference='base_link'><mu1>1</mu1></gazebo>"},
                  GazeboExtension{"", gazebo_block}};
  return m;
}

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

// The DescriptionError message of `f`, or "" if it did not throw one.
template <class F>
std::string errorOf(F f) {
  try {
    f();
  } catch (const DescriptionError& e) {
    return e.what();
  }
  return "";
}

TEST(DiffDriveConfig, AbsentWithoutTheBlock) {
  EXPECT_FALSE(parseDiffDrive(robot("<gazebo><plugin name='c' filename='libgazebo_ros_control.so'/></gazebo>")));
  EXPECT_FALSE(parseSkidSteerDrive(robot(diffDrive(""))));
}

TEST(DiffDriveConfig, DefaultsAreUpstreams) {
  const auto c = parseDiffDrive(robot(diffDrive("")));
  ASSERT_TRUE(c);
  EXPECT_EQ(c->plugin_name, "diff");
  EXPECT_EQ(c->left_joint, "left_wheel_joint");
  EXPECT_EQ(c->right_joint, "right_wheel_joint");
  EXPECT_FALSE(c->robot_namespace_given);
  EXPECT_EQ(c->wheel_separation, 0.34);
  EXPECT_EQ(c->wheel_diameter, 0.15);
  EXPECT_EQ(c->wheel_torque, 5.0);
  EXPECT_EQ(c->wheel_acceleration, 0.0);
  EXPECT_EQ(c->command_topic, "cmd_vel");
  EXPECT_EQ(c->odometry_topic, "odom");
  EXPECT_EQ(c->odometry_frame, "odom");
  EXPECT_EQ(c->robot_base_frame, "base_footprint");
  EXPECT_EQ(c->odometry_source, OdometrySource::World);
  EXPECT_TRUE(c->publish_tf);
  EXPECT_TRUE(c->publish_odom_tf);
  EXPECT_FALSE(c->publish_wheel_tf);
  EXPECT_FALSE(c->publish_wheel_joint_state);
  EXPECT_FALSE(c->legacy_mode);
  EXPECT_EQ(c->update_rate, 100.0);
  EXPECT_EQ(c->cmd_timeout, 0.5);
}

TEST(DiffDriveConfig, ReadsEveryParameter) {
  const auto c = parseDiffDrive(robot(diffDrive(
      "<robotNamespace>/r1</robotNamespace><wheelSeparation> 0.5 </wheelSeparation><wheelDiameter>0.2</wheelDiameter>"
      "<wheelTorque>20</wheelTorque><wheelAcceleration>1.5</wheelAcceleration><commandTopic>cmd</commandTopic>"
      "<odometryTopic>wheel_odom</odometryTopic><odometryFrame>/odom2</odometryFrame>"
      "<robotBaseFrame>base_link</robotBaseFrame><odometrySource>encoder</odometrySource>"
      "<publishTf>1</publishTf><publishOdomTF>false</publishOdomTF><publishWheelTF>True</publishWheelTF>"
      "<publishWheelJointState>true</publishWheelJointState><legacyMode>true</legacyMode>"
      "<updateRate>50</updateRate><cmdTimeout>0</cmdTimeout><rosDebugLevel>Debug</rosDebugLevel>")));
  ASSERT_TRUE(c);
  EXPECT_TRUE(c->robot_namespace_given);
  EXPECT_EQ(c->robot_namespace, "/r1");
  EXPECT_EQ(c->wheel_separation, 0.5);
  EXPECT_EQ(c->wheel_diameter, 0.2);
  EXPECT_EQ(c->wheel_torque, 20.0);
  EXPECT_EQ(c->wheel_acceleration, 1.5);
  EXPECT_EQ(c->command_topic, "cmd");
  EXPECT_EQ(c->odometry_topic, "wheel_odom");
  EXPECT_EQ(c->odometry_frame, "/odom2");
  EXPECT_EQ(c->robot_base_frame, "base_link");
  EXPECT_EQ(c->odometry_source, OdometrySource::Encoder);
  EXPECT_TRUE(c->publish_tf);
  EXPECT_FALSE(c->publish_odom_tf);
  EXPECT_TRUE(c->publish_wheel_tf);
  EXPECT_TRUE(c->publish_wheel_joint_state);
  EXPECT_TRUE(c->legacy_mode);
  EXPECT_EQ(c->update_rate, 50.0);
  EXPECT_EQ(c->cmd_timeout, 0.0);
}

TEST(DiffDriveConfig, OlderTorqueIsUsedUnlessWheelTorqueIsGiven) {
  EXPECT_EQ(parseDiffDrive(robot(diffDrive("<torque>12</torque>")))->wheel_torque, 12.0);
  EXPECT_EQ(parseDiffDrive(robot(diffDrive("<torque>12</torque><wheelTorque>3</wheelTorque>")))->wheel_torque, 3.0);
}

TEST(DiffDriveConfig, OdometrySourceAlsoTakesUpstreamsEnumNumbers) {
  EXPECT_EQ(parseDiffDrive(robot(diffDrive("<odometrySource>0</odometrySource>")))->odometry_source,
            OdometrySource::Encoder);
  EXPECT_EQ(parseDiffDrive(robot(diffDrive("<odometrySource>1</odometrySource>")))->odometry_source,
            OdometrySource::World);
}

TEST(DiffDriveConfig, LegacyModeIsNotValidated) {
  // Noetic's plugin does not read it, so nothing it says can be wrong.
  EXPECT_FALSE(parseDiffDrive(robot(diffDrive("<legacyMode>maybe</legacyMode>")))->legacy_mode);
}

TEST(DiffDriveConfig, SdfModelPluginIsFoundToo) {
  ModelDescription m = robot("");
  m.extensions = {GazeboExtension{"", "<plugin name='d' filename='/opt/lib/libgazebo_ros_diff_drive.so'>"
                                      "<leftJoint>lf</leftJoint><rightJoint>rf</rightJoint></plugin>"}};
  const auto c = parseDiffDrive(m);
  ASSERT_TRUE(c);
  EXPECT_EQ(c->left_joint, "lf");
  EXPECT_EQ(c->where, "bot.urdf: <plugin name='d' filename='/opt/lib/libgazebo_ros_diff_drive.so'>");
}

TEST(DiffDriveConfig, BadValuesNameSourcePathAndExpectation) {
  const std::string where = "bot.urdf: <gazebo>/<plugin name='diff' filename='libgazebo_ros_diff_drive.so'>";
  EXPECT_EQ(errorOf([] { parseDiffDrive(robot(diffDrive("<wheelSeparation>wide</wheelSeparation>"))); }),
            where + "/<wheelSeparation>: expected a number > 0 (m), got 'wide'");
  EXPECT_EQ(errorOf([] { parseDiffDrive(robot(diffDrive("<wheelDiameter>0</wheelDiameter>"))); }),
            where + "/<wheelDiameter>: expected a number > 0 (m), got '0'");
  EXPECT_EQ(errorOf([] { parseDiffDrive(robot(diffDrive("<wheelTorque>-1</wheelTorque>"))); }),
            where + "/<wheelTorque>: expected a number >= 0 (N m), got '-1'");
  EXPECT_EQ(errorOf([] { parseDiffDrive(robot(diffDrive("<updateRate>nan</updateRate>"))); }),
            where + "/<updateRate>: expected a number >= 0 (Hz; 0 for every step), got 'nan'");
  EXPECT_EQ(errorOf([] { parseDiffDrive(robot(diffDrive("<cmdTimeout>1 s</cmdTimeout>"))); }),
            where + "/<cmdTimeout>: expected a number >= 0 (s; 0 for never), got '1 s'");
  EXPECT_EQ(errorOf([] { parseDiffDrive(robot(diffDrive("<publishOdomTF>yes</publishOdomTF>"))); }),
            where + "/<publishOdomTF>: expected true or false (or 1 or 0), got 'yes'");
  EXPECT_EQ(errorOf([] { parseDiffDrive(robot(diffDrive("<odometrySource>gps</odometrySource>"))); }),
            where + "/<odometrySource>: expected world or encoder, got 'gps'");
}

TEST(DiffDriveConfig, WheelsMustBeRevoluteOrContinuousJointsOfTheModel) {
  const std::string where = "bot.urdf: <gazebo>/<plugin name='d' filename='libgazebo_ros_diff_drive.so'>";
  auto block = [](const std::string& children) {
    return "<gazebo><plugin name='d' filename='libgazebo_ros_diff_drive.so'>" + children + "</plugin></gazebo>";
  };
  EXPECT_EQ(errorOf([&] {
              parseDiffDrive(robot(block("<leftJoint>nope</leftJoint><rightJoint>rf</rightJoint>")));
            }),
            where + "/<leftJoint>: expected a revolute or continuous joint of model 'bot', got 'nope'");
  EXPECT_EQ(errorOf([&] {
              parseDiffDrive(robot(block("<leftJoint>lf</leftJoint><rightJoint>caster_joint</rightJoint>")));
            }),
            where + "/<rightJoint>: expected a revolute or continuous joint of model 'bot', got 'caster_joint' "
                    "(a fixed joint)");
  EXPECT_EQ(errorOf([&] { parseDiffDrive(robot(block("<leftJoint>lift</leftJoint>"))); }),
            where + "/<leftJoint>: expected a revolute or continuous joint of model 'bot', got 'lift' "
                    "(a prismatic joint)");
  EXPECT_EQ(errorOf([&] { parseDiffDrive(robot(block("<leftJoint>lf</leftJoint>"))); }),
            where + "/<rightJoint>: expected a revolute or continuous joint of model 'bot', got 'right_joint' "
                    "(the default, as <rightJoint> is missing)");
}

TEST(DiffDriveConfig, TwoBlocksAreAnError) {
  ModelDescription m = robot(diffDrive(""));
  m.extensions.push_back(GazeboExtension{"", diffDrive("")});
  EXPECT_NE(errorOf([&] { parseDiffDrive(m); }).find("expected at most one libgazebo_ros_diff_drive.so plugin"),
            std::string::npos);
}

TEST(SkidSteerDriveConfig, DefaultsAreUpstreams) {
  const auto c = parseSkidSteerDrive(robot(skidSteer("")));
  ASSERT_TRUE(c);
  EXPECT_EQ(c->left_front_joint, "lf");
  EXPECT_EQ(c->right_front_joint, "rf");
  EXPECT_EQ(c->left_rear_joint, "lr");
  EXPECT_EQ(c->right_rear_joint, "rr");
  EXPECT_EQ(c->wheel_separation, 0.4);
  EXPECT_EQ(c->wheel_diameter, 0.15);
  EXPECT_EQ(c->torque, 5.0);
  EXPECT_EQ(c->command_topic, "cmd_vel");
  EXPECT_EQ(c->odometry_topic, "odom");
  EXPECT_EQ(c->odometry_frame, "odom");
  EXPECT_EQ(c->robot_base_frame, "base_footprint");
  EXPECT_FALSE(c->broadcast_tf);
  EXPECT_EQ(c->update_rate, 100.0);
  EXPECT_EQ(c->covariance_x, 0.0001);
  EXPECT_EQ(c->covariance_y, 0.0001);
  EXPECT_EQ(c->covariance_yaw, 0.01);
  EXPECT_EQ(c->cmd_timeout, 0.5);
}

TEST(SkidSteerDriveConfig, ReadsParametersAndRejectsBadOnes) {
  const auto c = parseSkidSteerDrive(robot(skidSteer(
      "<torque>40</torque><broadcastTF>1</broadcastTF><covariance_x>0.5</covariance_x><covariance_yaw>2</covariance_yaw>"
      "<wheelSeparation>0.6</wheelSeparation><cmdTimeout>1</cmdTimeout><robotNamespace></robotNamespace>")));
  ASSERT_TRUE(c);
  EXPECT_EQ(c->torque, 40.0);
  EXPECT_TRUE(c->broadcast_tf);
  EXPECT_EQ(c->covariance_x, 0.5);
  EXPECT_EQ(c->covariance_yaw, 2.0);
  EXPECT_EQ(c->wheel_separation, 0.6);
  EXPECT_EQ(c->cmd_timeout, 1.0);
  EXPECT_TRUE(c->robot_namespace_given);

  const std::string where = "bot.urdf: <gazebo>/<plugin name='skid' filename='libgazebo_ros_skid_steer_drive.so'>";
  EXPECT_EQ(errorOf([] { parseSkidSteerDrive(robot(skidSteer("<covariance_y>-1</covariance_y>"))); }),
            where + "/<covariance_y>: expected a number >= 0, got '-1'");
  EXPECT_EQ(errorOf([] {
              parseSkidSteerDrive(robot("<gazebo><plugin name='s' filename='libgazebo_ros_skid_steer_drive.so'>"
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
