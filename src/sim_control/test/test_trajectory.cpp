// The ROS-free part of the JointTrajectoryController: spline segments, merging commands into the
// current trajectory (ros_controllers' semantics), and tolerance checks.
#include <gtest/gtest.h>

#include <cmath>

#include "sim_control/trajectory.h"

using namespace sim_control::trajectory;

namespace {

constexpr double kEps = 1e-9;
constexpr double kPi = 3.14159265358979323846;

Waypoint point(double t, std::vector<double> p, std::vector<double> v = {}, std::vector<double> a = {}) {
  Waypoint w;
  w.time_from_start = t;
  w.positions = std::move(p);
  w.velocities = std::move(v);
  w.accelerations = std::move(a);
  return w;
}

State sampleAt(const JointTrajectory& trajectory, double t) {
  State s;
  sample(trajectory, t, s);
  return s;
}

// A controller holding every joint at `positions` since time 0.
Trajectory holding(const std::vector<double>& positions) {
  Trajectory t;
  for (double p : positions) t.push_back(holdTrajectory(0.0, p));
  return t;
}

MergeOptions options(const std::vector<std::string>& joints, int goal_id = 0) {
  MergeOptions o;
  o.joints = joints;
  o.goal_id = goal_id;
  return o;
}

// Checks position (and up to `derivatives` derivatives) are continuous at `t`.
void expectContinuousAt(const JointTrajectory& trajectory, double t, int derivatives, double tol = 1e-5) {
  const State before = sampleAt(trajectory, t - 1e-7), after = sampleAt(trajectory, t + 1e-7);
  EXPECT_NEAR(before.position, after.position, tol) << "position jumps at t = " << t;
  if (derivatives >= 1) {
    EXPECT_NEAR(before.velocity, after.velocity, tol) << "velocity jumps at t = " << t;
  }
  if (derivatives >= 2) {
    EXPECT_NEAR(before.acceleration, after.acceleration, tol) << "acceleration jumps at t = " << t;
  }
}

}  // namespace

// ---------------------------------------------------------------------------------------------
// Segments

TEST(Segment, LinearInterpolatesPositions) {
  const Segment s(1.0, {0.0, 5.0, 5.0}, 3.0, {4.0, 7.0, 7.0}, Order::Linear);  // velocities ignored
  const State mid = s.sample(2.0);
  EXPECT_NEAR(mid.position, 2.0, kEps);
  EXPECT_NEAR(mid.velocity, 2.0, kEps);
  EXPECT_NEAR(mid.acceleration, 0.0, kEps);
  EXPECT_NEAR(s.sample(1.0).position, 0.0, kEps);
  EXPECT_NEAR(s.sample(3.0).position, 4.0, kEps);
}

TEST(Segment, CubicMeetsPositionsAndVelocities) {
  const State a{1.0, -2.0, 0.0}, b{-3.0, 0.5, 0.0};
  const Segment s(0.5, a, 2.0, b, Order::Cubic);
  EXPECT_NEAR(s.sample(0.5).position, a.position, kEps);
  EXPECT_NEAR(s.sample(0.5).velocity, a.velocity, kEps);
  EXPECT_NEAR(s.sample(2.0).position, b.position, 1e-9);
  EXPECT_NEAR(s.sample(2.0).velocity, b.velocity, 1e-9);
}

TEST(Segment, QuinticMeetsPositionsVelocitiesAndAccelerations) {
  const State a{0.3, 1.0, -4.0}, b{2.0, -0.5, 3.0};
  const Segment s(10.0, a, 11.5, b, Order::Quintic);
  const State start = s.sample(10.0), end = s.sample(11.5);
  EXPECT_NEAR(start.position, a.position, kEps);
  EXPECT_NEAR(start.velocity, a.velocity, kEps);
  EXPECT_NEAR(start.acceleration, a.acceleration, kEps);
  EXPECT_NEAR(end.position, b.position, 1e-9);
  EXPECT_NEAR(end.velocity, b.velocity, 1e-9);
  EXPECT_NEAR(end.acceleration, b.acceleration, 1e-8);
  // The derivatives are those of the position: finite differences agree.
  const double h = 1e-6, t = 10.7;
  EXPECT_NEAR((s.sample(t + h).position - s.sample(t - h).position) / (2 * h), s.sample(t).velocity, 1e-5);
  EXPECT_NEAR((s.sample(t + h).velocity - s.sample(t - h).velocity) / (2 * h), s.sample(t).acceleration, 1e-5);
}

