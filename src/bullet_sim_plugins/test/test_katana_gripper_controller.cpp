// The Katana gripper's controller (katana_gripper_controller.h) and parameters
// (katana_gripper_config.h): the PID and its clamps, the goal range, when a goal is reached or
// stalled, and the errors a user sees.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>

#include "bullet_sim_core/description_error.h"
#include "bullet_sim_core/urdf_parser.h"
#include "bullet_sim_plugins/katana_gripper_config.h"
#include "bullet_sim_plugins/katana_gripper_controller.h"
#include "bullet_sim_core/testing/error_of.h"

namespace bullet_sim {
namespace {

using Pair = KatanaGripperController::Pair;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// --- the PID -------------------------------------------------------------------------------------

TEST(ClampedPid, IsProportionalPlusIntegralMinusDampingOnVelocity) {
  ClampedPid pid(0.4, 0.1, 0.2, 0.5);
  // First step: p * e + i * e * dt - d * v.
  EXPECT_NEAR(pid.update(0.5, 0.1, 0.01), 0.4 * 0.5 + 0.1 * 0.005 - 0.02, 1e-12);
  EXPECT_NEAR(pid.update(0.5, 0.0, 0.01), 0.4 * 0.5 + 0.1 * 0.01, 1e-12);  // the integral adds up
  pid.reset();
  EXPECT_NEAR(pid.update(-0.2, 0.0, 0.01), -0.08 - 0.1 * 0.002, 1e-12);
}

TEST(ClampedPid, OutputStaysWithinPlusMinusTheLimitAndReachesIt) {
  ClampedPid pid(0.4, 0.1, 0.0, 0.5);
  EXPECT_DOUBLE_EQ(pid.update(10.0, 0.0, 0.001), 0.5);  // 4 N m asked, 0.5 given
  pid.reset();
  EXPECT_DOUBLE_EQ(pid.update(-10.0, 0.0, 0.001), -0.5);
  pid.reset();
  const double just_below = pid.update(1.2, 0.0, 0.0);  // 0.48: not clamped
  EXPECT_GT(just_below, 0.47);
  EXPECT_LT(just_below, 0.5);
}

TEST(ClampedPid, TheIntegralsShareIsBoundedByTheLimit) {
  ClampedPid pid(0.4, 0.1, 0.0, 0.5);
  for (int i = 0; i < 100000; ++i) pid.update(-0.3, 0.0, 0.001);  // 100 s pressed on an object
  EXPECT_DOUBLE_EQ(pid.update(-0.3, 0.0, 0.001), -0.5);
  // Unbounded, the integral's share would be -3 N m and an error of +0.7 (p share 0.28) would
  // take (3 - 0.28) / 0.07 = 39 s to turn the command; bounded at -0.5, (0.5 - 0.28) / 0.07 = 3.1 s.
  double out = -1.0;
  int steps = 0;
  while (out <= 0.0 && steps < 100000) {
    out = pid.update(0.7, 0.0, 0.001);
    ++steps;
  }
  EXPECT_GE(steps, 3000);
  EXPECT_LE(steps, 3300);
}

TEST(KatanaGripperController, ANewGoalStartsTheIntegralAfreshSoSqueezedFingersOpenAtOnce) {
  KatanaGripperController c(KatanaGripperOptions(), {0.3, 0.3});
  c.startGoal(-0.44, 0.0, {0.3, 0.3});
  for (int i = 0; i < 100000; ++i) c.efforts({-0.1, -0.1}, {0.0, 0.0}, 0.001);  // 100 s on a can
  c.startGoal(0.3, 100.0, {-0.1, -0.1});
  const Pair e = c.efforts({-0.1, -0.1}, {0.0, 0.0}, 0.001);
  for (const double effort : e) {
    EXPECT_GT(effort, 0.4 * 0.4 - 1e-9);  // p * 0.4 rad, and nothing left of the squeeze
    EXPECT_LT(effort, 0.4 * 0.4 + 1e-3);
  }
}

// --- options and the goal range ------------------------------------------------------------------

TEST(KatanaGripperOptions, DefaultsAreUpstreamsAndValid) {
  const KatanaGripperOptions o;
  EXPECT_EQ(validate(o), "");
  EXPECT_DOUBLE_EQ(o.max_torque, 0.5);
  EXPECT_DOUBLE_EQ(o.p_gain, 0.4);
  EXPECT_DOUBLE_EQ(o.i_gain, 0.1);
  EXPECT_DOUBLE_EQ(o.d_gain, 0.0);
  EXPECT_DOUBLE_EQ(o.goal_threshold, 0.01);
  EXPECT_DOUBLE_EQ(o.goal_timeout, 3.0);
}

TEST(KatanaGripperOptions, ValidateNamesEveryBadField) {
  KatanaGripperOptions o;
  o.max_torque = 0.0;
  o.i_gain = -1.0;
  o.min_position = 0.5;
  o.goal_timeout = kNaN;
  EXPECT_EQ(validate(o),
            "max_torque: expected a torque > 0 (N m), got 0; p, i, d: expected gains >= 0, got 0.4, -1, 0; gripper "
            "range: expected min < max, got [0.5, 0.3]; goal_timeout: expected a time > 0 (s), got nan");
}

TEST(CheckGoalPosition, AcceptsTheRangeWithItsEndsAndRefusesOutsideNamingIt) {
  const KatanaGripperOptions o;
  for (const double p : {-0.44, -0.2, 0.0, 0.30}) EXPECT_EQ(checkGoalPosition(p, o), "") << p;
  EXPECT_EQ(checkGoalPosition(0.5, o), "Goal position (0.5) outside gripper range [-0.44, 0.3].");
  EXPECT_EQ(checkGoalPosition(-0.4401, o), "Goal position (-0.4401) outside gripper range [-0.44, 0.3].");
  EXPECT_NE(checkGoalPosition(0.3001, o), "");
  EXPECT_NE(checkGoalPosition(kNaN, o), "");
  EXPECT_NE(checkGoalPosition(std::numeric_limits<double>::infinity(), o), "");
}

// --- the controller ------------------------------------------------------------------------------

TEST(KatanaGripperController, HoldsEachFingerWhereItStartsUntilAGoal) {
  KatanaGripperController c(KatanaGripperOptions(), {0.1, -0.2});
  EXPECT_EQ(c.targets(), (Pair{0.1, -0.2}));
  const Pair at_rest = c.efforts({0.1, -0.2}, {0.0, 0.0}, 0.001);
  EXPECT_DOUBLE_EQ(at_rest[0], 0.0);
  EXPECT_DOUBLE_EQ(at_rest[1], 0.0);
  const Pair pushed = c.efforts({0.15, -0.25}, {0.0, 0.0}, 0.001);  // pushed apart: pulled back
  EXPECT_LT(pushed[0], 0.0);
  EXPECT_GT(pushed[1], 0.0);
  EXPECT_FALSE(c.goalActive());
  EXPECT_EQ(c.judge(1.0, {0.1, -0.2}, {0.0, 0.0}), GraspOutcome::Running);  // nothing to judge
}

TEST(KatanaGripperController, AGoalDrivesBothFingersToOneTargetWithinTheClamp) {
  KatanaGripperOptions o;
  o.max_torque = 0.2;
  KatanaGripperController c(o, {0.0, 0.0});
  c.startGoal(-0.44, 0.0, {0.3, 0.0});
  EXPECT_EQ(c.targets(), (Pair{-0.44, -0.44}));
  const Pair e = c.efforts({0.3, 0.0}, {0.0, 0.0}, 0.001);
  EXPECT_DOUBLE_EQ(e[0], -0.2);  // 0.4 * -0.74 clamped
  EXPECT_LT(e[1], -0.17);        // 0.4 * -0.44 = -0.176
  EXPECT_GT(e[1], -0.2);
}

TEST(KatanaGripperController, TheSetpointMovesFromTheFingersToTheTargetAtMaxVelocity) {
  KatanaGripperOptions o;
  o.max_velocity = 1.0;
  KatanaGripperController c(o, {0.0, 0.0});
  c.startGoal(-0.44, 0.0, {0.3, 0.28});
  EXPECT_EQ(c.setpoints(), (Pair{0.3, 0.28}));  // from where the fingers are, not the last target
  const Pair e = c.efforts({0.3, 0.28}, {0.0, 0.0}, 0.01);
  EXPECT_NEAR(c.setpoints()[0], 0.29, 1e-12);
  EXPECT_NEAR(c.setpoints()[1], 0.27, 1e-12);
  EXPECT_NEAR(e[0], 0.4 * -0.01 + 0.1 * -0.01 * 0.01, 1e-12);  // a small pull, not 0.4 * -0.74
  for (int i = 0; i < 72; ++i) c.efforts({0.3, 0.28}, {0.0, 0.0}, 0.01);
  EXPECT_NEAR(c.setpoints()[0], -0.43, 1e-9);
  for (int i = 0; i < 5; ++i) c.efforts({0.3, 0.28}, {0.0, 0.0}, 0.01);
  EXPECT_EQ(c.setpoints(), (Pair{-0.44, -0.44}));  // and stops there
}

// Runs judge() with the fingers at `q` moving at `v` from t to t_end in 1 ms steps; the outcome
// and when it came (t_end if none).
std::pair<GraspOutcome, double> judgeFor(KatanaGripperController& c, double t, double t_end, const Pair& q,
                                         const Pair& v) {
  for (; t < t_end - 1e-9; t += 0.001) {
    const GraspOutcome o = c.judge(t, q, v);
    if (o != GraspOutcome::Running) return {o, t};
  }
  return {GraspOutcome::Running, t_end};
}

TEST(KatanaGripperController, ReachedOnceTheFingersStayStillWithinTheThresholdForSettleTime) {
  KatanaGripperController c(KatanaGripperOptions(), {0.0, 0.0});  // settle_time 0.05 s
  c.startGoal(0.30, 10.0, {0.0, 0.0});
  EXPECT_EQ(judgeFor(c, 10.0, 10.2, {0.2, 0.2}, {1.0, 1.0}).first, GraspOutcome::Running);      // on the way
  EXPECT_EQ(judgeFor(c, 10.2, 10.3, {0.295, 0.295}, {0.5, 0.5}).first, GraspOutcome::Running);  // within, moving
  // A bounce's turning point is still for an instant only.
  EXPECT_EQ(c.judge(10.3, {0.295, 0.295}, {0.0, 0.0}), GraspOutcome::Running);
  EXPECT_EQ(c.judge(10.301, {0.296, 0.296}, {0.2, 0.2}), GraspOutcome::Running);
  const auto [outcome, at] = judgeFor(c, 10.4, 11.0, {0.295, 0.2951}, {0.0, 0.01});
  EXPECT_EQ(outcome, GraspOutcome::Reached);
  EXPECT_GE(at, 10.45 - 1e-6);
  EXPECT_LE(at, 10.452);
  EXPECT_FALSE(c.goalActive());
  EXPECT_EQ(c.judge(11.0, {0.3, 0.3}, {0.0, 0.0}), GraspOutcome::Running);  // once only
}

TEST(KatanaGripperController, TheThresholdIsInclusiveAndOnTheMeanAngle) {
  KatanaGripperOptions o;
  o.settle_time = 0.0;
  KatanaGripperController c(o, {0.0, 0.0});
  c.startGoal(0.0, 0.0, {0.0, 0.0});
  EXPECT_EQ(c.judge(0.001, {0.0125, -0.0125}, {0.0, 0.0}), GraspOutcome::Reached);  // mean 0
  c.startGoal(0.0, 1.0, {0.0, 0.0});
  EXPECT_EQ(c.judge(1.001, {0.0099, 0.0099}, {0.0, 0.0}), GraspOutcome::Reached);
  c.startGoal(0.0, 2.0, {0.0, 0.0});
  EXPECT_EQ(c.judge(2.001, {0.0102, 0.0102}, {0.0, 0.0}), GraspOutcome::Running);  // just outside, still
}

TEST(KatanaGripperController, StalledWhenStillOutsideTheThresholdForStallTime) {
  KatanaGripperController c(KatanaGripperOptions(), {0.3, 0.3});  // stall_time 0.25 s, stall_velocity 0.05
  c.startGoal(-0.44, 5.0, {0.3, 0.3});
  // Closing, then pressing on a can at -0.1 rad: still, but far from the target.
  EXPECT_EQ(judgeFor(c, 5.0, 5.2, {0.0, 0.0}, {-2.0, -2.0}).first, GraspOutcome::Running);
  const auto [outcome, at] = judgeFor(c, 5.2, 9.0, {-0.1, -0.1}, {0.001, -0.04});
  EXPECT_EQ(outcome, GraspOutcome::Stalled);
  EXPECT_GE(at - 5.2, 0.25 - 1e-6);
  EXPECT_LE(at - 5.2, 0.25 + 0.002);
}

TEST(KatanaGripperController, OneMovingFingerKeepsTheGoalGoingAndMotionRestartsTheStallClock) {
  KatanaGripperController c(KatanaGripperOptions(), {0.0, 0.0});
  c.startGoal(-0.44, 0.0, {0.0, 0.0});
  EXPECT_EQ(c.judge(0.0, {-0.1, -0.1}, {0.0, 0.0}), GraspOutcome::Running);
  EXPECT_EQ(c.judge(0.2, {-0.1, -0.1}, {0.0, 0.0}), GraspOutcome::Running);
  EXPECT_EQ(c.judge(0.21, {-0.1, -0.12}, {0.0, -0.5}), GraspOutcome::Running);  // the l finger moves on
  EXPECT_EQ(c.judge(0.4, {-0.1, -0.2}, {0.0, 0.0}), GraspOutcome::Running);     // still again from 0.4
  EXPECT_EQ(c.judge(0.64, {-0.1, -0.2}, {0.0, 0.0}), GraspOutcome::Running);
  EXPECT_EQ(c.judge(0.65, {-0.1, -0.2}, {0.0, 0.0}), GraspOutcome::Stalled);
}

TEST(KatanaGripperController, AtTheTimeoutTheAngleDecidesAsUpstream) {
  KatanaGripperController moving(KatanaGripperOptions(), {0.0, 0.0});
  moving.startGoal(0.1, 1.0, {0.0, 0.0});
  EXPECT_EQ(moving.judge(3.99, {0.095, 0.095}, {0.3, -0.3}), GraspOutcome::Running);  // within, oscillating
  EXPECT_EQ(moving.judge(4.0, {0.095, 0.095}, {0.3, -0.3}), GraspOutcome::Reached);   // 3 s of sim time
  KatanaGripperController short_of_it(KatanaGripperOptions(), {0.0, 0.0});
  short_of_it.startGoal(0.1, 1.0, {0.0, 0.0});
  EXPECT_EQ(short_of_it.judge(3.99, {0.05, 0.05}, {0.3, -0.3}), GraspOutcome::Running);
  EXPECT_EQ(short_of_it.judge(4.0, {0.05, 0.05}, {0.3, -0.3}), GraspOutcome::Stalled);
}

TEST(KatanaGripperController, ANewGoalRestartsTheClocksAndHoldEndsTheGoal) {
  KatanaGripperController c(KatanaGripperOptions(), {0.0, 0.0});
  c.startGoal(0.3, 0.0, {0.0, 0.0});
  EXPECT_EQ(c.judge(2.9, {0.1, 0.1}, {1.0, 1.0}), GraspOutcome::Running);
  c.startGoal(-0.3, 2.9, {0.1, 0.1});  // preempts: 3 s from now
  EXPECT_EQ(c.judge(3.5, {0.0, 0.0}, {-1.0, -1.0}), GraspOutcome::Running);
  EXPECT_EQ(c.judge(5.9, {-0.1, -0.1}, {-1.0, -1.0}), GraspOutcome::Stalled);
  c.startGoal(0.2, 6.0, {-0.1, -0.1});
  c.hold({0.05, 0.06});
  EXPECT_FALSE(c.goalActive());
  EXPECT_EQ(c.targets(), (Pair{0.05, 0.06}));
  EXPECT_EQ(c.setpoints(), (Pair{0.05, 0.06}));
  EXPECT_EQ(c.judge(10.0, {0.05, 0.06}, {0.0, 0.0}), GraspOutcome::Running);
}

// One Katana finger on its own: 6.5e-5 kg m^2 about the hinge, 0.005 N m s/rad damping, the
// default gains; from open to closed. The peak speed and the time taken.
struct Swing {
  GraspOutcome outcome = GraspOutcome::Running;
  double took = 0.0, fastest = 0.0, lowest = 0.0, final_position = 0.0, largest_effort = 0.0;
};
Swing swingShut(const KatanaGripperOptions& o) {
  KatanaGripperController c(o, {0.3, 0.3});
  c.startGoal(-0.44, 0.0, {0.3, 0.3});
  const double inertia = 6.5e-5, damping = 0.005, dt = 0.001;
  Pair q{0.3, 0.3}, v{0.0, 0.0};
  Swing s;
  s.lowest = q[0];
  double t = 0.0;
  for (; s.outcome == GraspOutcome::Running && t < 5.0; t += dt) {
    const Pair e = c.efforts(q, v, dt);
    for (size_t f = 0; f < 2; ++f) {
      s.largest_effort = std::max(s.largest_effort, std::abs(e[f]));
      v[f] += (e[f] - damping * v[f]) / inertia * dt;
      q[f] += v[f] * dt;
    }
    s.lowest = std::min(s.lowest, q[0]);
    s.fastest = std::max(s.fastest, std::abs(v[0]));
    s.outcome = c.judge(t + dt, q, v);
  }
  s.took = t;
  s.final_position = q[0];
  return s;
}

TEST(KatanaGripperController, AKatanaFingerSwingsShutAtTheVelocityLimitAndSettlesWithinTheClamp) {
  KatanaGripperOptions o;
  o.max_velocity = 1.0;
  const Swing s = swingShut(o);
  EXPECT_EQ(s.outcome, GraspOutcome::Reached);
  EXPECT_GT(s.took, 0.74);  // 0.74 rad at 1 rad/s
  EXPECT_LT(s.took, 1.2);   // well before upstream's fixed 3 s
  EXPECT_NEAR(s.final_position, -0.44, o.goal_threshold);
  EXPECT_GT(s.fastest, 0.9);
  EXPECT_LT(s.fastest, 1.25);  // the PID catching up with the setpoint at the start
  EXPECT_GT(s.lowest, -0.44 - 0.01);  // hardly past the target
  EXPECT_LE(s.largest_effort, o.max_torque);
  // Without the ramp (upstream's jump) the same finger swings at about 20 rad/s.
  const Swing jump = swingShut(KatanaGripperOptions());
  EXPECT_GT(jump.fastest, 10.0);
  EXPECT_LE(jump.largest_effort, o.max_torque);
}

// --- the parameters ------------------------------------------------------------------------------

ModelDescription katanaWith(const std::string& plugin, const std::string& l_velocity = "1") {
  std::string urdf = "<robot name='katana'><link name='palm'/><link name='r'/><link name='l'/>";
  for (const std::string side : {"r", "l"})
    urdf += "<joint name='katana_" + side + "_finger_joint' type='revolute'><parent link='palm'/><child link='" + side +
            "'/><axis xyz='0 0 1'/><limit lower='-0.44' upper='0.3' effort='0.5' velocity='" +
            (side == "l" ? l_velocity : std::string("1")) + "'/></joint>";
  urdf += "<link name='tool'/><joint name='tool_joint' type='fixed'><parent link='palm'/><child link='tool'/></joint>";
  urdf += "<gazebo><plugin name='gazebo_ros_katana_gripper' filename='libgazebo_ros_katana_gripper.so'>" + plugin +
          "</plugin></gazebo></robot>";
  return parseUrdf(urdf, "katana.urdf", ResourceResolver(), "");
}

KatanaGripperConfig configOf(const std::string& plugin) {
  const ModelDescription m = katanaWith(plugin);
  return parseKatanaGripperConfig(m.plugins.at(0), m);
}

std::string errorOf(const std::string& plugin) { return bullet_sim::errorOf([&] { configOf(plugin); }); }

const std::string kAt = "katana.urdf: <gazebo>/<plugin name='gazebo_ros_katana_gripper' "
                        "filename='libgazebo_ros_katana_gripper.so'>";

TEST(KatanaGripperConfig, DefaultsAreUpstreamsWithTheLFingerOnItsOwnJoint) {
  const KatanaGripperConfig c = configOf("");
  EXPECT_EQ(c.r_finger_joint, "katana_r_finger_joint");
  EXPECT_EQ(c.l_finger_joint, "katana_l_finger_joint");  // upstream falls back to the r finger
  EXPECT_EQ(c.node_namespace, "katana");
  EXPECT_DOUBLE_EQ(c.options.max_torque, 0.5);
  EXPECT_DOUBLE_EQ(c.options.max_velocity, 1.0);  // the finger joints' <limit velocity>
}

TEST(KatanaGripperConfig, ReadsEveryParameter) {
  const KatanaGripperConfig c = configOf(
      "<r_finger_joint>katana_l_finger_joint</r_finger_joint><l_finger_joint>katana_r_finger_joint</l_finger_joint>"
      "<max_torque>0.25</max_torque><node_namespace>arm</node_namespace>");
  EXPECT_EQ(c.r_finger_joint, "katana_l_finger_joint");
  EXPECT_EQ(c.l_finger_joint, "katana_r_finger_joint");
  EXPECT_DOUBLE_EQ(c.options.max_torque, 0.25);
  EXPECT_EQ(c.node_namespace, "arm");
}

TEST(KatanaGripperConfig, AMissingJointIsAnErrorNamingTheElementAndTheJoint) {
  EXPECT_EQ(errorOf("<r_finger_joint>finger_r</r_finger_joint>"),
            kAt + "/<r_finger_joint>: model 'katana' has no joint 'finger_r'");
  EXPECT_EQ(errorOf("<l_finger_joint>tool_joint</l_finger_joint>"),
            kAt + "/<l_finger_joint>: expected a revolute, continuous or prismatic joint of model 'katana', got "
                  "'tool_joint' (a fixed joint)");
  EXPECT_EQ(errorOf("<l_finger_joint> </l_finger_joint>"), kAt + "/<l_finger_joint>: expected a name, got ''");
  EXPECT_EQ(errorOf("<l_finger_joint>katana_r_finger_joint</l_finger_joint>"),
            kAt + "/<l_finger_joint>: expected a joint other than <r_finger_joint> ('katana_r_finger_joint')");
}

TEST(KatanaGripperConfig, ADefaultJointTheModelLacksSaysItIsTheDefault) {
  const ModelDescription m = parseUrdf(
      "<robot name='box'><link name='body'/><gazebo><plugin name='g' filename='libgazebo_ros_katana_gripper.so'/>"
      "</gazebo></robot>",
      "box.urdf", ResourceResolver(), "");
  try {
    parseKatanaGripperConfig(m.plugins.at(0), m);
    FAIL() << "expected a DescriptionError";
  } catch (const DescriptionError& e) {
    EXPECT_EQ(std::string(e.what()),
              "box.urdf: <gazebo>/<plugin name='g' filename='libgazebo_ros_katana_gripper.so'>/<r_finger_joint>: model "
              "'box' has no joint 'katana_r_finger_joint' (the default, as <r_finger_joint> is missing)");
  }
}

TEST(KatanaGripperConfig, TheSetpointMovesAtTheSlowerFingersVelocityLimitOrJumpsWithoutOne) {
  const ModelDescription slow_l = katanaWith("", "0.5");
  EXPECT_DOUBLE_EQ(parseKatanaGripperConfig(slow_l.plugins.at(0), slow_l).options.max_velocity, 0.5);
  const ModelDescription fast_l = katanaWith("", "3");
  EXPECT_DOUBLE_EQ(parseKatanaGripperConfig(fast_l.plugins.at(0), fast_l).options.max_velocity, 1.0);
  const ModelDescription r_only_unlimited = katanaWith("<r_finger_joint>katana_l_finger_joint</r_finger_joint>"
                                                       "<l_finger_joint>katana_r_finger_joint</l_finger_joint>", "0");
  EXPECT_DOUBLE_EQ(
      parseKatanaGripperConfig(r_only_unlimited.plugins.at(0), r_only_unlimited).options.max_velocity, 1.0);
  const ModelDescription none = parseUrdf(
      "<robot name='g'><link name='p'/><link name='a'/><link name='b'/><joint name='a_joint' type='continuous'>"
      "<parent link='p'/><child link='a'/></joint><joint name='b_joint' type='continuous'><parent link='p'/>"
      "<child link='b'/></joint><gazebo><plugin name='g' filename='libgazebo_ros_katana_gripper.so'><r_finger_joint>"
      "a_joint</r_finger_joint><l_finger_joint>b_joint</l_finger_joint></plugin></gazebo></robot>",
      "g.urdf", ResourceResolver(), "");
  EXPECT_TRUE(std::isinf(parseKatanaGripperConfig(none.plugins.at(0), none).options.max_velocity));
}

TEST(KatanaGripperConfig, MaxTorqueMustBePositive) {
  EXPECT_EQ(errorOf("<max_torque>0</max_torque>"), kAt + "/<max_torque>: expected a number > 0, got '0'");
  EXPECT_EQ(errorOf("<max_torque>strong</max_torque>"), kAt + "/<max_torque>: expected a number > 0, got 'strong'");
}

}  // namespace
}  // namespace bullet_sim
