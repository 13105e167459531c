#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "hector_style_mapping_core/multi_resolution_map.h"
#include "hector_style_mapping_core/scan_matcher.h"
#include "hector_style_mapping_core/slam_processor.h"
#include "hector_style_mapping_core/testing/synthetic_world.h"

namespace hector_style_mapping {
namespace {

using testing::LaserConfig;
using testing::SyntheticWorld;

using testing::kDegree;
using testing::robotOptions;

// Coarse to fine over all levels, as SlamProcessor does.
Pose2D matchCoarseToFine(const MultiResolutionMap& map, const ScanPoints& scan, Pose2D guess) {
  const ScanMatcher matcher;
  for (int level = map.levels() - 1; level >= 0; --level) {
    const int iterations =
        level == 0 ? SlamProcessor::kFinestLevelIterations : SlamProcessor::kCoarseLevelIterations;
    guess = matcher.match(map.level(level), scan, guess, iterations);
  }
  return guess;
}

struct Offset {
  double dx;
  double dy;
  double dtheta;
};

const Offset kOffsets[] = {{0.10, -0.08, 0.08}, {-0.12, 0.05, -0.06}, {0.05, 0.15, 0.0},
                           {0.0, 0.0, 0.12},    {-0.07, -0.10, -0.10}, {0.02, -0.02, 0.02}};

const Pose2D kTruePoses[] = {{0.0, 0.0, 0.0}, {2.9, -1.3, 2.1}, {-0.6, 2.2, -0.7}, {3.5, 1.6, -2.8}};

// Map from one scan at the true pose, then the matcher must bring an offset guess back to the truth (within
// `tolerance` metres and 0.5 degrees). Both scans can have range noise.
void expectRecoversOffsets(const MapperOptions& options, double world_rotation, double noise,
                           double tolerance = 0.01) {
  const SyntheticWorld world = testing::smallMaze().rotated(world_rotation);
  LaserConfig laser;
  laser.mount = {0.12, 0.0};
  std::mt19937 rng(42);
  double worst_translation = 0.0;
  double worst_rotation = 0.0;
  for (const Pose2D& maze_pose : kTruePoses) {
    const Pose2D truth{transformPoint({0, 0, world_rotation}, {maze_pose.x, maze_pose.y}).x(),
                       transformPoint({0, 0, world_rotation}, {maze_pose.x, maze_pose.y}).y(),
                       normalizeAngle(maze_pose.theta + world_rotation)};
    LaserConfig noisy = laser;
    noisy.range_noise_sigma = noise;
    MultiResolutionMap map(options);
    map.updateByScan(world.scan(truth, noisy, &rng), truth);
    const ScanPoints scan = world.scan(truth, noisy, &rng);
    for (const Offset& offset : kOffsets) {
      const Pose2D guess{truth.x + offset.dx, truth.y + offset.dy, truth.theta + offset.dtheta};
      const Pose2D matched = matchCoarseToFine(map, scan, guess);
      const double translation_error = std::hypot(matched.x - truth.x, matched.y - truth.y);
      const double rotation_error = std::abs(angleDifference(matched.theta, truth.theta));
      worst_translation = std::max(worst_translation, translation_error);
      worst_rotation = std::max(worst_rotation, rotation_error);
      EXPECT_LT(translation_error, tolerance) << "truth " << truth.x << "," << truth.y << "," << truth.theta
                                         << " offset " << offset.dx << "," << offset.dy << "," << offset.dtheta;
      EXPECT_LT(rotation_error, 0.5 * kDegree) << "truth " << truth.x << "," << truth.y << "," << truth.theta
                                               << " offset " << offset.dx << "," << offset.dy << ","
                                               << offset.dtheta;
    }
  }
  std::printf("  [resolution %.3f, %d levels, world turned %.2f rad, noise %.3f m] worst error %.1f mm, %.3f deg\n",
              options.map_resolution, options.map_multi_res_levels, world_rotation, noise,
              worst_translation * 1000.0, worst_rotation / kDegree);
}

TEST(ScanMatcher, RecoversOffsetsAtFiveCentimetresWithTwoLevels) {
  expectRecoversOffsets(robotOptions(), 0.37, 0.0);
  expectRecoversOffsets(robotOptions(), -1.1, 0.0);
  expectRecoversOffsets(robotOptions(), 0.37, 0.01);
  expectRecoversOffsets(robotOptions(), 0.0, 0.02);  // grid-aligned walls: see the next test for less noise
}

TEST(ScanMatcher, RecoversOffsetsAtDefaultResolutionWithThreeLevels) {
  expectRecoversOffsets(MapperOptions{}, 0.0, 0.0);
  expectRecoversOffsets(MapperOptions{}, -0.61, 0.0);
  expectRecoversOffsets(MapperOptions{}, 0.0, 0.01);
  expectRecoversOffsets(MapperOptions{}, -0.61, 0.02);
}

// One scan of walls parallel to the grid, with less range noise than a cell, cannot tell where inside its cells a
// wall lies: nearly every hit of a wall lands in the same column of cells, and the cost sum (1 - M)^2 is lowest
// with the points on those cells' centres. The truth can be up to half a cell from that optimum (15 mm here at
// 5 cm cells; a brute-force search finds no pose of lower cost nearer the truth). Walls at any other angle, or
// noise comparable to a cell, spread the hits over neighbouring cells and bring the error down to millimetres
// (the tests above); so do the many scans of a real map.
TEST(ScanMatcher, GridAlignedWallsFromOneSharpScanAreFoundWithinHalfACell) {
  expectRecoversOffsets(robotOptions(), 0.0, 0.0, 0.5 * robotOptions().map_resolution);
  expectRecoversOffsets(robotOptions(), 0.0, 0.01, 0.5 * robotOptions().map_resolution);
}

TEST(ScanMatcher, EmptyScanOrEmptyMapKeepsTheGuess) {
  const MultiResolutionMap map{MapperOptions{}};
  const ScanMatcher matcher;
  const Pose2D guess{0.3, -0.2, 0.1};
  Eigen::Matrix3d hessian = Eigen::Matrix3d::Ones();
  const ScanPoints empty;
  Pose2D result = matcher.match(map.finest(), empty, guess, 10, &hessian);
  EXPECT_EQ(result.x, guess.x);
  EXPECT_EQ(result.y, guess.y);
  EXPECT_EQ(result.theta, guess.theta);
  EXPECT_EQ(hessian, Eigen::Matrix3d::Zero());

  const ScanPoints scan = testing::smallMaze().scan(Pose2D{}, LaserConfig{});
  hessian = Eigen::Matrix3d::Ones();
  const ScanMatchResult details = matcher.matchWithDetails(map.finest(), scan, guess, 10);
  EXPECT_EQ(details.pose.x, guess.x);
  EXPECT_EQ(details.pose.y, guess.y);
  EXPECT_EQ(details.pose.theta, guess.theta);
  EXPECT_EQ(details.hessian, Eigen::Matrix3d::Zero());
  EXPECT_EQ(details.iterations, 0);
  EXPECT_EQ(details.point_count, static_cast<int>(scan.points.size()));
  EXPECT_DOUBLE_EQ(details.squared_residual_sum, static_cast<double>(scan.points.size()));
}

TEST(ScanMatcher, NonFinitePointsAreIgnored) {
  MultiResolutionMap map{MapperOptions{}};
  const SyntheticWorld world = testing::smallMaze();
  const ScanPoints scan = world.scan(Pose2D{}, LaserConfig{});
  map.updateByScan(scan, Pose2D{});
  ScanPoints polluted = scan;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  polluted.points.insert(polluted.points.begin() + 10, Eigen::Vector2d(nan, 1.0));
  polluted.points.insert(polluted.points.begin() + 100, Eigen::Vector2d(1.0, inf));
  polluted.points.emplace_back(-inf, nan);
  const ScanMatcher matcher;
  const Pose2D guess{0.05, -0.04, 0.03};
  const ScanMatchResult clean_result = matcher.matchWithDetails(map.finest(), scan, guess, 10);
  const ScanMatchResult polluted_result = matcher.matchWithDetails(map.finest(), polluted, guess, 10);
  EXPECT_EQ(polluted_result.point_count, clean_result.point_count);
  EXPECT_NEAR(polluted_result.pose.x, clean_result.pose.x, 1e-12);
  EXPECT_NEAR(polluted_result.pose.y, clean_result.pose.y, 1e-12);
  EXPECT_NEAR(polluted_result.pose.theta, clean_result.pose.theta, 1e-12);
  EXPECT_TRUE(polluted_result.hessian.isApprox(clean_result.hessian, 1e-12));
}

// H must be sum J^T J with J the derivative of M(S_i(xi)) by the pose: compare it with J from finite differences.
TEST(ScanMatcher, HessianIsSumOfJacobianProductsAtTheResult) {
  MultiResolutionMap map{MapperOptions{}};
  const SyntheticWorld world = testing::smallMaze().rotated(0.2);
  LaserConfig laser;
  laser.mount = {0.15, -0.05};
  const Pose2D truth{0.3, 0.2, 0.9};
  map.updateByScan(world.scan(truth, laser), truth);
  std::mt19937 rng(5);
  laser.range_noise_sigma = 0.01;
  const ScanPoints scan = world.scan(truth, laser, &rng);
  const ScanMatcher matcher;
  Eigen::Matrix3d hessian;
  const Pose2D result = matcher.match(map.finest(), scan, {0.33, 0.18, 0.93}, 10, &hessian);

  const OccupancyGridMap& level = map.finest();
  const auto value = [&](const Pose2D& pose, const Eigen::Vector2d& point) {
    return level.interpolate(transformPoint(pose, point));
  };
  const double h = 1e-7;
  Eigen::Matrix3d expected = Eigen::Matrix3d::Zero();
  for (const Eigen::Vector2d& point : scan.points) {
    Eigen::Vector3d jacobian;
    for (int k = 0; k < 3; ++k) {
      Pose2D plus = result, minus = result;
      (k == 0 ? plus.x : k == 1 ? plus.y : plus.theta) += h;
      (k == 0 ? minus.x : k == 1 ? minus.y : minus.theta) -= h;
      jacobian(k) = (value(plus, point) - value(minus, point)) / (2 * h);
    }
    expected += jacobian * jacobian.transpose();
  }
  EXPECT_TRUE(hessian.isApprox(hessian.transpose(), 1e-12));
  EXPECT_GT(hessian(0, 0), 1e3);
  EXPECT_LT((hessian - expected).norm(), 1e-3 * expected.norm()) << "H\n" << hessian << "\nexpected\n" << expected;
}

// A scan of one straight wall says nothing about the position along it: the matcher must correct the distance to
// the wall and leave the along-wall coordinate alone instead of inverting a singular H.
TEST(ScanMatcher, SingleWallLeavesTheUnconstrainedDirectionAlone) {
  OccupancyGridMap map(200, 200, 0.05, {-5.0, -5.0}, 0.4, 0.9);
  // A wall along y = 1.0 mapped from (0, 0) with dense rays, so every cell just below it is seen free too.
  ScanPoints mapping_scan;
  for (double x = -4.0; x <= 4.0; x += 0.01) {
    mapping_scan.points.emplace_back(x, 1.0);
  }
  map.updateByScan(mapping_scan, Pose2D{});
  ScanPoints scan;
  for (double x = -1.5; x <= 1.5; x += 0.02) {
    scan.points.emplace_back(x, 1.0);
  }
  const ScanMatcher matcher;
  const Pose2D guess{0.2, 0.03, 0.0};
  Eigen::Matrix3d hessian;
  const Pose2D result = matcher.match(map, scan, guess, 20, &hessian);
  EXPECT_EQ(hessian(0, 0), 0.0) << "the map should be exactly flat along the wall";
  EXPECT_TRUE(std::isfinite(result.x) && std::isfinite(result.y) && std::isfinite(result.theta));
  EXPECT_NEAR(result.x, guess.x, 1e-9);
  EXPECT_NEAR(result.y, 0.0, 0.025);  // within half a cell: the wall cell's centre is the best the map knows
  EXPECT_LT(std::abs(result.y), std::abs(guess.y));
  EXPECT_NEAR(result.theta, 0.0, 0.01);
}

TEST(ScanMatcher, SurfaceNormalHessianDropsGradientsAlongWalls) {
  // The dense one-wall map of SingleWallLeavesTheUnconstrainedDirectionAlone, but a slanted wall: its staircase of
  // cells gives the map gradient a component along the wall.
  OccupancyGridMap map(200, 200, 0.05, {-5.0, -5.0}, 0.4, 0.9);
  const Eigen::Vector2d along(std::cos(0.3), std::sin(0.3));
  const Eigen::Vector2d across(-along.y(), along.x());
  ScanPoints mapping_scan;
  for (double t = -4.0; t <= 4.0; t += 0.01) {
    mapping_scan.points.push_back(1.0 * across + t * along);
  }
  map.updateByScan(mapping_scan, Pose2D{});
  ScanPoints scan;
  for (double t = -2.0; t <= 2.0; t += 0.02) {
    scan.points.push_back(1.0 * across + t * along);
  }
  const ScanMatcher matcher;
  const Pose2D pose{0.004, -0.003, 0.001};
  const Eigen::Matrix3d plain = matcher.matchWithDetails(map, scan, pose, 0).hessian;
  const Eigen::Matrix3d projected = matcher.surfaceNormalHessian(map, scan, pose);
  const auto information = [](const Eigen::Matrix3d& h, const Eigen::Vector2d& direction) {
    return direction.dot(h.topLeftCorner<2, 2>() * direction);
  };
  std::printf("  plain H along %.3g across %.3g; projected along %.3g across %.3g\n", information(plain, along),
              information(plain, across), information(projected, along), information(projected, across));
  EXPECT_GT(information(plain, along), 1e-3 * information(plain, across)) << "the test map has no texture";
  EXPECT_LT(information(projected, along), 1e-4 * information(projected, across));
  EXPECT_NEAR(information(projected, across), information(plain, across), 0.2 * information(plain, across));

  // Clutter has no straight surfaces to fit: the full gradient is kept.
  ScanPoints clutter;
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> coordinate(-2.0, 2.0);
  for (int i = 0; i < 300; ++i) {
    clutter.points.emplace_back(coordinate(rng), coordinate(rng));
  }
  const Eigen::Matrix3d clutter_plain = matcher.matchWithDetails(map, clutter, pose, 0).hessian;
  ASSERT_GT(clutter_plain.trace(), 0.0);
  EXPECT_TRUE(matcher.surfaceNormalHessian(map, clutter, pose).isApprox(clutter_plain, 1e-12));
}

TEST(ScanMatcher, StepsAreClampedPerIteration) {
  MultiResolutionMap map{robotOptions()};
  const SyntheticWorld world = testing::smallMaze();
  const ScanPoints scan = world.scan(Pose2D{}, LaserConfig{});
  map.updateByScan(scan, Pose2D{});
  const ScanMatcher matcher;
  for (const Pose2D& guess : {Pose2D{0.0, 0.0, 0.5}, Pose2D{0.0, 0.0, -0.45}, Pose2D{0.3, -0.25, 0.0}}) {
    for (int level = 0; level < map.levels(); ++level) {
      const ScanMatchResult one_step = matcher.matchWithDetails(map.level(level), scan, guess, 1);
      EXPECT_LE(std::abs(angleDifference(one_step.pose.theta, guess.theta)), ScanMatcher::kMaxRotationStep + 1e-12);
      EXPECT_LE(std::hypot(one_step.pose.x - guess.x, one_step.pose.y - guess.y),
                ScanMatcher::kMaxTranslationStepCells * map.level(level).resolution() + 1e-12);
      EXPECT_LE(one_step.iterations, 1);
    }
  }
}

TEST(ScanMatcher, ZeroIterationsReturnsTheGuessWithItsHessian) {
  MultiResolutionMap map{MapperOptions{}};
  const ScanPoints scan = testing::smallMaze().scan(Pose2D{}, LaserConfig{});
  map.updateByScan(scan, Pose2D{});
  const ScanMatcher matcher;
  const Pose2D guess{0.01, 0.02, 0.01};
  Eigen::Matrix3d hessian;
  const Pose2D result = matcher.match(map.finest(), scan, guess, 0, &hessian);
  EXPECT_EQ(result.x, guess.x);
  EXPECT_EQ(result.y, guess.y);
  EXPECT_EQ(result.theta, guess.theta);
  EXPECT_GT(hessian.trace(), 0.0);
  const ScanMatchResult details = matcher.matchWithDetails(map.finest(), scan, guess, 0);
  EXPECT_EQ(details.hessian, hessian);
}

TEST(ScanMatcher, CostNeverRises) {
  MultiResolutionMap map{MapperOptions{}};
  const SyntheticWorld world = testing::smallMaze().rotated(1.1);
  std::mt19937 rng(9);
  LaserConfig laser;
  laser.range_noise_sigma = 0.02;
  const Pose2D truth{0.4, -0.2, 1.0};
  map.updateByScan(world.scan(truth, laser, &rng), truth);
  const ScanPoints scan = world.scan(truth, laser, &rng);
  const ScanMatcher matcher;
  Pose2D guess{truth.x + 0.04, truth.y - 0.05, truth.theta + 0.04};
  double previous_cost = matcher.matchWithDetails(map.finest(), scan, guess, 0).squared_residual_sum;
  for (int i = 0; i < 8; ++i) {
    const ScanMatchResult step = matcher.matchWithDetails(map.finest(), scan, guess, 1);
    EXPECT_LE(step.squared_residual_sum, previous_cost);
    previous_cost = step.squared_residual_sum;
    guess = step.pose;
  }
}

}  // namespace
}  // namespace hector_style_mapping