TEST(Segment, OutsideItsTimeHoldsTheEndsAtRest) {
  const Segment s(1.0, {0.0, 1.0, 0.0}, 2.0, {1.0, 1.0, 0.0}, Order::Cubic);
  const State before = s.sample(0.0), after = s.sample(5.0);
  EXPECT_NEAR(before.position, 0.0, kEps);
  EXPECT_EQ(before.velocity, 0.0);
  EXPECT_NEAR(after.position, 1.0, kEps);
  EXPECT_EQ(after.velocity, 0.0);
  EXPECT_EQ(after.acceleration, 0.0);
}

TEST(Segment, FindSegmentTakesTheLastStartedOne) {
  JointTrajectory t = {Segment(0.0, {}, 1.0, {}, Order::Linear), Segment(1.0, {}, 2.0, {}, Order::Linear),
                       Segment(2.0, {}, 3.0, {}, Order::Linear)};
  EXPECT_EQ(findSegment(t, -0.1), -1);
  EXPECT_EQ(findSegment(t, 0.0), 0);
  EXPECT_EQ(findSegment(t, 0.99), 0);
  EXPECT_EQ(findSegment(t, 1.0), 1);
  EXPECT_EQ(findSegment(t, 2.5), 2);
  EXPECT_EQ(findSegment(t, 100.0), 2);
  EXPECT_EQ(findSegment({}, 1.0), -1);
}

// ---------------------------------------------------------------------------------------------
// Sampling merged trajectories: linear / cubic / quintic continuity, hold after the end

TEST(Sampling, PositionsOnlyIsLinearAndContinuousInPosition) {
  Command c;
  c.joint_names = {"j"};
  c.points = {point(1.0, {1.0}), point(2.0, {3.0}), point(4.0, {2.0})};
  const MergeResult r = merge(holding({0.0}), c, 0.0, 0.0, options({"j"}));
  ASSERT_EQ(r.error_code, kSuccessful) << r.error;
  const JointTrajectory& t = r.trajectory[0];
  EXPECT_NEAR(sampleAt(t, 0.5).position, 0.5, kEps);  // bridge from the hold at 0 to the first point
  EXPECT_NEAR(sampleAt(t, 1.0).position, 1.0, kEps);
  EXPECT_NEAR(sampleAt(t, 1.5).position, 2.0, kEps);
  EXPECT_NEAR(sampleAt(t, 1.5).velocity, 2.0, kEps);
  EXPECT_NEAR(sampleAt(t, 3.0).position, 2.5, kEps);
  EXPECT_NEAR(sampleAt(t, 3.0).velocity, -0.5, kEps);
  for (double w : {1.0, 2.0, 4.0}) expectContinuousAt(t, w, 0);
}

TEST(Sampling, VelocitiesMakeItCubicAndContinuousInVelocity) {
  Command c;
  c.joint_names = {"a", "b"};
  c.points = {point(1.0, {1.0, -1.0}, {0.5, 0.0}), point(2.0, {2.0, 0.0}, {1.0, 2.0}),
              point(3.5, {0.0, 1.0}, {0.0, 0.0})};
  const MergeResult r = merge(holding({0.0, 0.0}), c, 0.0, 0.0, options({"a", "b"}));
  ASSERT_EQ(r.error_code, kSuccessful) << r.error;
  for (std::size_t j = 0; j < 2; ++j) {
    const JointTrajectory& t = r.trajectory[j];
    for (std::size_t p = 0; p < c.points.size(); ++p) {
      const State s = sampleAt(t, c.points[p].time_from_start);
      EXPECT_NEAR(s.position, c.points[p].positions[j], 1e-9);
      if (p + 1 < c.points.size()) {
        EXPECT_NEAR(s.velocity, c.points[p].velocities[j], 1e-9);
      }
    }
    for (double w : {1.0, 2.0}) expectContinuousAt(t, w, 1);
  }
}

