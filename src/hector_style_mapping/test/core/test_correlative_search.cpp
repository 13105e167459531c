// The correlative search on its own: a scan put back where it was taken, from far off.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "hector_style_mapping/correlative_search.h"
#include "hector_style_mapping/multi_resolution_map.h"
#include "synthetic_world.h"

namespace hector_style_mapping {
namespace {

constexpr double kDegree = M_PI / 180.0;

struct Mapped {
  MultiResolutionMap map{MapperOptions{}};
  ScanPoints scan;
};

// The small maze mapped from `truth`, and a second scan taken there.
Mapped mappedAt(const Pose2D& truth) {
  const testing::SyntheticWorld world = testing::smallMaze();
  testing::LaserConfig laser;
  laser.range_noise_sigma = 0.01;
  std::mt19937 rng(21);
  Mapped m;
  m.map.updateByScan(world.scan(truth, laser, &rng), truth);
  m.map.updateByScan(world.scan(truth, laser, &rng), truth);
  m.scan = world.scan(truth, laser, &rng);
  return m;
}

TEST(CorrelativeSearch, FindsAScanHalfAMetreAndTwentyDegreesOff) {
  const Pose2D truth{1.0, 0.2, 0.3};
  const Mapped m = mappedAt(truth);
  const OccupancyGridMap& coarse = m.map.level(m.map.levels() - 1);
  const SearchResult found = correlativeSearch(coarse, m.scan, {1.4, -0.1, 0.3 + 20 * kDegree}, {0.6, 0.45});
  EXPECT_LT(std::hypot(found.pose.x - truth.x, found.pose.y - truth.y), coarse.resolution());
  EXPECT_LT(std::abs(angleDifference(found.pose.theta, truth.theta)), 2.0 * kDegree);
  EXPECT_GT(found.score, 0.5);  // most points on walls the map knows
  EXPECT_LE(found.score, 1.0);
}

TEST(CorrelativeSearch, StaysInsideItsWindow) {
  const Pose2D truth{1.0, 0.2, 0.3};
  const Mapped m = mappedAt(truth);
  const OccupancyGridMap& coarse = m.map.level(m.map.levels() - 1);
  const Pose2D centre{1.6, -0.4, 0.3};
  const SearchResult found = correlativeSearch(coarse, m.scan, centre, {0.2, 0.1});
  EXPECT_LE(std::abs(found.pose.x - centre.x), 0.2 + coarse.resolution());
  EXPECT_LE(std::abs(found.pose.y - centre.y), 0.2 + coarse.resolution());
  EXPECT_LE(std::abs(angleDifference(found.pose.theta, centre.theta)), 0.1 + 2 * kDegree);
  // 5 x 5 shifts of the 0.1 m cells, times the rotations.
  EXPECT_EQ(found.candidates % 25, 0);
}

TEST(CorrelativeSearch, AnEmptyScanOrAZeroWindowReturnsTheCentre) {
  const Mapped m = mappedAt({1.0, 0.2, 0.3});
  const Pose2D centre{1.3, 0.1, 0.2};
  const SearchResult none = correlativeSearch(m.map.finest(), ScanPoints{}, centre, {0.5, 0.5});
  EXPECT_EQ(none.candidates, 0);
  EXPECT_EQ(none.pose.x, centre.x);
  const SearchResult one = correlativeSearch(m.map.finest(), m.scan, centre, {0.0, 0.0});
  EXPECT_EQ(one.candidates, 1);
  EXPECT_EQ(one.pose.theta, centre.theta);
}

}  // namespace
}  // namespace hector_style_mapping
