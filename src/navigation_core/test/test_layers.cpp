// The static and obstacle layers against costmap_2d's rules.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "navigation_core/cost_values.h"
#include "navigation_core/obstacle_layer.h"
#include "navigation_core/static_layer.h"

namespace navigation_core {
namespace {

TEST(StaticLayer, MapValuesBecomeFreeLethalOrUnknown) {
  const StaticLayerOptions o;
  EXPECT_EQ(staticCost(-1, o), kNoInformation);
  EXPECT_EQ(staticCost(0, o), kFreeSpace);
  EXPECT_EQ(staticCost(99, o), kFreeSpace);
  EXPECT_EQ(staticCost(100, o), kLethalObstacle);
  StaticLayerOptions untracked;
  untracked.track_unknown_space = false;
  EXPECT_EQ(staticCost(-1, untracked), kFreeSpace);
}

TEST(StaticLayer, ThresholdAndScaledCosts) {
  StaticLayerOptions o;
  o.lethal_cost_threshold = 65;
  EXPECT_EQ(staticCost(65, o), kLethalObstacle);
  EXPECT_EQ(staticCost(64, o), kFreeSpace);
  o.trinary_costmap = false;
  EXPECT_EQ(staticCost(0, o), 0);
  EXPECT_EQ(staticCost(32, o), 125);  // 32 / 65 * 254 = 125.05
  EXPECT_EQ(staticCost(-1, o), kNoInformation);
}

TEST(StaticLayer, TheGridKeepsTheMapsGeometry) {
  const Costmap map = staticCostmap({0, 100, -1, 0, 0, 100}, 3, 2, 0.1, -1.0, 2.0, StaticLayerOptions());
  EXPECT_EQ(map.sizeX(), 3u);
  EXPECT_EQ(map.originY(), 2.0);
  EXPECT_EQ(map.cost(1, 0), kLethalObstacle);
  EXPECT_EQ(map.cost(2, 0), kNoInformation);
  EXPECT_EQ(map.cost(2, 1), kLethalObstacle);
  try {
    staticCostmap({0, 0}, 3, 2, 0.1, 0, 0, StaticLayerOptions());
    FAIL() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("expected width * height = 6 values, got 2"), std::string::npos) << e.what();
  }
}

// A 5 x 5 m layer of 0.05 m cells, all lethal, so clearing shows.
Costmap allLethal() { return Costmap(100, 100, 0.05, 0, 0, kLethalObstacle); }

TEST(ObstacleLayer, ARayClearsUpToItsPointWhichItMarks) {
  Costmap layer = allLethal();
  applyObservation(layer, {{1.02, 1.02, 0.2}, {{2.02, 1.02, 0.2}}}, ObstacleLayerOptions());
  for (unsigned x = 20; x < 40; ++x) EXPECT_EQ(layer.cost(x, 20), kFreeSpace) << x;
  EXPECT_EQ(layer.cost(40, 20), kLethalObstacle);  // the point
  EXPECT_EQ(layer.cost(41, 20), kLethalObstacle);  // behind it: untouched
  EXPECT_EQ(layer.cost(30, 21), kLethalObstacle);  // beside the ray: untouched
}

TEST(ObstacleLayer, FarPointsClearToTheRaytraceRangeAndDoNotMark) {
  Costmap layer = allLethal();
  // 3.5 m away: beyond obstacle_range (2.5) and raytrace_range (3.0 = 60 cells).
  applyObservation(layer, {{1.02, 1.02, 0.2}, {{4.52, 1.02, 0.2}}}, ObstacleLayerOptions());
  for (unsigned x = 20; x <= 80; ++x) EXPECT_EQ(layer.cost(x, 20), kFreeSpace) << x;
  for (unsigned x = 81; x <= 90; ++x) EXPECT_EQ(layer.cost(x, 20), kLethalObstacle) << x;
}

TEST(ObstacleLayer, PointsOutsideTheHeightBandClearButDoNotMark) {
  for (const double z : {-0.1, 2.5}) {
    Costmap layer(100, 100, 0.05, 0, 0);
    applyObservation(layer, {{1.02, 1.02, 0.2}, {{2.02, 1.02, z}}}, ObstacleLayerOptions());
    EXPECT_EQ(layer.cost(40, 20), kFreeSpace) << z;
  }
  Costmap layer(100, 100, 0.05, 0, 0);
  applyObservation(layer, {{1.02, 1.02, 0.2}, {{2.02, 1.02, 1.9}}}, ObstacleLayerOptions());
  EXPECT_EQ(layer.cost(40, 20), kLethalObstacle);
}

TEST(ObstacleLayer, ARayLeavingTheMapClearsToItsEdge) {
  Costmap layer = allLethal();
  ObstacleLayerOptions o;
  o.raytrace_range = 10.0;
  applyObservation(layer, {{4.0, 1.02, 0.0}, {{7.0, 1.02, 0.0}, {4.0, -3.0, 0.0}}}, o);
  for (unsigned x = 80; x < 100; ++x) EXPECT_EQ(layer.cost(x, 20), kFreeSpace) << x;
  for (unsigned y = 0; y <= 20; ++y) EXPECT_EQ(layer.cost(80, y), kFreeSpace) << y;
  EXPECT_EQ(layer.cost(79, 10), kLethalObstacle);
}

TEST(ObstacleLayer, ADiagonalRayClearsAConnectedLine) {
  Costmap layer = allLethal();
  applyObservation(layer, {{0.52, 0.52, 0}, {{1.52, 1.02, 0}}}, ObstacleLayerOptions());  // 20 x 10 cells
  int cleared = 0;
  for (unsigned y = 0; y < 100; ++y)
    for (unsigned x = 0; x < 100; ++x) cleared += layer.cost(x, y) == kFreeSpace;
  EXPECT_EQ(cleared, 20);  // one cell per step along x, the point's own cell marked again
  EXPECT_EQ(layer.cost(10, 10), kFreeSpace);
  EXPECT_EQ(layer.cost(30, 20), kLethalObstacle);
}

}  // namespace
}  // namespace navigation_core