TEST(Sampling, AccelerationsMakeItQuinticAndContinuousInAcceleration) {
  Command c;
  c.joint_names = {"j"};
  c.points = {point(0.5, {0.2}, {0.4}, {0.0}), point(1.5, {1.0}, {0.5}, {-1.0}), point(2.0, {1.2}, {0.0}, {0.5}),
              point(3.0, {1.0}, {0.0}, {0.0})};
  const MergeResult r = merge(holding({0.0}), c, 0.0, 0.0, options({"j"}));
  ASSERT_EQ(r.error_code, kSuccessful) << r.error;
  const JointTrajectory& t = r.trajectory[0];
  for (std::size_t p = 0; p + 1 < c.points.size(); ++p) {
    const State s = sampleAt(t, c.points[p].time_from_start);
    EXPECT_NEAR(s.position, c.points[p].positions[0], 1e-9);
    EXPECT_NEAR(s.velocity, c.points[p].velocities[0], 1e-9);
    EXPECT_NEAR(s.acceleration, c.points[p].accelerations[0], 1e-8);
  }
  for (double w : {0.5, 1.5, 2.0}) expectContinuousAt(t, w, 2, 1e-4);
}

TEST(Sampling, MixedPointsUseTheLowestCommonOrder) {
  Command c;
  c.joint_names = {"j"};
  c.points = {point(1.0, {0.0}, {1.0}), point(2.0, {1.0}), point(3.0, {0.0}, {0.0})};
  const MergeResult r = merge(holding({0.0}), c, 0.0, 0.0, options({"j"}));
  ASSERT_EQ(r.error_code, kSuccessful) << r.error;
  EXPECT_NEAR(sampleAt(r.trajectory[0], 1.5).velocity, 1.0, kEps);  // linear: constant velocity
  EXPECT_NEAR(sampleAt(r.trajectory[0], 2.5).velocity, -1.0, kEps);
}

TEST(Sampling, HoldsTheLastPositionAfterTheEnd) {
  Command c;
  c.joint_names = {"j"};
  c.points = {point(1.0, {2.0}, {1.0}), point(2.0, {3.0}, {0.7})};  // ends still "moving"
  const MergeResult r = merge(holding({0.0}), c, 0.0, 0.0, options({"j"}));
  ASSERT_EQ(r.error_code, kSuccessful) << r.error;
  for (double t : {2.0 + 1e-6, 3.0, 100.0}) {
    const State s = sampleAt(r.trajectory[0], t);
    EXPECT_NEAR(s.position, 3.0, 1e-9);
    EXPECT_EQ(s.velocity, 0.0);
    EXPECT_EQ(s.acceleration, 0.0);
  }
}

TEST(Sampling, HoldTrajectoryStaysPut) {
  const JointTrajectory t = holdTrajectory(2.0, 1.25, 7);
  EXPECT_EQ(t.front().goal_id, 7);
  for (double time : {2.0, 2.5, 50.0}) {
    EXPECT_NEAR(sampleAt(t, time).position, 1.25, kEps);
    EXPECT_EQ(sampleAt(t, time).velocity, 0.0);
  }
}

TEST(Sampling, StopTrajectoryComesToRestInTime) {
  const State from{1.0, 2.0, 0.0};
  const JointTrajectory t = stopTrajectory(3.0, from, 0.5);
  EXPECT_NEAR(sampleAt(t, 3.0).position, 1.0, kEps);
  EXPECT_NEAR(sampleAt(t, 3.0).velocity, 2.0, kEps);
  const State end = sampleAt(t, 3.5);
  EXPECT_NEAR(end.velocity, 0.0, 1e-9);
  EXPECT_GT(end.position, 1.0);  // kept moving forward while braking
  EXPECT_LT(end.position, 1.0 + 2.0 * 0.5);
  EXPECT_NEAR(sampleAt(t, 10.0).position, end.position, 1e-9);
  EXPECT_EQ(sampleAt(t, 10.0).velocity, 0.0);
  for (double s = 3.0; s <= 3.5; s += 0.05) EXPECT_GE(sampleAt(t, s).velocity, -1e-9);  // no reversal
  // Zero duration: hold where it is.
  EXPECT_NEAR(sampleAt(stopTrajectory(3.0, from, 0.0), 4.0).position, 1.0, kEps);
}

