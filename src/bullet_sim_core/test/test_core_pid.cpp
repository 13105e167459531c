// Pid (bullet_sim_core/pid.h; test_pid is sim_control's): Gazebo's common::PID terms, signs and clamps,
// none; no kick from the rate term's first step).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "bullet_sim_core/pid.h"

namespace bullet_sim {
namespace {

const double kDt = 0.001;

PidGains gains(double p, double i, double d) {
  PidGains g;
  g.p = p;
  g.i = i;
  g.d = d;
  return g;
}

TEST(Pid, EffortOpposesTheErrorItsIntegralAndItsRate) {
  Pid pid(gains(2.0, 0.0, 0.0));
  EXPECT_DOUBLE_EQ(pid.update(0.5, kDt), -1.0);  // measured above the target: pushed down
  EXPECT_DOUBLE_EQ(pid.update(-0.25, kDt), 0.5);

  Pid integral(gains(0.0, 3.0, 0.0));
  double effort = 0.0;
  for (int k = 0; k < 1000; ++k) effort = integral.update(0.1, kDt);  // 1 s of an error of 0.1
  EXPECT_NEAR(effort, -3.0 * 0.1 * 1.0, 1e-9);

  Pid rate(gains(0.0, 0.0, 0.5));
  EXPECT_DOUBLE_EQ(rate.update(1.0, kDt), 0.0);            // no rate on the first step: no kick
  EXPECT_NEAR(rate.update(1.002, kDt), -0.5 * 2.0, 1e-9);  // the error grows at 2 per s
  rate.forgetLastError();
  EXPECT_DOUBLE_EQ(rate.update(5.0, kDt), 0.0);  // a new target: no kick either
}

TEST(Pid, TheIntegralTermStopsAtItsBoundsAndComesBackAtOnce) {
  PidGains g = gains(0.0, 10.0, 0.0);
  g.i_max = 0.5;
  g.i_min = -0.25;
  Pid pid(g);
  double effort = 0.0;
  for (int k = 0; k < 10000; ++k) effort = pid.update(-1.0, kDt);  // unbounded, i * integral would be -100
  EXPECT_DOUBLE_EQ(effort, 0.25);                                   // the term held at i_min
  // No wind-up: one step of the opposite error already lowers the term.
  EXPECT_NEAR(pid.update(1.0, kDt), -(-0.25 + 10.0 * 1.0 * kDt), 1e-12);
  for (int k = 0; k < 10000; ++k) effort = pid.update(1.0, kDt);
  EXPECT_DOUBLE_EQ(effort, -0.5);  // and at i_max the other way
}

TEST(Pid, TheEffortStaysWithinItsCommandBounds) {
  PidGains g = gains(100.0, 0.0, 0.0);
  g.cmd_max = 3.0;
  g.cmd_min = -2.0;
  Pid pid(g);
  EXPECT_DOUBLE_EQ(pid.update(-1.0, kDt), 3.0);
  EXPECT_DOUBLE_EQ(pid.update(1.0, kDt), -2.0);
  EXPECT_DOUBLE_EQ(pid.update(0.01, kDt), -1.0);  // inside: untouched
}

TEST(Pid, ZeroWidthBoundsAreNoBounds) {
  // A message's defaults (all bounds 0) must not silence the PID, as Gazebo's [0, 0] clamp would.
  Pid pid(gains(100.0, 10.0, 0.0));
  EXPECT_NEAR(pid.update(-1.0, kDt), 100.0 + 10.0 * kDt, 1e-9);
  PidGains inverted = gains(100.0, 0.0, 0.0);
  inverted.cmd_max = -1.0;
  inverted.cmd_min = 1.0;
  EXPECT_DOUBLE_EQ(Pid(inverted).update(-1.0, kDt), 100.0);
}

TEST(Pid, NonFiniteErrorsAndStepsGiveNothingAndLeaveNoTrace) {
  Pid pid(gains(1.0, 1.0, 1.0));
  EXPECT_EQ(pid.update(std::numeric_limits<double>::quiet_NaN(), kDt), 0.0);
  EXPECT_EQ(pid.update(std::numeric_limits<double>::infinity(), kDt), 0.0);
  EXPECT_EQ(pid.update(1.0, 0.0), 0.0);
  EXPECT_NEAR(pid.update(1.0, kDt), -(1.0 + kDt), 1e-12);  // as if they had never come
  pid.reset();
  EXPECT_NEAR(pid.update(1.0, kDt), -(1.0 + kDt), 1e-12);  // the integral starts again
}

}  // namespace
}  // namespace bullet_sim
