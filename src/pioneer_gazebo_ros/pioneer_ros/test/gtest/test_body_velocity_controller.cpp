// pioneer_ros::BodyVelocityController and its parameters: the modes and timeouts, the parameter
// tree of pioneer_controller_params.yaml, and the shipped gains on a simulated drive (no ROS master).
#include <gtest/gtest.h>
#include <xmlrpcpp/XmlRpcValue.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "pioneer_ros/body_velocity_controller.h"
#include "pioneer_ros/controller_params.h"

namespace pioneer_ros {
namespace {

using XmlRpc::XmlRpcValue;

// pytest.approx: within `rel` of the expected value (a millionth by default).
#define EXPECT_APPROX_REL(actual, expected, rel) EXPECT_NEAR((actual), (expected), (rel) * std::abs(expected) + 1e-12)
#define EXPECT_APPROX(actual, expected) EXPECT_APPROX_REL(actual, expected, 1e-6)

const char* const kNamespace = "/pioneer_pid_controller";

// pioneer_controller_params.yaml as the parameter server holds it: the build converts the yaml
// into XML-RPC as rosparam and the master do (python3-yaml, xmlrpc.client).
XmlRpcValue shippedParams() {
  std::ifstream file(PIONEER_CONTROLLER_PARAMS_XML);
  std::stringstream text;
  text << file.rdbuf();
  const std::string xml = text.str();
  int offset = static_cast<int>(xml.find("<value>"));
  XmlRpcValue tree;
  if (offset < 0 || !tree.fromXml(xml, &offset) || tree.getType() != XmlRpcValue::TypeStruct)
    throw std::runtime_error(std::string("cannot read ") + PIONEER_CONTROLLER_PARAMS_XML);
  return tree;
}

ControllerConfig shippedConfig() { return configFromParams(shippedParams(), kNamespace); }

BodyVelocityController controller() { return BodyVelocityController(shippedConfig()); }

// A tree with one value at `path` ({"controller_gains", "body", "linear", "p"}).
XmlRpcValue treeWith(const std::vector<std::string>& path, const XmlRpcValue& value) {
  XmlRpcValue tree;
  XmlRpcValue* node = &tree;
  for (const std::string& key : path) node = &(*node)[key];
  *node = value;
  return tree;
}

// {} in yaml.
XmlRpcValue emptyDictionary() {
  int offset = 0;
  return XmlRpcValue("<value><struct></struct></value>", &offset);
}

// The message of the BadParameter the tree gives, or "" when it is accepted.
std::string badParameter(const XmlRpcValue& tree) {
  try {
    configFromParams(tree, kNamespace);
  } catch (const BadParameter& e) {
    return e.what();
  }
  return "";
}

void expectCommand(const std::optional<PlanarVelocity>& output, double linear, double angular) {
  ASSERT_TRUE(output.has_value());
  EXPECT_APPROX(output->linear, linear);
  EXPECT_APPROX(output->angular, angular);
}

void expectStop(const std::optional<PlanarVelocity>& output) {
  ASSERT_TRUE(output.has_value());
  EXPECT_EQ(output->linear, 0.0);
  EXPECT_EQ(output->angular, 0.0);
}

TEST(ControllerParams, ShippedParamsLoadWithTheReportLayout) {
  const ControllerConfig config = shippedConfig();
  for (const AxisConfig* axis : {&config.linear, &config.angular}) {
    EXPECT_GT(axis->p, 0.0);
    EXPECT_GT(axis->i, 0.0);
    EXPECT_GT(axis->d, 0.0);
  }
  const PidGains linear = pidGains(config.linear, config.derivative_filter_time);
  const PidGains angular = pidGains(config.angular, config.derivative_filter_time);
  EXPECT_EQ(std::make_pair(linear.output_min, linear.output_max), std::make_pair(-1.0, 1.0));
  EXPECT_EQ(std::make_pair(angular.output_min, angular.output_max), std::make_pair(-2.0, 2.0));
  EXPECT_EQ(linear.i_clamp, 0.3);
  EXPECT_EQ(angular.i_clamp, 0.6);
  EXPECT_EQ(linear.d_filter_time, 0.05);
  EXPECT_EQ(config.rate, 20.0);
  EXPECT_EQ(config.cmd_timeout, 0.5);
  EXPECT_EQ(config.odom_timeout, 0.5);
}

TEST(ControllerParams, MissingParamsTakeDefaultsAndBadOnesAreNamed) {
  for (const XmlRpcValue& empty : {XmlRpcValue(), treeWith({"controller_gains"}, emptyDictionary())}) {
    const ControllerConfig config = configFromParams(empty, kNamespace);
    EXPECT_EQ(config.linear.p, 0.0);
    EXPECT_EQ(config.linear.feedforward, 1.0);
    EXPECT_EQ(pidGains(config.linear, 0.0).output_max, 1.0);
    EXPECT_EQ(pidGains(config.angular, 0.0).output_max, 2.0);
    EXPECT_EQ(pidGains(config.angular, 0.0).i_clamp, 2.0);  // i_clamp defaults to the limit
  }
  EXPECT_EQ(badParameter(treeWith({"controller_gains", "body", "linear", "p"}, XmlRpcValue("fast"))),
            "/pioneer_pid_controller/controller_gains/body/linear/p: expected a number, got the string 'fast'");
  EXPECT_EQ(badParameter(treeWith({"limits", "angular"}, XmlRpcValue(-1.0))),
            "/pioneer_pid_controller/limits/angular: expected a positive number, got -1");
  EXPECT_EQ(badParameter(treeWith({"rate"}, XmlRpcValue(0))),
            "/pioneer_pid_controller/rate: expected a positive, finite number of Hz, got 0");
}

TEST(ControllerParams, WrongTypesAreErrorsNotDefaults) {
  XmlRpcValue list;
  list.setSize(2);
  list[0] = 1.0;
  list[1] = 2.0;
  EXPECT_EQ(badParameter(treeWith({"feedforward", "linear"}, XmlRpcValue(true))),
            "/pioneer_pid_controller/feedforward/linear: expected a number, got true");
  EXPECT_EQ(badParameter(treeWith({"cmd_timeout"}, XmlRpcValue("0.5"))),
            "/pioneer_pid_controller/cmd_timeout: expected a number, got the string '0.5'");
  EXPECT_EQ(badParameter(treeWith({"limits"}, list)),
            "/pioneer_pid_controller/limits: expected a dictionary, got a list of 2 items");
  EXPECT_EQ(badParameter(treeWith({"controller_gains", "body"}, XmlRpcValue(3))),
            "/pioneer_pid_controller/controller_gains/body: expected a dictionary, got 3");
  EXPECT_EQ(badParameter(treeWith({"derivative_filter_time"}, XmlRpcValue(std::nan("")))),
            "/pioneer_pid_controller/derivative_filter_time: expected a number, got NaN");
  // An int is a number (yaml "rate: 20").
  EXPECT_EQ(configFromParams(treeWith({"rate"}, XmlRpcValue(50)), kNamespace).rate, 50.0);
}

TEST(ControllerParams, RangesAreCheckedWithTheParameterPath) {
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_EQ(badParameter(treeWith({"controller_gains", "body", "angular", "d"}, XmlRpcValue(inf))),
            "/pioneer_pid_controller/controller_gains/body/angular/d: expected a finite gain, got inf");
  EXPECT_EQ(badParameter(treeWith({"controller_gains", "body", "linear", "i_clamp"}, XmlRpcValue(-0.1))),
            "/pioneer_pid_controller/controller_gains/body/linear/i_clamp: expected a number >= 0, got -0.1");
  EXPECT_EQ(badParameter(treeWith({"derivative_filter_time"}, XmlRpcValue(-0.05))),
            "/pioneer_pid_controller/derivative_filter_time: expected seconds >= 0, got -0.05");
  EXPECT_EQ(badParameter(treeWith({"odom_timeout"}, XmlRpcValue(0.0))),
            "/pioneer_pid_controller/odom_timeout: expected a positive number of seconds, got 0");
  // The controller refuses the same configurations when it is given one directly.
  ControllerConfig config;
  config.cmd_timeout = -1.0;
  EXPECT_THROW(BodyVelocityController{config}, std::invalid_argument);
}

TEST(BodyVelocityController, IdleUntilACommandArrives) {
  BodyVelocityController c = controller();
  EXPECT_FALSE(c.update(1.0).has_value());
  EXPECT_EQ(c.mode(), ControllerMode::kIdle);
}

TEST(BodyVelocityController, OpenLoopWithoutOdometryPassesTheCommandThrough) {
  BodyVelocityController c = controller();
  c.setCommand({0.4, -0.3}, 1.0);
  expectCommand(c.update(1.0), 0.4, -0.3);
  EXPECT_EQ(c.mode(), ControllerMode::kOpenLoop);
}

TEST(BodyVelocityController, OutputIsLimitedEvenOpenLoop) {
  BodyVelocityController c = controller();
  c.setCommand({3.0, -9.0}, 1.0);
  expectCommand(c.update(1.0), 1.0, -2.0);
}

TEST(BodyVelocityController, ClosedLoopCorrectsAShortfall) {
  BodyVelocityController c = controller();
  c.setCommand({0.5, 0.0 + 1e-9}, 1.0);
  c.setMeasurement({0.3, 0.0}, 1.0);
  const std::optional<PlanarVelocity> first = c.update(1.0);
  ASSERT_TRUE(first.has_value());
  EXPECT_EQ(c.mode(), ControllerMode::kClosedLoop);
  EXPECT_APPROX(first->linear, 0.5 + 0.5 * 0.2);  // feedforward + p * error on the first step
  c.setMeasurement({0.3, 0.0}, 1.05);
  const std::optional<PlanarVelocity> later = c.update(1.05);
  ASSERT_TRUE(later.has_value());
  EXPECT_GT(later->linear, first->linear);  // the integral adds to it while the shortfall lasts
}

TEST(BodyVelocityController, StaleOdometryFallsBackToOpenLoop) {
  BodyVelocityController c = controller();
  c.setCommand({0.5, 0.2}, 1.0);
  c.setMeasurement({0.3, 0.1}, 1.0);
  c.update(1.0);
  c.setCommand({0.5, 0.2}, 1.6);
  expectCommand(c.update(1.6), 0.5, 0.2);
  EXPECT_EQ(c.mode(), ControllerMode::kOpenLoop);
}

TEST(BodyVelocityController, ZeroCommandStopsAtOnceAndClearsTheIntegral) {
  BodyVelocityController c = controller();
  c.setCommand({0.5, 0.0}, 1.0);
  for (int k = 0; k < 10; ++k) {
    c.setMeasurement({0.2, 0.0}, 1.0 + 0.05 * k);
    c.update(1.0 + 0.05 * k);
  }
  EXPECT_GT(c.linearPid().integral(), 0.0);
  c.setCommand({0.0, 0.0}, 1.5);
  expectStop(c.update(1.5));
  EXPECT_EQ(c.mode(), ControllerMode::kStopped);
  EXPECT_EQ(c.linearPid().integral(), 0.0);
}

TEST(BodyVelocityController, CommandTimeoutSendsOneStopThenGoesQuiet) {
  BodyVelocityController c = controller();
  c.setCommand({0.5, 0.1}, 1.0);
  EXPECT_TRUE(c.update(1.2).has_value());
  expectStop(c.update(1.6));
  EXPECT_EQ(c.mode(), ControllerMode::kIdle);
  EXPECT_FALSE(c.update(1.7).has_value());
}

TEST(BodyVelocityController, ClockJumpingBackResetsEverything) {
  BodyVelocityController c = controller();
  c.setCommand({0.5, 0.1}, 10.0);
  c.setMeasurement({0.4, 0.1}, 10.0);
  c.update(10.0);
  EXPECT_FALSE(c.update(0.5).has_value());  // reset_simulation: the old command is gone
  EXPECT_EQ(c.mode(), ControllerMode::kIdle);
}

TEST(BodyVelocityController, NonFiniteCommandsAreRefused) {
  BodyVelocityController c = controller();
  EXPECT_THROW(c.setCommand({std::nan(""), 0.0}, 1.0), std::invalid_argument);
}

struct Sample {
  double t, velocity;
};

// A drive that reaches efficiency * its command with time constant tau (slip, a weak motor),
// odometry read at the controller's instants. Returns the velocity at each control instant.
std::vector<Sample> simulate(const XmlRpcValue& params, double command, double efficiency, double duration = 3.0,
                             double tau = 0.05, double rate = 20.0, double physics_dt = 0.001) {
  BodyVelocityController c(configFromParams(params, kNamespace));
  double velocity = 0.0, drive_command = 0.0, t = 0.0, next_control = 0.0;
  std::vector<Sample> trace;
  while (t < duration) {
    if (t >= next_control - 1e-9) {
      c.setCommand({command, 0.0}, t);
      c.setMeasurement({velocity, 0.0}, t);
      const std::optional<PlanarVelocity> out = c.update(t);
      drive_command = out ? out->linear : 0.0;
      trace.push_back({t, velocity});
      next_control += 1.0 / rate;
    }
    velocity += (efficiency * drive_command - velocity) * physics_dt / tau;
    t += physics_dt;
  }
  return trace;
}

double peak(const std::vector<Sample>& trace) {
  return std::max_element(trace.begin(), trace.end(), [](const Sample& a, const Sample& b) {
           return a.velocity < b.velocity;
         })->velocity;
}

TEST(ShippedGains, RemoveA20PercentShortfallWithoutOvershoot) {
  const std::vector<Sample> trace = simulate(shippedParams(), 0.5, 0.8);
  EXPECT_APPROX_REL(trace.back().velocity, 0.5, 0.02);
  EXPECT_LT(peak(trace), 0.5 * 1.05);
  const auto settled = std::find_if(trace.begin(), trace.end(),
                                    [](const Sample& s) { return std::abs(s.velocity - 0.5) < 0.02 * 0.5; });
  ASSERT_NE(settled, trace.end());
  EXPECT_LT(settled->t, 2.0);
  // Feedforward alone would stay 20 % short:
  const std::vector<Sample> open_loop = simulate(treeWith({"controller_gains"}, emptyDictionary()), 0.5, 0.8);
  EXPECT_APPROX_REL(open_loop.back().velocity, 0.4, 0.01);
}

TEST(ShippedGains, DoNotOscillateWithAPerfectDrive) {
  const std::vector<Sample> trace = simulate(shippedParams(), 0.8, 1.0);
  EXPECT_APPROX_REL(trace.back().velocity, 0.8, 0.01);
  EXPECT_LT(peak(trace), 0.8 * 1.05);
}

}  // namespace
}  // namespace pioneer_ros
