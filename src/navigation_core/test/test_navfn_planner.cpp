// The navfn-style planner on grids whose shortest paths are known.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "navigation_core/cost_values.h"
#include "navigation_core/navfn_planner.h"

namespace navigation_core {
namespace {

constexpr double kRes = 0.05;

double length(const std::vector<Point2>& path) {
  double total = 0;
  for (std::size_t k = 1; k < path.size(); ++k) total += std::hypot(path[k].x - path[k - 1].x, path[k].y - path[k - 1].y);
  return total;
}

double dist(const Point2& a, const Point2& b) { return std::hypot(a.x - b.x, a.y - b.y); }

// Every point of the path lies in a cell the planner may cross.
void expectPassable(const Costmap& map, const std::vector<Point2>& path, std::uint8_t blocked_from) {
  for (const Point2& p : path) {
    unsigned mx, my;
    ASSERT_TRUE(map.worldToMap(p.x, p.y, mx, my)) << p.x << ", " << p.y;
    EXPECT_LT(map.cost(mx, my), blocked_from) << "path point " << p.x << ", " << p.y;
  }
}

TEST(NavfnPlanner, InTheOpenThePathIsNearlyStraight) {
  const Costmap map(100, 100, kRes, 0, 0);
  NavfnPlanner planner;
  const Point2 start{0.52, 0.51}, goal{4.0, 3.1};
  std::string why;
  const std::vector<Point2> path = planner.makePlan(map, start, goal, 0.0, &why);
  ASSERT_FALSE(path.empty()) << why;
  EXPECT_EQ(path.front().x, start.x);
  EXPECT_EQ(path.back().y, goal.y);
  // navfn's interpolation keeps a diagonal within a few per cent of the straight line (a 4-connected
  // staircase would be 36 % longer here).
  const double straight = dist(start, goal);
  EXPECT_GE(length(path), straight);
  EXPECT_LE(length(path), 1.01 * straight) << length(path) << " vs " << straight;  // 1.0005 measured
  for (const Point2& p : path) {  // and never far from it
    const double cross = std::abs((goal.x - start.x) * (p.y - start.y) - (goal.y - start.y) * (p.x - start.x)) / straight;
    EXPECT_LT(cross, 0.1) << p.x << ", " << p.y;
  }
}

Costmap wallWithGap(std::uint8_t wall_cost, bool gap) {
  Costmap map(100, 100, kRes, 0, 0);
  for (unsigned y = 0; y < 100; ++y)
    if (!gap || y < 80 || y > 85) map.setCost(50, y, wall_cost);  // x in [2.50, 2.55) m; gap y in [4.00, 4.30)
  return map;
}

TEST(NavfnPlanner, ThroughAGapThePathIsTheShortestWithinInterpolation) {
  const Costmap map = wallWithGap(kLethalObstacle, true);
  NavfnPlanner planner;
  const Point2 start{1.0, 1.0}, goal{4.0, 1.0};
  std::string why;
  const std::vector<Point2> path = planner.makePlan(map, start, goal, 0.0, &why);
  ASSERT_FALSE(path.empty()) << why;
  expectPassable(map, path, kLethalObstacle);
  // It must cross x in [2.50, 2.55] at y >= 4.0, so the shortest is via the gap's lower corners.
  const double shortest = dist(start, {2.5, 4.0}) + 0.05 + dist({2.55, 4.0}, goal);
  EXPECT_GE(length(path), shortest - 1e-9);
  EXPECT_LE(length(path), 1.02 * shortest) << length(path) << " vs " << shortest;  // 1.008 measured
}

TEST(NavfnPlanner, NoPlanThroughLethalCells) {
  NavfnPlanner planner;
  std::string why;
  EXPECT_TRUE(planner.makePlan(wallWithGap(kLethalObstacle, false), {1.0, 1.0}, {4.0, 1.0}, 0.0, &why).empty());
  EXPECT_NE(why.find("no path"), std::string::npos) << why;
  // Inscribed cells block too: the robot's centre there means a collision.
  EXPECT_TRUE(planner.makePlan(wallWithGap(kInscribedInflatedObstacle, false), {1.0, 1.0}, {4.0, 1.0}, 0.0, &why).empty());
}

TEST(NavfnPlanner, UnknownCellsArePassableOnlyWithAllowUnknown) {
  const Costmap map = wallWithGap(kNoInformation, false);
  NavfnOptions options;
  options.allow_unknown = false;
  std::string why;
  EXPECT_TRUE(NavfnPlanner(options).makePlan(map, {1.0, 1.0}, {4.0, 1.0}, 0.0, &why).empty());
  options.allow_unknown = true;
  const std::vector<Point2> path = NavfnPlanner(options).makePlan(map, {1.0, 1.0}, {4.0, 1.0}, 0.0, &why);
  ASSERT_FALSE(path.empty()) << why;
  EXPECT_LE(length(path), 3.0 * 1.02 + kRes);  // straight through the unknown wall
}

TEST(NavfnPlanner, AGoalInAnObstacleIsReplacedWithinTheTolerance) {
  Costmap map(60, 60, kRes, 0, 0);
  for (unsigned y = 39; y <= 41; ++y)
    for (unsigned x = 39; x <= 41; ++x) map.setCost(x, y, kLethalObstacle);  // 3 x 3 around cell (40, 40)
  const Point2 goal{40.5 * kRes, 40.5 * kRes};
  NavfnPlanner planner;
  std::string why;
  EXPECT_TRUE(planner.makePlan(map, {0.5, 0.5}, goal, 0.0, &why).empty());
  const std::vector<Point2> path = planner.makePlan(map, {0.5, 0.5}, goal, 0.2, &why);
  ASSERT_FALSE(path.empty()) << why;
  // The nearest free cell centres are two cells from the goal's (0.10 m), and the nearest of them
  // on the robot's side is reached.
  EXPECT_NEAR(dist(path.back(), goal), 0.10, 1e-9);
  expectPassable(map, path, kLethalObstacle);
}

// The planner keeps its buffers from plan to plan: a plan must not depend on what came before it,
// on a map of the same size or another.
TEST(NavfnPlanner, AReusedPlannerPlansAsAFreshOne) {
  Costmap small(60, 60, kRes, 0, 0);
  for (unsigned y = 10; y < 50; ++y) small.setCost(30, y, kLethalObstacle);
  const Costmap gap = wallWithGap(kLethalObstacle, true), walled = wallWithGap(kLethalObstacle, false);
  struct Case {
    const Costmap* map;
    Point2 start, goal;
  };
  const std::vector<Case> cases = {{&gap, {1.0, 1.0}, {4.0, 1.0}},    {&small, {0.5, 1.5}, {2.5, 1.5}},
                                   {&walled, {1.0, 1.0}, {4.0, 1.0}}, {&gap, {4.5, 4.5}, {0.3, 0.4}},
                                   {&small, {2.5, 0.2}, {0.4, 2.8}},  {&gap, {1.0, 1.0}, {4.0, 1.0}}};
  NavfnPlanner reused;
  for (const Case& c : cases) {
    NavfnPlanner fresh;
    std::string why_reused, why_fresh;
    const std::vector<Point2> path = reused.makePlan(*c.map, c.start, c.goal, 0.0, &why_reused);
    const std::vector<Point2> expected = fresh.makePlan(*c.map, c.start, c.goal, 0.0, &why_fresh);
    ASSERT_EQ(path.size(), expected.size()) << why_reused;
    for (std::size_t k = 0; k < path.size(); ++k) {
      EXPECT_EQ(path[k].x, expected[k].x) << k;
      EXPECT_EQ(path[k].y, expected[k].y) << k;
    }
    EXPECT_EQ(why_reused, why_fresh);
    EXPECT_TRUE(reused.potential() == fresh.potential());
  }
}

TEST(NavfnPlanner, StartOrGoalOffTheMapIsSaid) {
  const Costmap map(20, 20, kRes, 0, 0);
  NavfnPlanner planner;
  std::string why;
  EXPECT_TRUE(planner.makePlan(map, {0.5, 0.5}, {5.0, 0.5}, 0.0, &why).empty());
  EXPECT_NE(why.find("goal is off"), std::string::npos) << why;
  EXPECT_TRUE(planner.makePlan(map, {-1, 0.5}, {0.5, 0.5}, 0.0, &why).empty());
  EXPECT_NE(why.find("robot's position is off"), std::string::npos) << why;
}

}  // namespace
}  // namespace navigation_core
