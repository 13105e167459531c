// The costmap grid: world <-> cell conversions and distances as costmap_2d's Costmap2D has them.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "navigation_core/costmap.h"

namespace navigation_core {
namespace {

TEST(Costmap, APointBelongsToTheCellWhoseSquareHoldsIt) {
  const Costmap map(10, 20, 0.05, -1.0, 2.0);
  unsigned mx = 99, my = 99;
  ASSERT_TRUE(map.worldToMap(-1.0, 2.0, mx, my));  // the map's corner
  EXPECT_EQ(mx, 0u);
  EXPECT_EQ(my, 0u);
  ASSERT_TRUE(map.worldToMap(-1.0 + 0.149, 2.0 + 0.951, mx, my));
  EXPECT_EQ(mx, 2u);
  EXPECT_EQ(my, 19u);
  EXPECT_FALSE(map.worldToMap(-1.0 + 0.5, 2.0, mx, my));  // x = size: one past the last cell
  EXPECT_FALSE(map.worldToMap(-1.001, 2.0, mx, my));
  EXPECT_FALSE(map.worldToMap(NAN, 2.0, mx, my));
  EXPECT_EQ(mx, 2u);  // untouched when outside
}

TEST(Costmap, ACellsWorldPointIsItsCentreAndMapsBack) {
  const Costmap map(10, 20, 0.05, -1.0, 2.0);
  double wx = 0, wy = 0;
  map.mapToWorld(3, 7, wx, wy);
  EXPECT_NEAR(wx, -1.0 + 3.5 * 0.05, 1e-12);
  EXPECT_NEAR(wy, 2.0 + 7.5 * 0.05, 1e-12);
  unsigned mx = 0, my = 0;
  ASSERT_TRUE(map.worldToMap(wx, wy, mx, my));
  EXPECT_EQ(mx, 3u);
  EXPECT_EQ(my, 7u);
}

TEST(Costmap, CellDistanceRoundsUp) {
  const Costmap map(1, 1, 0.05, 0, 0);
  EXPECT_EQ(map.cellDistance(0.55), 11u);
  EXPECT_EQ(map.cellDistance(0.551), 12u);
  EXPECT_EQ(map.cellDistance(0.0), 0u);
  EXPECT_EQ(map.cellDistance(-1.0), 0u);
}

TEST(Costmap, CellsAreRowMajorWithXFastest) {
  Costmap map(4, 3, 1.0, 0, 0, 7);
  EXPECT_EQ(map.costs().size(), 12u);
  EXPECT_EQ(map.cost(3, 2), 7);
  map.setCost(1, 2, 200);
  EXPECT_EQ(map.costs()[2 * 4 + 1], 200);
  map.reset(0);
  EXPECT_EQ(map.cost(1, 2), 0);
}

TEST(Costmap, ABadResolutionIsNamed) {
  try {
    Costmap(2, 2, 0.0, 0, 0);
    FAIL() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("resolution"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace navigation_core