// ---------------------------------------------------------------------------------------------
// Merging: dropped points, replacement, partial goals, continuous joints

TEST(Merge, PointsAtOrBeforeNowAreDroppedAndBridgedFromTheCurrentState) {
  Command c;
  c.joint_names = {"j"};
  // Started at 3 (in the past): points at 4 and 5 are not after now = 5.
  c.points = {point(1.0, {10.0}), point(2.0, {20.0}), point(3.0, {30.0}), point(4.0, {40.0})};
  const MergeResult r = merge(holding({1.0}), c, 3.0, 5.0, options({"j"}));
  ASSERT_EQ(r.error_code, kSuccessful) << r.error;
  EXPECT_EQ(r.dropped_points, 2u);
  const JointTrajectory& t = r.trajectory[0];
  EXPECT_NEAR(sampleAt(t, 5.0).position, 1.0, kEps);  // starts from the current state...
  EXPECT_NEAR(sampleAt(t, 5.5).position, 15.5, kEps);  // ...to the first future point
  EXPECT_NEAR(sampleAt(t, 6.0).position, 30.0, kEps);
  EXPECT_NEAR(sampleAt(t, 7.0).position, 40.0, kEps);
}

TEST(Merge, FirstPointAtTimeZeroWithAZeroStampIsDropped) {
  Command c;
  c.joint_names = {"j"};
  c.points = {point(0.0, {5.0}), point(1.0, {1.0})};
  const MergeResult r = merge(holding({0.0}), c, 2.0, 2.0, options({"j"}));
  ASSERT_EQ(r.error_code, kSuccessful) << r.error;
  EXPECT_EQ(r.dropped_points, 1u);
  EXPECT_NEAR(sampleAt(r.trajectory[0], 2.5).position, 0.5, kEps);  // never goes to 5
}

TEST(Merge, AllPointsInThePastIsAnInvalidGoal) {
  Command c;
  c.joint_names = {"j"};
  c.points = {point(1.0, {1.0}), point(2.0, {2.0})};
  const MergeResult r = merge(holding({0.0}), c, 0.0, 2.5, options({"j"}));
  EXPECT_EQ(r.error_code, kInvalidGoal);
  EXPECT_NE(r.error.find("in the past"), std::string::npos) << r.error;
  EXPECT_NE(r.error.find("0.5 s"), std::string::npos) << r.error;
}

TEST(Merge, NewTrajectoryReplacesTheCurrentOneFromItsStartTime) {
  // Current: 0 -> 10 over [0, 10], linear, through a waypoint at 3.
  Command first;
  first.joint_names = {"j"};
  first.points = {point(0.0, {0.0}), point(3.0, {3.0}), point(10.0, {10.0})};
  MergeResult a = merge(holding({0.0}), first, 0.0, -1.0, options({"j"}));
  ASSERT_EQ(a.error_code, kSuccessful) << a.error;

  // At now = 2, a trajectory starting at 4 whose point is -5 at 5.
  Command second;
  second.joint_names = {"j"};
  second.points = {point(1.0, {-5.0}), point(2.0, {-6.0})};
  MergeResult b = merge(a.trajectory, second, 4.0, 2.0, options({"j"}));
  ASSERT_EQ(b.error_code, kSuccessful) << b.error;
  const JointTrajectory& t = b.trajectory[0];
  EXPECT_NEAR(sampleAt(t, 2.0).position, 2.0, kEps);  // what was before the start is kept
  EXPECT_NEAR(sampleAt(t, 3.0).position, 3.0, kEps);
  EXPECT_NEAR(sampleAt(t, 3.5).position, 3.5, kEps);  // past the old waypoint, still the old trajectory
  EXPECT_NEAR(sampleAt(t, 4.0).position, 4.0, kEps);  // continuous at the start
  EXPECT_NEAR(sampleAt(t, 4.5).position, -0.5, kEps);  // bridge 4 -> -5 over [4, 5]
  EXPECT_NEAR(sampleAt(t, 5.0).position, -5.0, kEps);
  EXPECT_NEAR(sampleAt(t, 6.0).position, -6.0, kEps);
  EXPECT_NEAR(sampleAt(t, 9.0).position, -6.0, kEps);  // the rest of the old one is gone
  expectContinuousAt(t, 4.0, 0);

  // Starting now instead: bridges from the current desired state.
  MergeResult c = merge(a.trajectory, second, 2.0, 2.0, options({"j"}));
  ASSERT_EQ(c.error_code, kSuccessful) << c.error;
  EXPECT_NEAR(sampleAt(c.trajectory[0], 2.0).position, 2.0, kEps);
  EXPECT_NEAR(sampleAt(c.trajectory[0], 3.0).position, -5.0, kEps);
}

