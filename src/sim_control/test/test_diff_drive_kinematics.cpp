// Unit tests of diff_drive_controller's ROS-free part: kinematics, odometry, speed limiter.
#include <gtest/gtest.h>

#include <cmath>

#include "sim_control/diff_drive_kinematics.h"

using namespace sim_control::diff_drive;

namespace {
constexpr double kSeparation = 0.5;  // m
constexpr double kRadius = 0.1;      // m
constexpr double kTol = 1e-9;

// Drives an Odometry with wheel angles that grow at constant rates for `steps` steps of `dt`,
// starting from (left0, right0) at time t0. Returns the final time.
double driveWheels(Odometry& odom, double& left, double& right, double left_rate, double right_rate, int steps,
                   double dt, double t0) {
  double t = t0;
  for (int i = 0; i < steps; ++i) {
    left += left_rate * dt;
    right += right_rate * dt;
    t += dt;
    odom.update(left, right, t);
  }
  return t;
}

Odometry makeOdometry(std::size_t window = 10) {
  Odometry odom(window);
  odom.setWheelParams(kSeparation, kRadius, kRadius);
  odom.init(0.0);
  odom.update(0.0, 0.0, 0.0);  // reference wheel positions
  return odom;
}
}  // namespace

// --- Kinematics ---

TEST(DiffDriveKinematics, ForwardStraight) {
  const BodyTwist t = forwardKinematics(2.0, 2.0, kSeparation, kRadius, kRadius);
  EXPECT_NEAR(t.linear, 0.2, kTol);
  EXPECT_NEAR(t.angular, 0.0, kTol);
  const BodyTwist back = forwardKinematics(-3.0, -3.0, kSeparation, kRadius, kRadius);
  EXPECT_NEAR(back.linear, -0.3, kTol);
  EXPECT_NEAR(back.angular, 0.0, kTol);
}

TEST(DiffDriveKinematics, ForwardTurnInPlace) {
  // Right wheel forward, left backward: counter-clockwise about z, no translation.
  const BodyTwist t = forwardKinematics(-5.0, 5.0, kSeparation, kRadius, kRadius);
  EXPECT_NEAR(t.linear, 0.0, kTol);
  EXPECT_NEAR(t.angular, 2.0 * 5.0 * kRadius / kSeparation, kTol);  // 2 rad/s
  const BodyTwist cw = forwardKinematics(5.0, -5.0, kSeparation, kRadius, kRadius);
  EXPECT_NEAR(cw.angular, -2.0, kTol);
}

TEST(DiffDriveKinematics, ForwardArc) {
  // Left 1 rad/s (0.1 m/s), right 3 rad/s (0.3 m/s): v = 0.2 m/s, w = 0.2/0.5 = 0.4 rad/s,
  // i.e. a left turn of radius v/w = 0.5 m.
  const BodyTwist t = forwardKinematics(1.0, 3.0, kSeparation, kRadius, kRadius);
  EXPECT_NEAR(t.linear, 0.2, kTol);
  EXPECT_NEAR(t.angular, 0.4, kTol);
  EXPECT_NEAR(t.linear / t.angular, 0.5, kTol);
}

TEST(DiffDriveKinematics, InverseMatchesRosControllersFormula) {
  // w_l = (v - w b/2) / r_l, w_r = (v + w b/2) / r_r
  const WheelVelocities w = inverseKinematics(0.2, 0.4, kSeparation, 0.1, 0.12);
  EXPECT_NEAR(w.left, (0.2 - 0.4 * 0.25) / 0.1, kTol);
  EXPECT_NEAR(w.right, (0.2 + 0.4 * 0.25) / 0.12, kTol);
}

TEST(DiffDriveKinematics, InverseThenForwardRoundTrips) {
  for (double v : {-1.0, 0.0, 0.3, 2.0}) {
    for (double w : {-2.0, 0.0, 0.7}) {
      const WheelVelocities wheels = inverseKinematics(v, w, kSeparation, 0.1, 0.11);
      const BodyTwist t = forwardKinematics(wheels.left, wheels.right, kSeparation, 0.1, 0.11);
      EXPECT_NEAR(t.linear, v, kTol);
      EXPECT_NEAR(t.angular, w, kTol);
    }
  }
}

// --- Rolling mean ---

