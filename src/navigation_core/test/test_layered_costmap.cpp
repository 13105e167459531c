// The layers combined as costmap_2d combines them, and the rolling window.
#include <gtest/gtest.h>

#include <cmath>

#include "navigation_core/cost_values.h"
#include "navigation_core/layered_costmap.h"

namespace navigation_core {
namespace {

const Footprint kFootprint = {{-0.12, -0.09}, {-0.12, 0.09}, {0.12, 0.09}, {0.12, -0.09}};

std::uint8_t at(const Costmap& map, double x, double y) {
  unsigned mx, my;
  EXPECT_TRUE(map.worldToMap(x, y, mx, my)) << x << ", " << y;
  return map.cost(mx, my);
}

// A 4 x 3 m static map of 0.05 m cells with a wall at x = 2.00-2.05 m and an unknown strip at y > 2.5.
Costmap staticMap() {
  Costmap map(80, 60, 0.05, 0.0, 0.0);
  for (unsigned y = 0; y < 60; ++y) map.setCost(40, y, kLethalObstacle);
  for (unsigned y = 51; y < 60; ++y)
    for (unsigned x = 0; x < 40; ++x) map.setCost(x, y, kNoInformation);
  return map;
}

TEST(LayeredCostmap, AGlobalCostmapTakesTheStaticMapsGeometryAndInflatesItsWalls) {
  LayeredCostmapOptions o;
  o.track_unknown_space = true;
  LayeredCostmap costmap(o, kFootprint);
  costmap.setStaticMap(staticMap());
  const Costmap& master = costmap.update();
  EXPECT_EQ(master.sizeX(), 80u);
  EXPECT_EQ(master.sizeY(), 60u);
  EXPECT_EQ(at(master, 2.02, 1.0), kLethalObstacle);
  EXPECT_EQ(at(master, 2.07, 1.0), kInscribedInflatedObstacle);  // 0.05 m from the wall
  EXPECT_EQ(at(master, 2.27, 1.0), 50);                          // 0.25 m: 252 e^(-10 (0.25 - 0.09))
  EXPECT_EQ(at(master, 3.5, 1.0), kFreeSpace);
  EXPECT_EQ(at(master, 1.0, 2.8), kNoInformation);
}

TEST(LayeredCostmap, ObstaclesAddToTheStaticMapAndClearingThemLeavesItsWalls) {
  LayeredCostmapOptions o;
  o.inflate = false;
  LayeredCostmap costmap(o, kFootprint);
  costmap.setStaticMap(staticMap());
  costmap.addObservation({{0.5, 1.0, 0.2}, {{1.5, 1.0, 0.2}}});
  EXPECT_EQ(at(costmap.update(), 1.52, 1.02), kLethalObstacle);
  // Seen again from the other side, farther than the wall: the ray clears the box's cell and the
  // wall's, but the wall is the static map's.
  costmap.addObservation({{0.5, 1.02, 0.2}, {{2.92, 1.02, 0.2}}});
  const Costmap& master = costmap.update();
  EXPECT_EQ(at(master, 1.52, 1.02), kFreeSpace);
  EXPECT_EQ(at(master, 2.02, 1.02), kLethalObstacle);
  EXPECT_EQ(at(master, 2.92, 1.02), kLethalObstacle);
  // Seen cells of the unknown strip become free.
  costmap.addObservation({{0.52, 2.0, 0.2}, {{0.52, 2.92, 0.2}}});
  EXPECT_EQ(at(costmap.update(), 0.52, 2.62), kFreeSpace);
  costmap.resetObstacles();
  EXPECT_EQ(at(costmap.update(), 0.52, 2.62), kNoInformation);
}

TEST(LayeredCostmap, ARollingWindowFollowsTheRobotAndKeepsWhatItStillCovers) {
  LayeredCostmapOptions o;
  o.width = o.height = 2.0;
  o.rolling_window = true;
  o.inflate = false;
  LayeredCostmap costmap(o, kFootprint);
  costmap.updateOrigin(0.0, 0.0);
  EXPECT_DOUBLE_EQ(costmap.master().originX(), -1.0);
  costmap.addObservation({{0.0, 0.0, 0.2}, {{0.52, 0.02, 0.2}, {-0.83, 0.02, 0.2}}});
  EXPECT_EQ(at(costmap.update(), 0.52, 0.02), kLethalObstacle);
  costmap.updateOrigin(0.61, 0.0);  // 12.2 cells: the window moves by 12
  EXPECT_NEAR(costmap.master().originX(), -1.0 + 0.60, 1e-12);
  const Costmap& master = costmap.update();
  EXPECT_EQ(at(master, 0.52, 0.02), kLethalObstacle);  // the same place in the world
  EXPECT_EQ(at(master, 1.55, 0.02), kFreeSpace);       // newly covered: unseen, free without track_unknown_space
  unsigned mx, my;
  EXPECT_FALSE(master.worldToMap(-0.83, 0.02, mx, my));  // left behind
}

TEST(LayeredCostmap, AnObstacleLayerThatDoesNotTrackUnknownSpaceFreesTheStaticMapsUnknownCells) {
  // costmap_2d's default: the obstacle layer's unseen cells are free, and the maximum of free and
  // the static map's unknown is free.
  LayeredCostmapOptions o;
  o.inflate = false;
  o.obstacle_track_unknown_space = false;
  LayeredCostmap costmap(o, kFootprint);
  costmap.setStaticMap(staticMap());
  EXPECT_EQ(at(costmap.update(), 1.0, 2.8), kFreeSpace);
  EXPECT_EQ(at(costmap.update(), 2.02, 1.0), kLethalObstacle);  // the walls stay
  o.obstacle_track_unknown_space = true;
  LayeredCostmap tracking(o, kFootprint);
  tracking.setStaticMap(staticMap());
  EXPECT_EQ(at(tracking.update(), 1.0, 2.8), kNoInformation);
}

TEST(LayeredCostmap, ResettingOutsideAWindowKeepsTheObstaclesInsideIt) {
  LayeredCostmapOptions o;
  o.inflate = false;
  LayeredCostmap costmap(o, kFootprint);
  costmap.setStaticMap(Costmap(80, 60, 0.05, 0.0, 0.0));
  costmap.addObservation({{1.0, 1.0, 0.2}, {{1.42, 1.02, 0.2}, {1.62, 1.02, 0.2}, {3.02, 1.02, 0.2}}});
  costmap.resetObstaclesOutside(1.0, 1.0, 1.0);  // keeps x, y in 0.5 .. 1.5
  const Costmap& master = costmap.update();
  EXPECT_EQ(at(master, 1.42, 1.02), kLethalObstacle);
  EXPECT_EQ(at(master, 1.62, 1.02), kFreeSpace);  // unseen again: the static map's free
  EXPECT_EQ(at(master, 3.02, 1.02), kFreeSpace);
}

// A map arriving between two updates (the mapper publishes one every few seconds) must not leave
// the master blank until the next update: a planner reading it then would plan through walls.
TEST(LayeredCostmap, ANewStaticMapIsCombinedAtOnceAndKeepsTheObstaclesOfTheSameGrid) {
  LayeredCostmapOptions o;
  o.track_unknown_space = true;
  o.inflate = false;
  LayeredCostmap costmap(o, kFootprint);
  costmap.setStaticMap(staticMap());
  EXPECT_EQ(at(costmap.master(), 2.02, 1.0), kLethalObstacle);
  costmap.addObservation({{0.5, 1.0, 0.2}, {{1.5, 1.0, 0.2}}});
  costmap.update();
  costmap.setStaticMap(staticMap());  // the same grid again, no update after it
  EXPECT_EQ(at(costmap.master(), 2.02, 1.0), kLethalObstacle);
  EXPECT_EQ(at(costmap.master(), 1.52, 1.02), kLethalObstacle);
  EXPECT_EQ(at(costmap.master(), 1.0, 2.8), kNoInformation);
  EXPECT_EQ(at(costmap.master(), 1.0, 1.0), kFreeSpace);
  // A grown map: the new size at once, the obstacles started again.
  Costmap bigger(100, 60, 0.05, 0.0, 0.0);
  costmap.setStaticMap(bigger);
  EXPECT_EQ(costmap.master().sizeX(), 100u);
  EXPECT_EQ(at(costmap.master(), 1.52, 1.02), kFreeSpace);
}

// ObstacleLayer's footprint_clearing_enabled: what was marked under the robot is freed on the
// update that knows where the robot is, cells next to it stay marked, and the option turns it off.
TEST(LayeredCostmap, ObstacleCellsUnderTheFootprintAreFreedWhenTheRobotsPoseIsGiven) {
  for (const bool clearing : {true, false}) {
    LayeredCostmapOptions o;
    o.inflate = false;
    o.footprint_clearing_enabled = clearing;
    LayeredCostmap costmap(o, kFootprint);
    // Marks in a 1 m window about the robot at (5, 5) turned by 90 degrees: its 0.24 m length along
    // y now, 0.18 m width along x.
    const Observation seen{{5.0, 5.0, 0.2}, {{5.0, 5.10, 0.2}, {5.07, 5.0, 0.2}, {5.0, 5.22, 0.2}, {5.17, 5.0, 0.2}}};
    costmap.addObservation(seen, ObstacleLayerOptions{});
    const Costmap& master = costmap.update(Pose2{5.0, 5.0, M_PI / 2});
    const std::uint8_t under = clearing ? kFreeSpace : kLethalObstacle;
    EXPECT_EQ(at(master, 5.0, 5.10), under) << "inside, near the front edge";
    EXPECT_EQ(at(master, 5.07, 5.0), under) << "on the side edge's cell";
    EXPECT_EQ(at(master, 5.0, 5.22), kLethalObstacle) << "0.10 m beyond the front edge";
    EXPECT_EQ(at(master, 5.17, 5.0), kLethalObstacle) << "0.08 m beyond the side edge";
    // Without the pose (no tf yet) nothing is freed.
    costmap.addObservation(seen, ObstacleLayerOptions{});
    EXPECT_EQ(at(costmap.update(), 5.0, 5.10), kLethalObstacle);
  }
}

}  // namespace
}  // namespace navigation_core