TEST(Merge, NewSegmentsAndKeptOnesCarryTheGoalId) {
  Command c;
  c.joint_names = {"j"};
  c.points = {point(1.0, {1.0}), point(2.0, {2.0})};
  const MergeResult r = merge(holding({0.0}), c, 1.0, 0.5, options({"j"}, 42));
  ASSERT_EQ(r.error_code, kSuccessful) << r.error;
  for (const Segment& s : r.trajectory[0]) EXPECT_EQ(s.goal_id, 42);
}

TEST(Merge, JointsInAnyOrder) {
  Command c;
  c.joint_names = {"b", "a"};
  c.points = {point(1.0, {2.0, 1.0})};
  const MergeResult r = merge(holding({0.0, 0.0}), c, 0.0, 0.0, options({"a", "b"}));
  ASSERT_EQ(r.error_code, kSuccessful) << r.error;
  EXPECT_NEAR(sampleAt(r.trajectory[0], 1.0).position, 1.0, kEps);
  EXPECT_NEAR(sampleAt(r.trajectory[1], 1.0).position, 2.0, kEps);
}

TEST(Merge, PartialGoalKeepsTheOtherJointsTrajectories) {
  MergeOptions o = options({"a", "b"}, 3);
  o.allow_partial = true;
  Command c;
  c.joint_names = {"b"};
  c.points = {point(1.0, {5.0})};
  const MergeResult r = merge(holding({0.5, 0.0}), c, 0.0, 0.0, o);
  ASSERT_EQ(r.error_code, kSuccessful) << r.error;
  EXPECT_NEAR(sampleAt(r.trajectory[0], 2.0).position, 0.5, kEps);
  EXPECT_EQ(r.trajectory[0].back().goal_id, 3);
  EXPECT_NEAR(sampleAt(r.trajectory[1], 1.0).position, 5.0, kEps);
}

TEST(Merge, ContinuousJointsTakeTheShortWayRound) {
  MergeOptions o = options({"wheel", "arm"});
  o.wraparound = {true, false};
  Command c;
  c.joint_names = {"wheel", "arm"};
  c.points = {point(1.0, {-3.0, -3.0}), point(2.0, {-2.9, -2.9})};
  const MergeResult r = merge(holding({3.0, 3.0}), c, 0.0, 0.0, o);
  ASSERT_EQ(r.error_code, kSuccessful) << r.error;
  EXPECT_NEAR(sampleAt(r.trajectory[0], 0.5).position, (3.0 + (-3.0 + 2 * kPi)) / 2, 1e-9);  // bridge
  EXPECT_NEAR(sampleAt(r.trajectory[0], 1.0).position, -3.0 + 2 * kPi, 1e-9);  // +0.28 rad, not -6
  EXPECT_NEAR(sampleAt(r.trajectory[0], 2.0).position, -2.9 + 2 * kPi, 1e-9);  // offset kept
  EXPECT_NEAR(sampleAt(r.trajectory[1], 0.5).position, 0.0, 1e-9);
  EXPECT_NEAR(sampleAt(r.trajectory[1], 1.0).position, -3.0, 1e-9);
}