TEST(DiffDriveRollingMean, MeanOfLastSamples) {
  RollingMean m(3);
  EXPECT_EQ(m.mean(), 0.0);
  m.push(1.0);
  EXPECT_NEAR(m.mean(), 1.0, kTol);
  m.push(2.0);
  EXPECT_NEAR(m.mean(), 1.5, kTol);
  m.push(3.0);
  m.push(10.0);  // drops the 1
  EXPECT_NEAR(m.mean(), (2.0 + 3.0 + 10.0) / 3.0, kTol);
  m.reset();
  EXPECT_EQ(m.mean(), 0.0);
}

// --- Odometry ---

TEST(DiffDriveOdometry, Straight) {
  Odometry odom = makeOdometry();
  double l = 0.0, r = 0.0;
  driveWheels(odom, l, r, 4.0, 4.0, 1000, 0.001, 0.0);  // 4 rad/s * 0.1 m = 0.4 m/s for 1 s
  EXPECT_NEAR(odom.x(), 0.4, 1e-12);
  EXPECT_NEAR(odom.y(), 0.0, 1e-12);
  EXPECT_NEAR(odom.heading(), 0.0, 1e-12);
  EXPECT_NEAR(odom.linear(), 0.4, 1e-9);
  EXPECT_NEAR(odom.angular(), 0.0, 1e-9);
}

TEST(DiffDriveOdometry, TurnInPlace) {
  Odometry odom = makeOdometry();
  double l = 0.0, r = 0.0;
  // 2.5 rad/s at 0.1 m radius: +/-0.25 m/s at the wheels, w = 0.5/0.5 = 1 rad/s, for pi/2 s.
  const int steps = 1571;
  const double dt = (M_PI / 2.0) / steps;
  driveWheels(odom, l, r, -2.5, 2.5, steps, dt, 0.0);
  EXPECT_NEAR(odom.heading(), M_PI / 2.0, 1e-9);
  EXPECT_NEAR(odom.x(), 0.0, 1e-12);
  EXPECT_NEAR(odom.y(), 0.0, 1e-12);
  EXPECT_NEAR(odom.linear(), 0.0, 1e-9);
  EXPECT_NEAR(odom.angular(), 1.0, 1e-6);
}

TEST(DiffDriveOdometry, ArcMatchesAnalyticPose) {
  Odometry odom = makeOdometry();
  double l = 0.0, r = 0.0;
  // v = 0.2 m/s, w = 0.4 rad/s (radius 0.5 m) for 5 s: well over a quarter circle.
  const double v = 0.2, w = 0.4, T = 5.0;
  driveWheels(odom, l, r, 1.0, 3.0, 5000, T / 5000, 0.0);
  EXPECT_NEAR(odom.heading(), w * T, 1e-9);
  EXPECT_NEAR(odom.x(), v / w * std::sin(w * T), 1e-9);
  EXPECT_NEAR(odom.y(), v / w * (1.0 - std::cos(w * T)), 1e-9);
  EXPECT_NEAR(odom.linear(), v, 1e-6);
  EXPECT_NEAR(odom.angular(), w, 1e-6);
}

TEST(DiffDriveOdometry, SquareOfWheelMoves) {
  // Straight 1 m, turn +90 deg in place, straight 1 m, turn +90 deg, straight 1 m:
  // ends at (0, 1) heading pi.
  Odometry odom = makeOdometry();
  double l = 0.0, r = 0.0, t = 0.0;
  const double straight_rate = 10.0;                            // rad/s -> 1 m/s
  const double turn_angle = M_PI / 2.0 * (kSeparation / 2.0) / kRadius;  // wheel rad per quarter turn
  for (int leg = 0; leg < 3; ++leg) {
    t = driveWheels(odom, l, r, straight_rate, straight_rate, 100, 0.01, t);  // 1 s
    if (leg < 2) t = driveWheels(odom, l, r, -turn_angle, turn_angle, 100, 0.01, t);
  }
  EXPECT_NEAR(odom.x(), 0.0, 1e-9);
  EXPECT_NEAR(odom.y(), 1.0, 1e-9);
  EXPECT_NEAR(odom.heading(), M_PI, 1e-9);
}

