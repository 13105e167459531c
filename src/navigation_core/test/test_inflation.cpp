// The inflation layer against costmap_2d's definition of its costs.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

#include "navigation_core/cost_values.h"
#include "navigation_core/inflation.h"

namespace navigation_core {
namespace {

constexpr double kResolution = 0.05;
constexpr double kInscribed = 0.09;  // m_robot's 0.24 x 0.18 m footprint

// costmap_2d's formula, written out independently of Inflation::costAt.
std::uint8_t expectedCost(double distance_m, const InflationOptions& o) {
  if (distance_m == 0) return 254;
  if (distance_m <= kInscribed) return 253;
  if (distance_m > std::ceil(o.inflation_radius / kResolution) * kResolution + 1e-9) return 0;
  return static_cast<std::uint8_t>(252 * std::exp(-o.cost_scaling_factor * (distance_m - kInscribed)));
}

TEST(Inflation, CostsAroundOneObstacleFollowTheFormula) {
  InflationOptions o;  // upstream defaults: 0.55 m, factor 10
  const Inflation inflation(o, kInscribed, kResolution);
  Costmap map(41, 41, kResolution, 0, 0);
  map.setCost(20, 20, kLethalObstacle);
  inflation.apply(map);
  int inflated = 0;
  for (unsigned y = 0; y < 41; ++y) {
    for (unsigned x = 0; x < 41; ++x) {
      const double d = kResolution * std::hypot(double(x) - 20, double(y) - 20);
      ASSERT_EQ(int(map.cost(x, y)), int(expectedCost(d, o))) << "cell " << x << ", " << y << " at " << d << " m";
      inflated += map.cost(x, y) > 0;
    }
  }
  // A disc of radius 11 cells: about pi 11^2 cells, fewer where the tail rounds down to 0.
  EXPECT_GT(inflated, 300);
  EXPECT_LT(inflated, 400);
  EXPECT_EQ(map.cost(20, 21), 253);  // 0.05 m: inside the inscribed radius
  EXPECT_EQ(map.cost(20, 22), 228);  // 0.10 m: 252 e^-0.1 = 228.02
}

TEST(Inflation, AWallInflatesByTheDistanceAcrossIt) {
  InflationOptions o;
  o.inflation_radius = 0.3;
  o.cost_scaling_factor = 5.0;
  const Inflation inflation(o, kInscribed, kResolution);
  Costmap map(30, 30, kResolution, 0, 0);
  for (unsigned x = 0; x < 30; ++x) map.setCost(x, 5, kLethalObstacle);
  inflation.apply(map);
  for (unsigned x = 0; x < 30; ++x) {
    for (unsigned y = 0; y < 30; ++y) {
      const double d = kResolution * std::abs(double(y) - 5);
      ASSERT_EQ(int(map.cost(x, y)), int(expectedCost(d, o))) << "cell " << x << ", " << y;
    }
  }
}

TEST(Inflation, NearestObstacleWinsBetweenTwo) {
  const InflationOptions o;
  const Inflation inflation(o, kInscribed, kResolution);
  Costmap map(60, 20, kResolution, 0, 0);
  map.setCost(10, 10, kLethalObstacle);
  map.setCost(30, 10, kLethalObstacle);
  inflation.apply(map);
  for (unsigned x = 0; x < 60; ++x) {
    const double d = kResolution * std::min(std::abs(double(x) - 10), std::abs(double(x) - 30));
    EXPECT_EQ(int(map.cost(x, 10)), int(expectedCost(d, o))) << "cell " << x;
  }
}

TEST(Inflation, UnknownCellsTakeOnlyInscribedCostsUnlessInflateUnknown) {
  for (const bool inflate_unknown : {false, true}) {
    InflationOptions o;
    o.inflate_unknown = inflate_unknown;
    const Inflation inflation(o, kInscribed, kResolution);
    Costmap map(21, 21, kResolution, 0, 0, kNoInformation);
    map.setCost(10, 10, kLethalObstacle);
    inflation.apply(map);
    EXPECT_EQ(map.cost(10, 11), kInscribedInflatedObstacle);         // 0.05 m
    EXPECT_EQ(map.cost(10, 15), inflate_unknown ? 50 : kNoInformation);  // 0.25 m: 252 e^-1.6 = 50.9
  }
}

TEST(Inflation, AHigherCostAlreadyThereStays) {
  const Inflation inflation(InflationOptions(), kInscribed, kResolution);
  Costmap map(21, 21, kResolution, 0, 0);
  map.setCost(10, 10, kLethalObstacle);
  map.setCost(10, 17, 200);  // 0.35 m away: inflation alone would give 252 e^-2.6 = 18
  map.setCost(10, 18, 1);    // 0.40 m: inflation gives 11
  inflation.apply(map);
  EXPECT_EQ(map.cost(10, 17), 200);
  EXPECT_EQ(map.cost(10, 18), 11);
}

TEST(Inflation, NegativeParametersAreNamed) {
  InflationOptions o;
  o.cost_scaling_factor = -1;
  try {
    Inflation(o, kInscribed, kResolution);
    FAIL() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("cost_scaling_factor"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace navigation_core