TEST(Angles, ShortestAngularDistanceAndWraparoundOffset) {
  EXPECT_NEAR(shortestAngularDistance(0.0, 1.0), 1.0, kEps);
  EXPECT_NEAR(shortestAngularDistance(3.0, -3.0), 2 * kPi - 6.0, kEps);
  EXPECT_NEAR(shortestAngularDistance(-3.0, 3.0), 6.0 - 2 * kPi, kEps);
  EXPECT_NEAR(shortestAngularDistance(0.0, 4 * kPi + 0.1), 0.1, 1e-9);
  EXPECT_NEAR(wraparoundOffset(0.0, 0.5), 0.0, kEps);
  EXPECT_NEAR(wraparoundOffset(3.0, -3.0), 2 * kPi, 1e-9);
  EXPECT_NEAR(wraparoundOffset(10 * kPi, 0.1), 10 * kPi, 1e-9);
}

// ---------------------------------------------------------------------------------------------
// Validation (action result codes)

TEST(Validation, UnknownJointsAreInvalidJoints) {
  Command c;
  c.joint_names = {"a", "x"};
  std::vector<std::size_t> mapping;
  std::string error;
  EXPECT_EQ(validateJoints(c, {"a", "b"}, false, mapping, error), kInvalidJoints);
  EXPECT_NE(error.find("'x'"), std::string::npos) << error;
  EXPECT_NE(error.find("a, b"), std::string::npos) << error;
}

TEST(Validation, MissingJointsNeedAllowPartial) {
  Command c;
  c.joint_names = {"b"};
  std::vector<std::size_t> mapping;
  std::string error;
  EXPECT_EQ(validateJoints(c, {"a", "b", "c"}, false, mapping, error), kInvalidJoints);
  EXPECT_NE(error.find("'a', 'c'"), std::string::npos) << error;
  EXPECT_NE(error.find("allow_partial_joints_goal"), std::string::npos) << error;
  EXPECT_EQ(validateJoints(c, {"a", "b", "c"}, true, mapping, error), kSuccessful);
  ASSERT_EQ(mapping.size(), 1u);
  EXPECT_EQ(mapping[0], 1u);
}

TEST(Validation, RepeatedOrNoJointsAreInvalidJoints) {
  Command c;
  std::vector<std::size_t> mapping;
  std::string error;
  EXPECT_EQ(validateJoints(c, {"a"}, true, mapping, error), kInvalidJoints);
  c.joint_names = {"a", "a"};
  EXPECT_EQ(validateJoints(c, {"a", "b"}, true, mapping, error), kInvalidJoints);
  EXPECT_NE(error.find("more than once"), std::string::npos) << error;
}

TEST(Validation, InconsistentSizesAreInvalidGoals) {
  Command c;
  c.joint_names = {"a", "b"};
  std::string error;
  c.points = {point(1.0, {1.0})};
  EXPECT_EQ(validatePoints(c, error), kInvalidGoal);
  EXPECT_NE(error.find("point 0 has 1 positions; expected 2"), std::string::npos) << error;
  c.points = {point(1.0, {1.0, 2.0}), point(2.0, {1.0, 2.0}, {0.0})};
  EXPECT_EQ(validatePoints(c, error), kInvalidGoal);
  EXPECT_NE(error.find("point 1 has 1 velocities"), std::string::npos) << error;
  c.points = {point(1.0, {1.0, 2.0}, {0.0, 0.0}, {1.0, 2.0, 3.0})};
  EXPECT_EQ(validatePoints(c, error), kInvalidGoal);
  EXPECT_NE(error.find("accelerations"), std::string::npos) << error;
  c.points = {point(1.0, {1.0, NAN})};
  EXPECT_EQ(validatePoints(c, error), kInvalidGoal);
  EXPECT_NE(error.find("joint 'b'"), std::string::npos) << error;
  c.points = {point(1.0, {1.0, 2.0}, {0.0, 0.0}, {0.0, 0.0}), point(2.0, {1.0, 2.0})};
  EXPECT_EQ(validatePoints(c, error), kSuccessful) << error;
}