TEST(DiffDriveOdometry, UnequalRadiiAndWindow) {
  Odometry odom(2);
  odom.setWheelParams(kSeparation, 0.1, 0.2);
  odom.init(0.0);
  odom.update(0.0, 0.0, 0.0);
  // Left 2 rad/s * 0.1 = 0.2 m/s, right 1 rad/s * 0.2 = 0.2 m/s: straight at 0.2 m/s.
  double l = 0.0, r = 0.0;
  driveWheels(odom, l, r, 2.0, 1.0, 100, 0.01, 0.0);
  EXPECT_NEAR(odom.x(), 0.2, 1e-12);
  EXPECT_NEAR(odom.heading(), 0.0, 1e-12);
  // Speed doubles: after one step the 2-sample mean is halfway, after two it is the new speed.
  odom.update(l += 0.04, r += 0.02, 1.01);
  EXPECT_NEAR(odom.linear(), 0.3, 1e-9);
  odom.update(l += 0.04, r += 0.02, 1.02);
  EXPECT_NEAR(odom.linear(), 0.4, 1e-9);
}

TEST(DiffDriveOdometry, FirstUpdateIsTheReference) {
  // Wheels that start away from zero must not make the pose jump.
  Odometry odom(10);
  odom.setWheelParams(kSeparation, kRadius, kRadius);
  odom.init(0.0);
  odom.update(12.0, -7.0, 0.0);
  EXPECT_EQ(odom.x(), 0.0);
  EXPECT_EQ(odom.heading(), 0.0);
  odom.update(13.0, -6.0, 0.1);  // +1 rad on each wheel: 0.1 m straight
  EXPECT_NEAR(odom.x(), 0.1, 1e-12);
  EXPECT_NEAR(odom.heading(), 0.0, 1e-12);
}

TEST(DiffDriveOdometry, TooShortIntervalIntegratesPoseButKeepsVelocity) {
  Odometry odom = makeOdometry();
  EXPECT_TRUE(odom.update(1.0, 1.0, 0.1));  // 0.1 m in 0.1 s
  EXPECT_NEAR(odom.linear(), 1.0, 1e-9);
  EXPECT_FALSE(odom.update(2.0, 2.0, 0.10005));  // 50 us later: no velocity estimate
  EXPECT_NEAR(odom.x(), 0.2, 1e-12);
  EXPECT_NEAR(odom.linear(), 1.0, 1e-9);
}

TEST(DiffDriveOdometry, RungeKutta2ForTinyTurns) {
  // A turn below 1e-6 rad per step takes the Runge-Kutta 2 branch; it still tracks the arc.
  Odometry odom;
  const double v = 1.0, w = 5e-5;  // per step: 1e-3 m, 5e-8 rad
  for (int i = 0; i < 10000; ++i) odom.integrate(v * 1e-3, w * 1e-3);
  const double T = 10.0;
  EXPECT_NEAR(odom.heading(), w * T, 1e-12);
  EXPECT_NEAR(odom.x(), v / w * std::sin(w * T), 1e-9);
  EXPECT_NEAR(odom.y(), v / w * (1.0 - std::cos(w * T)), 1e-9);
}

TEST(DiffDriveOdometry, ExactArcStep) {
  // One exact step of a quarter circle of radius 1.
  Odometry odom;
  odom.integrateExact(M_PI / 2.0, M_PI / 2.0);
  EXPECT_NEAR(odom.x(), 1.0, 1e-12);
  EXPECT_NEAR(odom.y(), 1.0, 1e-12);
  EXPECT_NEAR(odom.heading(), M_PI / 2.0, 1e-12);
  // The same through Runge-Kutta 2 is only approximate (chord at the mid heading).
  Odometry rk;
  rk.integrateRungeKutta2(M_PI / 2.0, M_PI / 2.0);
  EXPECT_NEAR(rk.x(), M_PI / 2.0 * std::cos(M_PI / 4.0), 1e-12);
  EXPECT_NEAR(rk.y(), M_PI / 2.0 * std::sin(M_PI / 4.0), 1e-12);
}

TEST(DiffDriveOdometry, OpenLoop) {
  Odometry odom;
  odom.init(0.0);
  const double v = 0.3, w = -0.6;
  for (int i = 1; i <= 1000; ++i) odom.updateOpenLoop(v, w, i * 0.002);
  const double T = 2.0;
  EXPECT_NEAR(odom.heading(), w * T, 1e-9);
  EXPECT_NEAR(odom.x(), v / w * std::sin(w * T), 1e-9);
  EXPECT_NEAR(odom.y(), v / w * (1.0 - std::cos(w * T)), 1e-9);
  EXPECT_EQ(odom.linear(), v);
  EXPECT_EQ(odom.angular(), w);
}

