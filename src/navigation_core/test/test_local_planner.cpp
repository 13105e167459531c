// The trajectory-rollout local planner, closed loop: its commands integrated as a perfect robot would.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "navigation_core/cost_values.h"
#include "navigation_core/inflation.h"
#include "navigation_core/local_planner.h"

namespace navigation_core {
namespace {

constexpr double kRes = 0.05;
const Footprint kFootprint = {{-0.12, -0.09}, {-0.12, 0.09}, {0.12, 0.09}, {0.12, -0.09}};  // m_robot's

enum class Obstacle { kNone, kWall, kBox };

// A 5 x 5 m costmap, inflated as costmap_2d would: empty, with a wall across x = 3.00-3.10 m, or
// with a 0.4 m box at x 2.5-2.9, y 2.3-2.7.
Costmap arena(Obstacle obstacle) {
  Costmap map(100, 100, kRes, 0, 0);
  for (unsigned y = 0; y < 100; ++y) {
    for (unsigned x = 0; x < 100; ++x) {
      const bool wall = obstacle == Obstacle::kWall && (x == 60 || x == 61);
      const bool box = obstacle == Obstacle::kBox && x >= 50 && x < 58 && y >= 46 && y < 54;
      if (wall || box) map.setCost(x, y, kLethalObstacle);
    }
  }
  InflationOptions inflation;
  inflation.inflation_radius = 0.3;
  Inflation(inflation, footprintRadii(kFootprint).inscribed, kRes).apply(map);
  return map;
}

std::vector<Point2> straightPlan(Point2 from, Point2 to) {
  std::vector<Point2> plan;
  for (int k = 0; k <= 100; ++k) plan.push_back({from.x + (to.x - from.x) * k / 100, from.y + (to.y - from.y) * k / 100});
  return plan;
}

struct DriveResult {
  Pose2 pose;
  bool collided = false;
  int failures = 0;
  double max_front_x = -1e9;
};

// Follows `plan` for `seconds` at 20 Hz, the robot doing exactly what it is told.
DriveResult drive(const Costmap& map, Pose2 pose, const std::vector<Point2>& plan, double seconds, double stop_within) {
  LocalPlanner planner{LocalPlannerOptions()};
  DriveResult run;
  Velocity2 velocity;
  const double dt = 0.05;
  for (double t = 0; t < seconds; t += dt) {
    if (std::hypot(pose.x - plan.back().x, pose.y - plan.back().y) < stop_within) break;
    Trajectory best;
    std::string why;
    if (!planner.computeVelocity(map, kFootprint, pose, velocity, plan, best, &why)) {
      ++run.failures;
      velocity = Velocity2();
      continue;
    }
    velocity = best.velocity;
    pose.x += velocity.x * std::cos(pose.theta) * dt;
    pose.y += velocity.x * std::sin(pose.theta) * dt;
    pose.theta += velocity.theta * dt;
    for (const Point2& c : kFootprint) {
      const double x = pose.x + std::cos(pose.theta) * c.x - std::sin(pose.theta) * c.y;
      const double y = pose.y + std::sin(pose.theta) * c.x + std::cos(pose.theta) * c.y;
      unsigned mx, my;
      run.collided = run.collided || !map.worldToMap(x, y, mx, my) || map.cost(mx, my) == kLethalObstacle;
      run.max_front_x = std::max(run.max_front_x, x);
    }
  }
  run.pose = pose;
  return run;
}

TEST(LocalPlanner, InTheOpenItDrivesForwardAlongThePath) {
  const Costmap map = arena(Obstacle::kNone);
  LocalPlanner planner{LocalPlannerOptions()};
  Trajectory best;
  std::string why;
  ASSERT_TRUE(planner.computeVelocity(map, kFootprint, {1.0, 2.5, 0.0}, Velocity2(), straightPlan({1.0, 2.5}, {4.0, 2.5}),
                                      best, &why))
      << why;
  EXPECT_GT(best.velocity.x, 0.0);
  EXPECT_LE(best.velocity.x, 2.5 * 0.05 + 1e-9);  // within the window from rest: acc_lim_x * one period
  EXPECT_LE(std::abs(best.velocity.theta), 0.2);
}

TEST(LocalPlanner, ItTurnsTowardsAPathThatBendsLeft) {
  const Costmap map = arena(Obstacle::kNone);
  LocalPlanner planner{LocalPlannerOptions()};
  Trajectory best;
  std::string why;
  ASSERT_TRUE(planner.computeVelocity(map, kFootprint, {1.0, 1.0, 0.0}, Velocity2(), straightPlan({1.0, 1.0}, {1.5, 4.0}),
                                      best, &why))
      << why;
  EXPECT_GT(best.velocity.theta, 0.0);
}

TEST(LocalPlanner, WithDwasLimitsAPathBehindTheRobotMakesItTurnInPlaceNotStandStill) {
  // dwa_local_planner's set-up: min_vel_x 0 lets it sample standing still, which ends where a turn
  // in place does and, near a wall (0.4 m off: the turning footprint sweeps inflated cells), scores
  // better; min_vel_trans rules such non-moves out.
  LocalPlannerOptions o;
  o.min_vel_x = 0.0;
  o.min_vel_trans = 0.1;
  o.min_in_place_vel_theta = 0.8;
  o.max_vel_theta = 2.0;
  o.min_vel_theta = -2.0;
  o.meter_scoring = true;
  o.path_distance_bias = 32.0;
  o.goal_distance_bias = 24.0;
  o.occdist_scale = 0.02;
  LocalPlanner planner(o);
  const Costmap map = arena(Obstacle::kWall);
  Trajectory best;
  std::string why;
  ASSERT_TRUE(planner.computeVelocity(map, kFootprint, {2.6, 2.5, M_PI / 2}, Velocity2(),
                                      straightPlan({2.6, 2.5}, {2.6, 0.5}), best, &why))
      << why;
  EXPECT_GE(std::abs(best.velocity.theta), 0.8 - 1e-9);
  EXPECT_LE(std::abs(best.velocity.theta), 2.0 + 1e-9);
  EXPECT_LT(std::abs(best.velocity.x), 0.1);
}

TEST(LocalPlanner, ItReachesAGoalAheadWithoutTouchingAnything) {
  const DriveResult run = drive(arena(Obstacle::kNone), {1.0, 2.5, 0.3}, straightPlan({1.0, 2.5}, {3.5, 2.0}), 40.0, 0.10);
  EXPECT_FALSE(run.collided);
  EXPECT_EQ(run.failures, 0);
  EXPECT_LT(std::hypot(run.pose.x - 3.5, run.pose.y - 2.0), 0.10);
}

TEST(LocalPlanner, ItGoesRoundABoxOnThePathToTheGoal) {
  // The path runs through the box (as when the world changed under a global plan); the goal
  // distance counts round it.
  const DriveResult run = drive(arena(Obstacle::kBox), {1.0, 2.5, 0.0}, straightPlan({1.0, 2.5}, {4.0, 2.5}), 40.0, 0.10);
  EXPECT_FALSE(run.collided);
  EXPECT_LT(std::hypot(run.pose.x - 4.0, run.pose.y - 2.5), 0.10);
}

TEST(LocalPlanner, ATrajectoryOntoAWallIsCutAtTheLastSafePose) {
  const Costmap map = arena(Obstacle::kWall);
  const LocalPlanner planner{LocalPlannerOptions()};
  Velocity2 half_speed;
  half_speed.x = 0.5;  // 0.5 m in the 1 s simulated, in steps of sim_granularity (0.025 m)
  // From x = 2.5 the front edge (0.12 m ahead) is at 2.62 + 0.025 k after step k: on the wall's
  // first cell (x >= 3.00) from step 16, so 15 safe poses and the trajectory is unsafe.
  const Trajectory into = planner.simulate(map, kFootprint, {2.5, 2.5, 0.0}, half_speed);
  EXPECT_EQ(into.poses.size(), 15u);
  EXPECT_LT(into.cost, 0.0);
  // Along the wall, or stopping short of it (0.2 m: front at 2.82 m, over inflated cells only): every pose safe.
  EXPECT_EQ(planner.simulate(map, kFootprint, {2.5, 1.0, M_PI / 2}, half_speed).poses.size(), 20u);
  Velocity2 slow;
  slow.x = 0.2;
  EXPECT_EQ(planner.simulate(map, kFootprint, {2.5, 2.5, 0.0}, slow).poses.size(), 8u);
}

TEST(LocalPlanner, ItNeverDrivesIntoAWallAcrossThePath) {
  // The goal is behind a wall from edge to edge: nothing reaches it, and nothing may touch the wall.
  const DriveResult run = drive(arena(Obstacle::kWall), {2.2, 2.5, 0.0}, straightPlan({2.2, 2.5}, {4.5, 2.5}), 20.0, 0.10);
  EXPECT_FALSE(run.collided);
  EXPECT_LT(run.max_front_x, 3.0);
}

TEST(LocalPlanner, AGoalWalledOffFromTheRobotIsAFailureWithTheReason) {
  // As base_local_planner: no way round the obstacles to the local goal, no command at all (so that
  // move_base plans again), not the least bad of the hopeless trajectories.
  LocalPlanner planner{LocalPlannerOptions()};
  Trajectory best;
  std::string why;
  EXPECT_FALSE(planner.computeVelocity(arena(Obstacle::kWall), kFootprint, {2.2, 2.5, 0.0}, Velocity2(),
                                       straightPlan({2.2, 2.5}, {4.5, 2.5}), best, &why));
  EXPECT_NE(why.find("the plan is blocked"), std::string::npos) << why;
  // The same wall with a gap at its end: a way round, so a command.
  Costmap gap = arena(Obstacle::kNone);
  for (unsigned y = 0; y < 80; ++y) gap.setCost(60, y, kLethalObstacle), gap.setCost(61, y, kLethalObstacle);
  InflationOptions inflation;
  inflation.inflation_radius = 0.3;
  Inflation(inflation, footprintRadii(kFootprint).inscribed, kRes).apply(gap);
  EXPECT_TRUE(planner.computeVelocity(gap, kFootprint, {2.2, 2.5, 0.0}, Velocity2(), straightPlan({2.2, 2.5}, {4.5, 2.5}),
                                      best, &why)) << why;
  // Against the walled-off goal again: a trajectory over the robot's side, cut off from the goal,
  // scores -2 (the footprint would not touch anything).
  planner.computeVelocity(arena(Obstacle::kWall), kFootprint, {2.2, 2.5, 0.0}, Velocity2(),
                          straightPlan({2.2, 2.5}, {4.5, 2.5}), best, &why);
  Velocity2 ahead;
  ahead.x = 0.3;
  EXPECT_EQ(planner.simulate(arena(Obstacle::kWall), kFootprint, {2.2, 2.5, 0.0}, ahead).cost, -2.0);
}

// The best of every sampled move (not the turns in place) checked in turn: the lowest score, the
// first sampled among equals. Built on simulate(), which scores against the distance grids of the
// planner's last cycle.
Trajectory bestMoveCheckingEvery(const LocalPlanner& planner, const LocalPlannerOptions& o, const Costmap& map,
                                 const Pose2& pose, const Velocity2& v, const Footprint& footprint) {
  const double h = o.dwa ? o.sim_period : o.sim_time;
  const double max_vx = std::min(o.max_vel_x, v.x + o.acc_lim_x * h);
  const double min_vx = std::min(max_vx, std::max(o.min_vel_x, v.x - o.acc_lim_x * h));
  const double max_vth = std::min(o.max_vel_theta, v.theta + o.acc_lim_theta * h);
  const double min_vth = std::min(max_vth, std::max(o.min_vel_theta, v.theta - o.acc_lim_theta * h));
  Trajectory best;
  for (int i = 0; i < o.vx_samples; ++i) {
    for (int j = 0; j < o.vtheta_samples; ++j) {
      Velocity2 c;
      c.x = o.vx_samples == 1 ? max_vx : min_vx + i * (max_vx - min_vx) / (o.vx_samples - 1);
      c.theta = o.vtheta_samples == 1 ? 0.0 : min_vth + j * (max_vth - min_vth) / (o.vtheta_samples - 1);
      Trajectory t = planner.simulate(map, footprint, pose, c);
      if (t.cost >= 0 && (best.cost < 0 || t.cost < best.cost)) best = t;
    }
  }
  return best;
}

TEST(LocalPlanner, ItChoosesTheCommandThatCheckingEverySampleWouldChoose) {
  // The planner checks footprints cheapest end first and stops once no sample can beat the best;
  // over random poses and speeds among boxes, with the Pioneer's sampling (6 x 20 over 1.5 s, in
  // metres) and the defaults, its command is the exhaustive search's, cost for cost.
  Costmap map(100, 100, kRes, 0, 0);
  std::mt19937 rng(7);
  std::uniform_int_distribution<unsigned> cell(0, 95);
  for (int b = 0; b < 25; ++b) {
    const unsigned x0 = cell(rng), y0 = cell(rng);
    for (unsigned y = y0; y < y0 + 4; ++y)
      for (unsigned x = x0; x < x0 + 4; ++x) map.setCost(x, y, kLethalObstacle);
  }
  InflationOptions inflation;
  inflation.inflation_radius = 0.6;
  Inflation(inflation, footprintRadii(kFootprint).inscribed, kRes).apply(map);
  LocalPlannerOptions pioneer;
  pioneer.max_vel_x = 0.5, pioneer.acc_lim_x = 1.0, pioneer.acc_lim_theta = 2.0, pioneer.sim_time = 1.5;
  pioneer.vx_samples = 6, pioneer.meter_scoring = true, pioneer.min_in_place_vel_theta = 0.5;
  std::uniform_real_distribution<double> where(0.3, 4.7), heading(-M_PI, M_PI), speed(0.0, 0.5), turn(-1.0, 1.0);
  int compared = 0, moves = 0;
  for (const LocalPlannerOptions& o : {LocalPlannerOptions(), pioneer}) {
    LocalPlanner planner(o);
    for (int k = 0; k < 300; ++k) {
      const Pose2 pose{where(rng), where(rng), heading(rng)};
      unsigned mx, my;
      if (!map.worldToMap(pose.x, pose.y, mx, my) || map.cost(mx, my) >= kInscribedInflatedObstacle) continue;
      Velocity2 v;
      v.x = speed(rng), v.theta = turn(rng);
      Trajectory best;
      std::string why;
      const bool ok = planner.computeVelocity(map, kFootprint, pose, v, straightPlan({pose.x, pose.y}, {where(rng), where(rng)}),
                                              best, &why);
      const Trajectory reference = bestMoveCheckingEvery(planner, o, map, pose, v, kFootprint);
      ++compared;
      if (!ok || reference.cost < 0 || best.velocity.x == 0.0) continue;  // no move, or a turn in place
      ++moves;
      EXPECT_EQ(best.velocity.x, reference.velocity.x) << "sample " << k;
      EXPECT_EQ(best.velocity.theta, reference.velocity.theta) << "sample " << k;
      EXPECT_EQ(best.cost, reference.cost) << "sample " << k;
      EXPECT_EQ(best.poses.size(), reference.poses.size()) << "sample " << k;
    }
  }
  // Not a vacuous comparison: a quarter of the poses (134 of 538) end in a move; the rest turn in
  // place towards plans that lie behind them, or lie too near a box for any move.
  EXPECT_GT(moves, compared / 5);
  EXPECT_LE(moves, compared);
}

TEST(LocalPlanner, APlanThatLeavesTheWindowAndComesBackBeyondAWallIsFollowedToWhereItLeaves) {
  // North out of the 5 x 5 m window, east beyond it, back in south on the wall's far side: the
  // local goal is where the plan first leaves (no way inside the window leads to the far side).
  std::vector<Point2> plan = straightPlan({2.2, 2.5}, {2.2, 5.5});
  for (const Point2& p : straightPlan({2.2, 5.5}, {3.8, 5.5})) plan.push_back(p);
  for (const Point2& p : straightPlan({3.8, 5.5}, {3.8, 2.5})) plan.push_back(p);
  LocalPlanner planner{LocalPlannerOptions()};
  Trajectory best;
  std::string why;
  ASSERT_TRUE(planner.computeVelocity(arena(Obstacle::kWall), kFootprint, {2.2, 2.5, M_PI / 2}, Velocity2(), plan, best,
                                      &why)) << why;
  EXPECT_GT(best.velocity.x, 0.0);
  EXPECT_LE(std::abs(best.velocity.theta), 0.2);
}

}  // namespace
}  // namespace navigation_core