TEST(Validation, TimesMustIncreaseStrictly) {
  Command c;
  c.joint_names = {"a"};
  std::string error;
  c.points = {point(1.0, {1.0}), point(1.0, {2.0})};
  EXPECT_EQ(validatePoints(c, error), kInvalidGoal);
  EXPECT_NE(error.find("increase strictly"), std::string::npos) << error;
  c.points = {point(2.0, {1.0}), point(1.0, {2.0})};
  EXPECT_EQ(validatePoints(c, error), kInvalidGoal);
  // merge() checks too, before touching anything.
  const MergeResult r = merge(holding({0.0}), c, 0.0, 0.0, options({"a"}));
  EXPECT_EQ(r.error_code, kInvalidGoal);
  EXPECT_TRUE(r.trajectory.empty());
}

// ---------------------------------------------------------------------------------------------
// Tolerances

TEST(Tolerance, ZeroMeansUnchecked) {
  EXPECT_TRUE(withinTolerance({100.0, 100.0, 100.0}, {}));
  EXPECT_TRUE(withinTolerance({0.05, -0.009, 5.0}, {0.1, 0.01, 0.0}));
  std::string why;
  EXPECT_FALSE(withinTolerance({-0.15, 0.0, 0.0}, {0.1, 0.0, 0.0}, &why));
  EXPECT_EQ(why, "position error -0.15 exceeds the tolerance 0.1 by 0.05");
  EXPECT_FALSE(withinTolerance({0.0, 0.02, 0.0}, {0.1, 0.01, 0.0}, &why));
  EXPECT_NE(why.find("velocity error 0.02"), std::string::npos) << why;
  EXPECT_FALSE(withinTolerance({NAN, 0.0, 0.0}, {0.1, 0.0, 0.0}));
}

TEST(Tolerance, GoalOverridesReplaceDisableOrKeepTheDefaults) {
  std::vector<StateTolerance> tol = {{0.1, 0.01, 0.0}, {0.2, 0.01, 0.0}};
  applyOverrides({{"b", 0.5, -1.0, 0.0}, {"nope", 9.0, 9.0, 9.0}, {"a", 0.0, 0.0, 3.0}}, {"a", "b"}, tol);
  EXPECT_EQ(tol[0].position, 0.1);  // 0: default kept
  EXPECT_EQ(tol[0].velocity, 0.01);
  EXPECT_EQ(tol[0].acceleration, 3.0);
  EXPECT_EQ(tol[1].position, 0.5);  // > 0: replaced
  EXPECT_EQ(tol[1].velocity, 0.0);  // < 0: no check
  EXPECT_EQ(applyGoalTimeOverride(0.0, 0.6), 0.6);
  EXPECT_EQ(applyGoalTimeOverride(2.0, 0.6), 2.0);
  EXPECT_EQ(applyGoalTimeOverride(-1.0, 0.6), 0.0);
}

// One joint "j" moving 0 -> 1 over [0, 1] as goal 1.
struct MonitorFixture : ::testing::Test {
  void SetUp() override {
    Command c;
    c.joint_names = {"j"};
    c.points = {point(1.0, {1.0})};
    const MergeResult r = merge(holding({0.0}), c, 0.0, 0.0, options({"j"}, 1));
    ASSERT_EQ(r.error_code, kSuccessful) << r.error;
    trajectory = r.trajectory;
    tolerances.path = {{0.1, 0.0, 0.0}};
    tolerances.goal = {{0.02, 0.01, 0.0}};
    tolerances.goal_time = 0.5;
    monitor.start(1, tolerances, {"j"}, 0.0);
  }
  GoalMonitor::Result at(double t, State error) {
    std::vector<int> segments = {findSegment(trajectory[0], t)};
    return monitor.check(t, trajectory, segments, {error});
  }
  Trajectory trajectory;
  Tolerances tolerances;
  GoalMonitor monitor;
};