// --- Speed limiter ---

TEST(DiffDriveSpeedLimiter, NoLimitsPassThrough) {
  SpeedLimiter l;
  double v = 123.0;
  EXPECT_EQ(l.limit(v, -50.0, 7.0, 0.01), 1.0);
  EXPECT_EQ(v, 123.0);
}

TEST(DiffDriveSpeedLimiter, Velocity) {
  SpeedLimiter l;
  l.has_velocity_limits = true;
  l.max_velocity = 1.0;
  l.min_velocity = -0.5;
  double v = 3.0;
  EXPECT_NEAR(l.limit(v, 0.0, 0.0, 0.01), 1.0 / 3.0, kTol);
  EXPECT_EQ(v, 1.0);
  v = -2.0;
  l.limit(v, 0.0, 0.0, 0.01);
  EXPECT_EQ(v, -0.5);
  v = 0.7;
  l.limit(v, 0.0, 0.0, 0.01);
  EXPECT_EQ(v, 0.7);
  v = 0.0;
  EXPECT_EQ(l.limitVelocity(v), 1.0);  // ratio of a zero request is 1
}

TEST(DiffDriveSpeedLimiter, Acceleration) {
  SpeedLimiter l;
  l.has_acceleration_limits = true;
  l.max_acceleration = 2.0;
  l.min_acceleration = -4.0;
  double v = 10.0;
  l.limit(v, 0.0, 0.0, 0.1);  // at most +0.2 m/s in 0.1 s
  EXPECT_NEAR(v, 0.2, kTol);
  v = -10.0;
  l.limit(v, 1.0, 1.0, 0.1);  // at most -0.4 m/s in 0.1 s
  EXPECT_NEAR(v, 0.6, kTol);
  v = 1.1;
  l.limit(v, 1.0, 1.0, 0.1);  // within the limit
  EXPECT_NEAR(v, 1.1, kTol);
  v = 5.0;
  l.limit(v, 1.0, 1.0, 0.0);  // no time: no change
  EXPECT_EQ(v, 1.0);
  // Ramp: 10 steps of 0.1 s reach 2 m/s.
  double v0 = 0.0, v1 = 0.0;
  for (int i = 0; i < 10; ++i) {
    double cmd = 100.0;
    l.limit(cmd, v0, v1, 0.1);
    v1 = v0;
    v0 = cmd;
  }
  EXPECT_NEAR(v0, 2.0, 1e-9);
}

TEST(DiffDriveSpeedLimiter, Jerk) {
  SpeedLimiter l;
  l.has_jerk_limits = true;
  l.max_jerk = 5.0;
  l.min_jerk = -5.0;
  // ros_controllers: (v - v0) - (v0 - v1) is clamped to +/- max_jerk * 2 dt^2 = +/-0.1.
  double v = 10.0;
  l.limit(v, 0.0, 0.0, 0.1);
  EXPECT_NEAR(v, 0.1, kTol);
  v = 10.0;
  l.limit(v, 0.1, 0.0, 0.1);  // previous change 0.1, may grow by 0.1 more
  EXPECT_NEAR(v, 0.3, kTol);
  v = 0.0;
  l.limit(v, 0.3, 0.1, 0.1);  // previous change 0.2, may shrink by 0.1 only
  EXPECT_NEAR(v, 0.4, kTol);
}

TEST(DiffDriveSpeedLimiter, JerkThenAccelerationThenVelocity) {
  SpeedLimiter l;
  l.has_velocity_limits = l.has_acceleration_limits = l.has_jerk_limits = true;
  l.max_velocity = 0.25;
  l.min_velocity = -0.25;
  l.max_acceleration = 1.0;
  l.min_acceleration = -1.0;
  l.max_jerk = 100.0;
  l.min_jerk = -100.0;
  // Jerk allows +2 (100 * 2 * 0.01), acceleration then +0.1, velocity then 0.25.
  double v = 10.0;
  l.limit(v, 0.2, 0.2, 0.1);
  EXPECT_NEAR(v, 0.25, kTol);
  v = 10.0;
  l.limit(v, 0.0, 0.0, 0.1);
  EXPECT_NEAR(v, 0.1, kTol);  // acceleration-limited
}
