// Pid against control_toolbox's semantics, with gains given directly (no ROS master needed).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "sim_control/pid.h"

using sim_control::Pid;
using sim_control::PidGains;

namespace {
PidGains gains(double p, double i, double d, double i_clamp = 0.0, bool antiwindup = false) {
  PidGains g;
  g.p = p;
  g.i = i;
  g.d = d;
  g.i_clamp_min = -i_clamp;
  g.i_clamp_max = i_clamp;
  g.antiwindup = antiwindup;
  return g;
}
}  // namespace

TEST(Pid, ProportionalTerm) {
  Pid pid(gains(2.0, 0.0, 0.0));
  EXPECT_DOUBLE_EQ(pid.compute(1.5, 0.0, 0.01), 3.0);
  EXPECT_DOUBLE_EQ(pid.compute(-0.5, 0.0, 0.01), -1.0);
  EXPECT_DOUBLE_EQ(pid.lastCommand(), -1.0);
  EXPECT_DOUBLE_EQ(pid.lastError(), -0.5);
}

TEST(Pid, DerivativeTermUsesGivenRate) {
  Pid pid(gains(0.0, 0.0, 3.0));
  EXPECT_DOUBLE_EQ(pid.compute(10.0, -2.0, 0.01), -6.0);
  EXPECT_DOUBLE_EQ(pid.lastErrorDot(), -2.0);
}

TEST(Pid, DerivativeFromErrorDifference) {
  Pid pid(gains(0.0, 0.0, 1.0));
  // No previous error yet: no derivative kick on the first step.
  EXPECT_DOUBLE_EQ(pid.compute(1.0, 0.1), 0.0);
  EXPECT_DOUBLE_EQ(pid.compute(1.5, 0.1), 5.0);  // (1.5 - 1.0) / 0.1
  EXPECT_DOUBLE_EQ(pid.lastErrorDot(), 5.0);
}

TEST(Pid, IntegralAccumulatesWithinClamp) {
  Pid pid(gains(0.0, 2.0, 0.0, 100.0));
  EXPECT_DOUBLE_EQ(pid.compute(1.0, 0.0, 0.5), 1.0);  // 2 * 0.5 * 1
  EXPECT_DOUBLE_EQ(pid.compute(1.0, 0.0, 0.5), 2.0);
  EXPECT_DOUBLE_EQ(pid.compute(-3.0, 0.0, 0.5), -1.0);
}

TEST(Pid, IntegralIsZeroWithoutClamp) {
  // control_toolbox's default i_clamp of 0 holds the integral term at 0.
  Pid pid(gains(0.0, 5.0, 0.0));
  EXPECT_DOUBLE_EQ(pid.compute(1.0, 0.0, 1.0), 0.0);
  EXPECT_DOUBLE_EQ(pid.compute(1.0, 0.0, 1.0), 0.0);
}

TEST(Pid, IntegralClampWithoutAntiwindupKeepsWindingUp) {
  Pid pid(gains(0.0, 1.0, 0.0, 1.0));
  for (int k = 0; k < 5; ++k) EXPECT_LE(pid.compute(1.0, 0.0, 1.0), 1.0);  // state reaches 5
  EXPECT_DOUBLE_EQ(pid.lastCommand(), 1.0);
  // The hidden state has to unwind from 5 before the output leaves the bound.
  EXPECT_DOUBLE_EQ(pid.compute(-1.0, 0.0, 1.0), 1.0);  // state 4
  EXPECT_DOUBLE_EQ(pid.compute(-1.0, 0.0, 1.0), 1.0);  // state 3
}

TEST(Pid, AntiwindupClampsTheState) {
  Pid pid(gains(0.0, 1.0, 0.0, 1.0, true));
  for (int k = 0; k < 5; ++k) pid.compute(1.0, 0.0, 1.0);
  EXPECT_DOUBLE_EQ(pid.lastCommand(), 1.0);
  // The state stopped at 1, so it unwinds at once.
  EXPECT_DOUBLE_EQ(pid.compute(-1.0, 0.0, 1.0), 0.0);
  EXPECT_DOUBLE_EQ(pid.compute(-1.0, 0.0, 1.0), -1.0);
  EXPECT_DOUBLE_EQ(pid.compute(-1.0, 0.0, 1.0), -1.0);
}

TEST(Pid, AsymmetricClamp) {
  PidGains g = gains(0.0, 1.0, 0.0);
  g.i_clamp_min = -0.5;
  g.i_clamp_max = 2.0;
  Pid pid(g);
  EXPECT_DOUBLE_EQ(pid.compute(-10.0, 0.0, 1.0), -0.5);
  pid.reset();
  EXPECT_DOUBLE_EQ(pid.compute(10.0, 0.0, 1.0), 2.0);
}

TEST(Pid, SumOfTerms) {
  Pid pid(gains(2.0, 1.0, 0.5, 10.0));
  // p: 2 * 1 = 2; i: 1 * 0.1 * 1 = 0.1; d: 0.5 * 4 = 2
  EXPECT_DOUBLE_EQ(pid.compute(1.0, 4.0, 0.1), 4.1);
}

TEST(Pid, BadStepOrInputGivesZeroAndKeepsState) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  Pid pid(gains(1.0, 1.0, 1.0, 10.0));
  EXPECT_DOUBLE_EQ(pid.compute(1.0, 0.0, 1.0), 2.0);  // i state 1
  EXPECT_DOUBLE_EQ(pid.compute(1.0, 0.0, 0.0), 0.0);
  EXPECT_DOUBLE_EQ(pid.compute(1.0, 0.0, -0.1), 0.0);
  EXPECT_DOUBLE_EQ(pid.compute(nan, 0.0, 1.0), 0.0);
  EXPECT_DOUBLE_EQ(pid.compute(1.0, inf, 1.0), 0.0);
  EXPECT_DOUBLE_EQ(pid.compute(1.0, 0.0, nan), 0.0);
  EXPECT_DOUBLE_EQ(pid.compute(5.0, 0.0), 0.0);
  EXPECT_DOUBLE_EQ(pid.lastCommand(), 2.0);
  EXPECT_DOUBLE_EQ(pid.lastError(), 1.0);
  // None of the rejected calls touched the integral: 1 + 1 * 1 * 1 = 2, plus p 1.
  EXPECT_DOUBLE_EQ(pid.compute(1.0, 0.0, 1.0), 3.0);
}

TEST(Pid, ResetClearsState) {
  Pid pid(gains(0.0, 1.0, 1.0, 10.0));
  pid.compute(1.0, 1.0);
  pid.compute(2.0, 1.0);  // i state 3, last error 2
  pid.reset();
  EXPECT_DOUBLE_EQ(pid.lastCommand(), 0.0);
  EXPECT_DOUBLE_EQ(pid.lastError(), 0.0);
  // Integral starts again from 0, and no derivative from the error before the reset.
  EXPECT_DOUBLE_EQ(pid.compute(1.0, 1.0), 1.0);
}

TEST(Pid, SetGainsKeepsState) {
  Pid pid(gains(1.0, 0.0, 0.0));
  pid.compute(1.0, 0.0, 1.0);
  pid.setGains(gains(3.0, 0.0, 0.0));
  EXPECT_DOUBLE_EQ(pid.gains().p, 3.0);
  EXPECT_DOUBLE_EQ(pid.compute(1.0, 0.0, 1.0), 3.0);
}
