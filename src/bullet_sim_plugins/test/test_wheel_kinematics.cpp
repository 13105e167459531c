// The drive plugins' arithmetic: wheel speeds, the acceleration ramp and command timeout, and
// encoder odometry against analytic poses.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "bullet_sim_plugins/wheel_kinematics.h"

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

}  // namespace
}  // namespace bullet_sim