TEST_F(MonitorFixture, PathToleranceViolationAbortsNamingTheJoint) {
  EXPECT_FALSE(at(0.2, {0.05, 0.3, 0.0}).done);
  const GoalMonitor::Result r = at(0.5, {-0.25, 0.0, 0.0});
  EXPECT_TRUE(r.done);
  EXPECT_EQ(r.error_code, kPathToleranceViolated);
  EXPECT_NE(r.message.find("joint 'j'"), std::string::npos) << r.message;
  EXPECT_NE(r.message.find("path tolerance 0.1 by 0.15"), std::string::npos) << r.message;
  EXPECT_FALSE(monitor.active());
}

TEST_F(MonitorFixture, SucceedsWhenWithinGoalToleranceAfterTheEnd) {
  EXPECT_FALSE(at(0.99, {0.05, 0.0, 0.0}).done);  // path: fine; goal not yet checked
  EXPECT_FALSE(at(1.0, {0.05, 0.0, 0.0}).done);   // outside the goal tolerance, within goal_time
  const GoalMonitor::Result r = at(1.2, {0.01, 0.005, 0.0});
  EXPECT_TRUE(r.done);
  EXPECT_EQ(r.error_code, kSuccessful);
}

TEST_F(MonitorFixture, GoalToleranceViolatedAfterGoalTime) {
  EXPECT_FALSE(at(1.4, {0.05, 0.0, 0.0}).done);
  const GoalMonitor::Result r = at(1.5, {0.05, 0.0, 0.0});
  EXPECT_TRUE(r.done);
  EXPECT_EQ(r.error_code, kGoalToleranceViolated);
  EXPECT_NE(r.message.find("joint 'j' missed its goal"), std::string::npos) << r.message;
  EXPECT_NE(r.message.find("goal tolerance 0.02 by 0.03"), std::string::npos) << r.message;
  EXPECT_NE(r.message.find("goal_time tolerance 0.5 s"), std::string::npos) << r.message;
}

TEST_F(MonitorFixture, StillMovingViolatesTheStoppedVelocityTolerance) {
  const GoalMonitor::Result r = at(1.6, {0.0, -0.05, 0.0});
  EXPECT_TRUE(r.done);
  EXPECT_EQ(r.error_code, kGoalToleranceViolated);
  EXPECT_NE(r.message.find("still moving"), std::string::npos) << r.message;
}

TEST_F(MonitorFixture, ZeroGoalTimeChecksAtOnce) {
  tolerances.goal_time = 0.0;
  monitor.start(1, tolerances, {"j"}, 0.0);
  EXPECT_EQ(at(1.0, {0.05, 0.0, 0.0}).error_code, kGoalToleranceViolated);
}

TEST_F(MonitorFixture, SegmentsOfOtherGoalsAreNotChecked) {
  monitor.start(2, tolerances, {"j"}, 0.0);
  EXPECT_FALSE(at(0.5, {5.0, 0.0, 0.0}).done);
  EXPECT_FALSE(at(5.0, {5.0, 0.0, 0.0}).done);
  EXPECT_TRUE(monitor.active());
}

TEST(GoalMonitor, SucceedsOnlyOnceEveryJointHasArrived) {
  Command c;
  c.joint_names = {"a", "b"};
  c.points = {point(1.0, {1.0, 1.0})};
  const MergeResult m = merge(holding({0.0, 0.0}), c, 0.0, 0.0, options({"a", "b"}, 5));
  ASSERT_EQ(m.error_code, kSuccessful) << m.error;
  Tolerances tol;
  tol.path = {{}, {}};
  tol.goal = {{0.01, 0.0, 0.0}, {0.01, 0.0, 0.0}};
  tol.goal_time = 1.0;
  GoalMonitor monitor;
  monitor.start(5, tol, {"a", "b"}, 0.0);
  const std::vector<int> segments = {findSegment(m.trajectory[0], 1.1), findSegment(m.trajectory[1], 1.1)};
  EXPECT_FALSE(monitor.check(1.1, m.trajectory, segments, {{0.0, 0, 0}, {0.5, 0, 0}}).done);
  // a has arrived for good (ros_controllers does not re-check it); b arrives now.
  const GoalMonitor::Result r = monitor.check(1.2, m.trajectory, segments, {{0.5, 0, 0}, {0.0, 0, 0}});
  EXPECT_TRUE(r.done);
  EXPECT_EQ(r.error_code, kSuccessful);
}
