// At the goal: stop within the acceleration limits, turn in place to the goal's yaw, arrive.
#include <gtest/gtest.h>

#include <cmath>

#include "navigation_core/goal_approach.h"

namespace navigation_core {
namespace {

GoalApproachOptions options() {
  GoalApproachOptions o;
  o.xy_goal_tolerance = 0.2;
  o.yaw_goal_tolerance = 0.1;
  return o;
}

TEST(GoalApproach, FarFromTheGoalTheLocalPlannerDrives) {
  GoalApproach approach(options());
  Velocity2 command;
  EXPECT_EQ(approach.update({0, 0, 0}, {0.3, 0, 0}, {1.0, 0, 0}, command), GoalPhase::kApproaching);
}

TEST(GoalApproach, AtThePositionTheRobotBrakesThenTurnsThenArrives) {
  GoalApproach approach(options());
  Velocity2 command;
  const Pose2 goal{1.0, 0.0, M_PI / 2};
  // Moving at 0.3 m/s: brake by acc_lim_x * period = 0.125 m/s per period.
  ASSERT_EQ(approach.update({0.9, 0.05, 0}, {0.3, 0, 0}, goal, command), GoalPhase::kStopping);
  EXPECT_NEAR(command.x, 0.175, 1e-12);
  EXPECT_EQ(command.theta, 0.0);
  ASSERT_EQ(approach.update({0.9, 0.05, 0}, {0.1, 0, 0}, goal, command), GoalPhase::kStopping);
  EXPECT_EQ(command.x, 0.0);  // not past zero
  // Stopped: turn towards +pi/2, no faster than one period's acceleration from rest (0.16 rad/s).
  ASSERT_EQ(approach.update({0.9, 0.05, 0}, {0, 0, 0}, goal, command), GoalPhase::kTurning);
  EXPECT_NEAR(command.theta, 3.2 * 0.05, 1e-12);
  EXPECT_EQ(command.x, 0.0);
  // Turning at 0.5 rad/s with pi/2 left: 0.66 rad/s, within max_vel_theta 1.0.
  ASSERT_EQ(approach.update({0.9, 0.05, 0}, {0, 0, 0.5}, goal, command), GoalPhase::kTurning);
  EXPECT_NEAR(command.theta, 0.66, 1e-12);
  // Near the yaw the turn slows to what stops in the angle left, but not below the in-place minimum.
  ASSERT_EQ(approach.update({0.9, 0.05, M_PI / 2 - 0.15}, {0, 0, 0.4}, goal, command), GoalPhase::kTurning);
  EXPECT_NEAR(command.theta, 0.4, 1e-12);
  // The other way round: a negative turn.
  ASSERT_EQ(approach.update({0.9, 0.05, M_PI}, {0, 0, 0}, goal, command), GoalPhase::kTurning);
  EXPECT_LT(command.theta, 0.0);
  EXPECT_EQ(approach.update({0.9, 0.05, M_PI / 2 + 0.05}, {0, 0, 0}, goal, command), GoalPhase::kReached);
  EXPECT_EQ(command.theta, 0.0);
}

TEST(GoalApproach, ALatchedPositionHoldsWhileTheRobotDriftsOutOfTolerance) {
  GoalApproachOptions o = options();
  Velocity2 command;
  const Pose2 goal{1.0, 0.0, M_PI / 2};
  GoalApproach unlatched(o);
  ASSERT_EQ(unlatched.update({0.9, 0.0, 0}, {0, 0, 0}, goal, command), GoalPhase::kTurning);
  EXPECT_EQ(unlatched.update({0.7, 0.0, 0}, {0, 0, 0}, goal, command), GoalPhase::kApproaching);
  o.latch_xy_goal_tolerance = true;
  GoalApproach latched(o);
  ASSERT_EQ(latched.update({0.9, 0.0, 0}, {0, 0, 0}, goal, command), GoalPhase::kTurning);
  EXPECT_EQ(latched.update({0.7, 0.0, 0}, {0, 0, 0}, goal, command), GoalPhase::kTurning);
  latched.reset();
  EXPECT_EQ(latched.update({0.7, 0.0, 0}, {0, 0, 0}, goal, command), GoalPhase::kApproaching);
}

TEST(GoalApproach, AnglesWrapAcrossPi) {
  EXPECT_NEAR(angleDifference(M_PI - 0.1, -M_PI + 0.1), -0.2, 1e-12);
  EXPECT_NEAR(angleDifference(-M_PI + 0.1, M_PI - 0.1), 0.2, 1e-12);
}

}  // namespace
}  // namespace navigation_core
