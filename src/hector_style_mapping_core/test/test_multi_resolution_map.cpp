#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "hector_style_mapping_core/multi_resolution_map.h"

namespace hector_style_mapping {
namespace {

MapperOptions smallOptions() {
  MapperOptions options;
  options.map_resolution = 0.05;
  options.map_size = 128;  // 6.4 m
  options.map_start_x = 0.25;
  options.map_start_y = 0.625;
  options.map_multi_res_levels = 3;
  return options;
}

// Random laser scans from random poses until the map holds a patchwork of unknown, free, occupied and
// multiply-updated cells.
void scribble(MultiResolutionMap* map, std::mt19937* rng, int scans) {
  const MapperOptions options = smallOptions();
  const double side = options.map_size * options.map_resolution;
  const Eigen::Vector2d low(-options.map_start_x * side, -options.map_start_y * side);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int s = 0; s < scans; ++s) {
    const Pose2D pose{low.x() + side * unit(*rng), low.y() + side * unit(*rng), 2.0 * M_PI * unit(*rng)};
    ScanPoints scan;
    scan.origin = {0.1 * unit(*rng), 0.0};
    const int rays = 5 + static_cast<int>(40 * unit(*rng));
    for (int r = 0; r < rays; ++r) {
      const double angle = 2.0 * M_PI * unit(*rng);
      const double range = 0.2 + 2.5 * unit(*rng);
      scan.points.emplace_back(range * std::cos(angle), range * std::sin(angle));
    }
    map->updateByScan(scan, pose);
  }
}

TEST(MultiResolutionMap, LevelsHalveResolutionOverTheSameArea) {
  const MapperOptions options = smallOptions();
  const MultiResolutionMap map(options);
  ASSERT_EQ(map.levels(), 3);
  const Eigen::Vector2d expected_origin(-0.25 * 6.4, -0.625 * 6.4);
  for (int i = 0; i < map.levels(); ++i) {
    const OccupancyGridMap& level = map.level(i);
    EXPECT_EQ(level.sizeX(), 128 >> i);
    EXPECT_EQ(level.sizeY(), 128 >> i);
    EXPECT_DOUBLE_EQ(level.resolution(), 0.05 * (1 << i));
    EXPECT_TRUE(level.origin().isApprox(expected_origin));
    EXPECT_DOUBLE_EQ(level.sizeX() * level.resolution(), 6.4);
  }
  EXPECT_EQ(&map.finest(), &map.level(0));
  EXPECT_THROW(map.level(3), std::out_of_range);
  EXPECT_THROW(map.level(-1), std::out_of_range);
}

TEST(MultiResolutionMap, MapFrameOriginLiesAtTheStartFraction) {
  const MultiResolutionMap defaults{MapperOptions{}};
  // 1024 cells of 0.025 m with the origin in the middle: (0, 0) is the corner of cell (512, 512).
  EXPECT_EQ(defaults.level(0).cellOf({1e-9, 1e-9}), Eigen::Vector2i(512, 512));
  EXPECT_EQ(defaults.level(2).cellOf({1e-9, 1e-9}), Eigen::Vector2i(128, 128));
  const MultiResolutionMap shifted(smallOptions());
  EXPECT_EQ(shifted.level(0).cellOf({1e-9, 1e-9}), Eigen::Vector2i(32, 80));
}

TEST(MultiResolutionMap, UpdateReachesEveryLevelAndClearEmptiesThem) {
  MultiResolutionMap map(smallOptions());
  ScanPoints scan;
  scan.points = {{1.0, 0.3}, {-0.4, 1.1}};
  map.updateByScan(scan, Pose2D{0.2, -0.1, 0.3});
  const Eigen::Vector2d hit = transformPoint(Pose2D{0.2, -0.1, 0.3}, {1.0, 0.3});
  for (int i = 0; i < map.levels(); ++i) {
    const Eigen::Vector2i cell = map.level(i).cellOf(hit);
    EXPECT_TRUE(map.level(i).isOccupied(cell.x(), cell.y())) << "level " << i;
    const Eigen::Vector2i base = map.level(i).cellOf({0.2, -0.1});
    EXPECT_TRUE(map.level(i).isFree(base.x(), base.y())) << "level " << i;
  }
  map.clear();
  for (int i = 0; i < map.levels(); ++i) {
    std::vector<int8_t> data;
    map.level(i).toOccupancyData(&data);
    for (const int8_t state : data) {
      ASSERT_EQ(state, -1) << "level " << i;
    }
  }
}

// Value and gradient of the bilinear interpolation against central finite differences, at random points away
// from the lines through cell centres (where the gradient jumps), on several random maps, at every level.
TEST(MultiResolutionMap, InterpolationGradientMatchesFiniteDifferencesAtEveryLevel) {
  std::mt19937 rng(2011);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int trial = 0; trial < 4; ++trial) {
    MultiResolutionMap map(smallOptions());
    scribble(&map, &rng, 30 + 20 * trial);
    for (int i = 0; i < map.levels(); ++i) {
      const OccupancyGridMap& level = map.level(i);
      const double side = level.sizeX() * level.resolution();
      const double h = 1e-6 * level.resolution();
      int checked = 0;
      int with_slope = 0;
      while (checked < 3000) {
        // Points slightly beyond the map too: the gradient must stay consistent across its edge.
        const Eigen::Vector2d p = level.origin() + Eigen::Vector2d(unit(rng), unit(rng)) * (side * 1.02) -
                                  Eigen::Vector2d::Constant(side * 0.01);
        const Eigen::Vector2d centred = (p - level.origin()) / level.resolution() - Eigen::Vector2d(0.5, 0.5);
        const Eigen::Vector2d fraction = centred.array() - centred.array().floor();
        if ((fraction.array() < 0.01).any() || (fraction.array() > 0.99).any()) {
          continue;
        }
        ++checked;
        Eigen::Vector2d gradient;
        const double value = level.interpolate(p, &gradient);
        EXPECT_EQ(level.interpolate(p), value);
        const double dx = (level.interpolate(p + Eigen::Vector2d(h, 0)) - level.interpolate(p - Eigen::Vector2d(h, 0)));
        const double dy = (level.interpolate(p + Eigen::Vector2d(0, h)) - level.interpolate(p - Eigen::Vector2d(0, h)));
        // Values are floats in the map, so compare with a tolerance scaled to the possible slope (1 / resolution).
        const double tolerance = 1e-6 / level.resolution() + 1e-4 * gradient.norm();
        ASSERT_NEAR(gradient.x(), dx / (2 * h), tolerance) << "level " << i << " at " << p.transpose();
        ASSERT_NEAR(gradient.y(), dy / (2 * h), tolerance) << "level " << i << " at " << p.transpose();
        with_slope += gradient.norm() > 0.1 ? 1 : 0;
      }
      EXPECT_GT(with_slope, 300) << "level " << i << ": the random map is too flat to test anything";
    }
  }
}

}  // namespace
}  // namespace hector_style_mapping
