// pioneer_ros::Pid: P, I and D terms, anti-windup and output limits (no ROS).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

#include "pioneer_ros/pid.h"

namespace pioneer_ros {
namespace {

// pytest.approx's default: within a millionth of the expected value.
#define EXPECT_APPROX(actual, expected) EXPECT_NEAR((actual), (expected), 1e-6 * std::abs(expected) + 1e-12)

PidGains gains(double p, double i = 0.0, double d = 0.0) {
  PidGains g;
  g.p = p;
  g.i = i;
  g.d = d;
  return g;
}

PidGains limited(double p, double i, double output_min, double output_max) {
  PidGains g = gains(p, i);
  g.output_min = output_min;
  g.output_max = output_max;
  return g;
}

TEST(Pid, ProportionalOnly) {
  Pid pid(gains(2.0));
  EXPECT_APPROX(pid.update(0.5, 0.1), 1.0);
  EXPECT_APPROX(pid.update(-0.25, 0.1), -0.5);
}

TEST(Pid, FeedforwardIsAdded) {
  Pid pid(gains(1.0));
  EXPECT_APPROX(pid.update(0.1, 0.05, std::nullopt, 0.4), 0.5);
}

TEST(Pid, IntegralAccumulatesErrorTimesDt) {
  Pid pid(gains(0.0, 2.0));
  double out = 0.0;
  for (int k = 0; k < 10; ++k) out = pid.update(0.5, 0.1);
  EXPECT_APPROX(out, 2.0 * 0.5 * 1.0);
  EXPECT_APPROX(pid.integral(), 1.0);
}

TEST(Pid, IntegralIsClamped) {
  PidGains g = gains(0.0, 10.0);
  g.i_clamp = 0.3;
  Pid pid(g);
  double out = 0.0;
  for (int k = 0; k < 100; ++k) out = pid.update(1.0, 0.1);
  EXPECT_APPROX(out, 0.3);
  for (int k = 0; k < 100; ++k) out = pid.update(-1.0, 0.1);
  EXPECT_APPROX(out, -0.3);
}

TEST(Pid, DerivativeOfTheError) {
  Pid pid(gains(0.0, 0.0, 0.5));
  EXPECT_APPROX(pid.update(0.0, 0.1), 0.0);  // no history yet
  EXPECT_APPROX(pid.update(1.0, 0.1), 0.5 * 10.0);
}

TEST(Pid, DerivativeOnMeasurementIgnoresSetpointSteps) {
  Pid pid(gains(0.0, 0.0, 1.0));
  pid.update(0.0, 0.1, 0.0);
  // The setpoint jumps (error 0 -> 1) while the measurement stays: no derivative kick.
  EXPECT_APPROX(pid.update(1.0, 0.1, 0.0), 0.0);
  // The measurement rises at 2 per second: D opposes it.
  EXPECT_APPROX(pid.update(0.8, 0.1, 0.2), -2.0);
}

TEST(Pid, DerivativeFilterSmoothsAStep) {
  PidGains g = gains(0.0, 0.0, 1.0);
  g.d_filter_time = 0.1;
  Pid pid(g);
  pid.update(0.0, 0.1);
  const double first = pid.update(1.0, 0.1);
  EXPECT_APPROX(first, 0.5 * 10.0);               // alpha = dt / (tf + dt) = 0.5
  EXPECT_LT(std::abs(pid.update(1.0, 0.1)), first);  // and decays once the error is steady
}

TEST(Pid, OutputIsLimited) {
  Pid pid(limited(10.0, 0.0, -1.0, 0.5));
  EXPECT_APPROX(pid.update(1.0, 0.1), 0.5);
  EXPECT_TRUE(pid.saturated());
  EXPECT_APPROX(pid.update(-1.0, 0.1), -1.0);
}

TEST(Pid, NoWindupWhileSaturated) {
  Pid pid(limited(1.0, 1.0, -1.0, 1.0));
  for (int k = 0; k < 200; ++k) EXPECT_APPROX(pid.update(2.0, 0.1), 1.0);  // a long block: output pinned at the limit
  EXPECT_LT(pid.integral(), 0.5);  // it stopped integrating once the output hit the limit
  // When the error reverses, the output leaves the limit at once instead of after unwinding
  // 20 s worth of integral.
  EXPECT_LT(pid.update(-0.5, 0.1), 0.5);
}

TEST(Pid, IntegratingOutOfSaturationIsAllowed) {
  Pid pid(limited(1.0, 1.0, -1.0, 1.0));
  pid.update(0.08, 10.0);  // an integral of 0.8, unsaturated (0.08 + 0.8)
  EXPECT_APPROX(pid.integral(), 0.8);
  pid.update(-0.1, 0.1, std::nullopt, 2.0);  // saturated high, but the error pulls down
  EXPECT_APPROX(pid.integral(), 0.79);
}

TEST(Pid, ZeroDtNeitherIntegratesNorDifferentiates) {
  Pid pid(gains(1.0, 5.0, 5.0));
  pid.update(1.0, 0.1);
  const double integral = pid.integral(), derivative = pid.derivative();
  pid.update(3.0, 0.0);
  EXPECT_EQ(pid.integral(), integral);
  EXPECT_EQ(pid.derivative(), derivative);
}

TEST(Pid, ResetClearsTheHistory) {
  Pid pid(gains(0.0, 1.0, 1.0));
  pid.update(1.0, 0.1);
  pid.update(2.0, 0.1);
  pid.reset();
  EXPECT_EQ(pid.integral(), 0.0);
  EXPECT_EQ(pid.derivative(), 0.0);
  EXPECT_EQ(pid.update(0.0, 0.1), 0.0);
}

TEST(Pid, BadGainsAreRefused) {
  PidGains nan_p;
  nan_p.p = std::nan("");
  PidGains negative_clamp;
  negative_clamp.i_clamp = -1.0;
  PidGains inverted_limits;
  inverted_limits.output_min = 1.0;
  inverted_limits.output_max = 0.0;
  PidGains negative_filter;
  negative_filter.d_filter_time = -0.1;
  const std::pair<PidGains, const char*> cases[] = {
      {nan_p, "p: "},
      {negative_clamp, "i_clamp: "},
      {inverted_limits, "output_min"},
      {negative_filter, "d_filter_time: "}};
  for (const auto& [bad, field] : cases) {
    try {
      Pid pid(bad);
      ADD_FAILURE() << "accepted gains with a bad " << field;
    } catch (const std::invalid_argument& e) {
      EXPECT_EQ(std::string(e.what()).rfind(field, 0), 0u) << e.what();
    }
  }
  EXPECT_EQ(validate(PidGains{}), "");
}

TEST(Pid, NonFiniteErrorIsRefused) {
  Pid pid(gains(1.0));
  EXPECT_THROW(pid.update(std::numeric_limits<double>::infinity(), 0.1), std::invalid_argument);
}

TEST(Pid, DescribeShowsTheGainsAndLimits) {
  PidGains g = limited(0.5, 2.0, -1.0, 1.0);
  g.d = 0.01;
  g.i_clamp = 0.3;
  g.d_filter_time = 0.05;
  EXPECT_EQ(describe(g), "PidGains(p=0.5, i=2, d=0.01, i_clamp=0.3, output=[-1, 1], d_filter_time=0.05)");
}

}  // namespace
}  // namespace pioneer_ros
