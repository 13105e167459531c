#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <random>
#include <stdexcept>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "hector_style_mapping_core/occupancy_grid_map.h"

namespace hector_style_mapping {
namespace {

constexpr double kNan = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

// 40 x 30 cells of 0.1 m; the map frame's origin is the lower-left corner of cell (20, 15).
OccupancyGridMap smallMap() { return OccupancyGridMap(40, 30, 0.1, {-2.0, -1.5}, 0.4, 0.9); }

ScanPoints rays(const Eigen::Vector2d& origin, std::vector<Eigen::Vector2d> ends) {
  ScanPoints scan;
  scan.origin = origin;
  scan.points = std::move(ends);
  return scan;
}

std::vector<Eigen::Vector2i> updatedCells(const OccupancyGridMap& map) {
  std::vector<Eigen::Vector2i> cells;
  for (int y = 0; y < map.sizeY(); ++y) {
    for (int x = 0; x < map.sizeX(); ++x) {
      if (!map.isUnknown(x, y)) {
        cells.emplace_back(x, y);
      }
    }
  }
  return cells;
}

// Log-odds after `count` equal updates, accumulated and clamped in float as the map does.
double afterUpdates(int count, float change) {
  float log_odds = 0.0f;
  for (int i = 0; i < count; ++i) {
    log_odds = std::clamp(log_odds + change, -OccupancyGridMap::kLogOddsLimit, OccupancyGridMap::kLogOddsLimit);
  }
  return log_odds;
}

TEST(OccupancyGridMap, GeometryPutsValuesAtCellCentres) {
  const OccupancyGridMap map = smallMap();
  EXPECT_EQ(map.sizeX(), 40);
  EXPECT_EQ(map.sizeY(), 30);
  EXPECT_DOUBLE_EQ(map.resolution(), 0.1);
  EXPECT_EQ(map.origin(), Eigen::Vector2d(-2.0, -1.5));
  EXPECT_EQ(map.cellOf({0.0, 0.0}), Eigen::Vector2i(20, 15));
  EXPECT_EQ(map.cellOf({-0.001, -0.001}), Eigen::Vector2i(19, 14));
  EXPECT_EQ(map.cellOf({-2.0, -1.5}), Eigen::Vector2i(0, 0));
  EXPECT_EQ(map.cellOf({-2.05, 5.0}), Eigen::Vector2i(-1, 65));
  EXPECT_EQ(map.cellOf({kNan, 0.0}), Eigen::Vector2i(-1, -1));
  EXPECT_TRUE(map.cellCenter(20, 15).isApprox(Eigen::Vector2d(0.05, 0.05)));
  EXPECT_TRUE(map.cellCenter(0, 0).isApprox(Eigen::Vector2d(-1.95, -1.45)));
  for (int x = 0; x < map.sizeX(); x += 7) {
    for (int y = 0; y < map.sizeY(); y += 5) {
      EXPECT_EQ(map.cellOf(map.cellCenter(x, y)), Eigen::Vector2i(x, y));
    }
  }
}

TEST(OccupancyGridMap, StartsUnknownEverywhere) {
  const OccupancyGridMap map = smallMap();
  std::vector<int8_t> data;
  map.toOccupancyData(&data);
  ASSERT_EQ(data.size(), 40u * 30u);
  EXPECT_TRUE(std::all_of(data.begin(), data.end(), [](int8_t state) { return state == -1; }));
  EXPECT_TRUE(map.isUnknown(3, 4));
  EXPECT_FALSE(map.isFree(3, 4));
  EXPECT_FALSE(map.isOccupied(3, 4));
  EXPECT_EQ(map.probability(3, 4), 0.5);
  Eigen::Vector2d gradient(1.0, 1.0);
  EXPECT_EQ(map.interpolate({0.3, 0.2}, &gradient), 0.0);
  EXPECT_EQ(gradient, Eigen::Vector2d::Zero());
}

TEST(OccupancyGridMap, RejectsBadConstruction) {
  EXPECT_THROW(OccupancyGridMap(0, 10, 0.1, {0, 0}, 0.4, 0.9), std::invalid_argument);
  EXPECT_THROW(OccupancyGridMap(10, -1, 0.1, {0, 0}, 0.4, 0.9), std::invalid_argument);
  EXPECT_THROW(OccupancyGridMap(10, 10, 0.0, {0, 0}, 0.4, 0.9), std::invalid_argument);
  EXPECT_THROW(OccupancyGridMap(10, 10, 0.1, {kNan, 0}, 0.4, 0.9), std::invalid_argument);
  EXPECT_THROW(OccupancyGridMap(10, 10, 0.1, {0, 0}, 0.0, 0.9), std::invalid_argument);
  EXPECT_THROW(OccupancyGridMap(10, 10, 0.1, {0, 0}, 0.4, 1.0), std::invalid_argument);
  EXPECT_THROW(OccupancyGridMap(100000, 100000, 0.1, {0, 0}, 0.4, 0.9), std::invalid_argument);
}

TEST(OccupancyGridMap, LogOddsOfUpdateFactors) {
  const OccupancyGridMap map = smallMap();
  EXPECT_NEAR(map.logOddsFreeUpdate(), std::log(0.4 / 0.6), 1e-6);
  EXPECT_NEAR(map.logOddsOccupiedUpdate(), std::log(0.9 / 0.1), 1e-6);
}

TEST(OccupancyGridMap, RepeatedUpdatesAddLogOddsAndClamp) {
  OccupancyGridMap map = smallMap();
  const float free_change = static_cast<float>(map.logOddsFreeUpdate());
  const float hit_change = static_cast<float>(map.logOddsOccupiedUpdate());
  // One ray along row 15 from cell 20 to cell 30: cells 20..29 free, 30 hit.
  const ScanPoints scan = rays(map.cellCenter(20, 15), {map.cellCenter(30, 15)});
  for (int k = 1; k <= 12; ++k) {
    map.updateByScan(scan, Pose2D{});
    const double hit = afterUpdates(k, hit_change);
    const double free = afterUpdates(k, free_change);
    EXPECT_FLOAT_EQ(map.logOdds(30, 15), hit) << k;
    EXPECT_FLOAT_EQ(map.logOdds(25, 15), free) << k;
    EXPECT_NEAR(map.probability(30, 15), 1.0 / (1.0 + std::exp(-hit)), 1e-12) << k;
    EXPECT_NEAR(map.probability(25, 15), 1.0 / (1.0 + std::exp(-free)), 1e-12) << k;
    // The matcher sees the same probability at the cell centre.
    EXPECT_NEAR(map.interpolate(map.cellCenter(30, 15)), map.probability(30, 15), 1e-6) << k;
    EXPECT_NEAR(map.interpolate(map.cellCenter(25, 15)), map.probability(25, 15), 1e-6) << k;
  }
  EXPECT_FLOAT_EQ(map.logOdds(30, 15), OccupancyGridMap::kLogOddsLimit);
  EXPECT_FLOAT_EQ(map.logOdds(25, 15), -OccupancyGridMap::kLogOddsLimit);
  EXPECT_TRUE(map.isOccupied(30, 15));
  EXPECT_TRUE(map.isFree(25, 15));
  EXPECT_NEAR(map.probability(30, 15), 1.0 / (1.0 + std::exp(-3.5)), 1e-7);
}

TEST(OccupancyGridMap, ClampedCellsCanChangeTheirMind) {
  OccupancyGridMap map = smallMap();
  const ScanPoints long_ray = rays(map.cellCenter(20, 15), {map.cellCenter(35, 15)});
  const ScanPoints short_ray = rays(map.cellCenter(20, 15), {map.cellCenter(30, 15)});
  for (int k = 0; k < 30; ++k) {
    map.updateByScan(long_ray, Pose2D{});  // cell 30 becomes as free as it gets
  }
  map.updateByScan(short_ray, Pose2D{});
  EXPECT_TRUE(map.isFree(30, 15)) << "one hit must not flip the most certain free cell";
  map.updateByScan(short_ray, Pose2D{});
  EXPECT_TRUE(map.isOccupied(30, 15)) << "two hits must";

  for (int k = 0; k < 30; ++k) {
    map.updateByScan(short_ray, Pose2D{});  // now as occupied as it gets
  }
  for (int k = 0; k < 8; ++k) {
    map.updateByScan(long_ray, Pose2D{});
  }
  EXPECT_TRUE(map.isOccupied(30, 15)) << "eight misses must not clear the most certain wall";
  map.updateByScan(long_ray, Pose2D{});
  EXPECT_TRUE(map.isFree(30, 15)) << "nine must";
}

struct Offset {
  int dx;
  int dy;
};

TEST(OccupancyGridMap, BresenhamRaysInAllOctants) {
  const Offset offsets[] = {{7, 3},   {3, 7},   {-3, 7}, {-7, 3},  {-7, -3}, {-3, -7}, {3, -7}, {7, -3},
                            {9, 0},   {0, 9},   {-9, 0}, {0, -9},  {5, 5},   {-5, 5},  {-5, -5}, {5, -5},
                            {14, 1},  {1, -14}, {-1, 1}, {1, 0},   {13, 11}, {-11, -13}};
  const Eigen::Vector2i start(20, 15);
  for (const Offset& offset : offsets) {
    OccupancyGridMap map = smallMap();
    const Eigen::Vector2i end = start + Eigen::Vector2i(offset.dx, offset.dy);
    // End point off the cell centre: the ray must still end in the cell that contains it.
    const Eigen::Vector2d end_point = map.cellCenter(end.x(), end.y()) + Eigen::Vector2d(0.03, -0.04);
    map.updateByScan(rays(map.cellCenter(start.x(), start.y()) + Eigen::Vector2d(-0.02, 0.01), {end_point}),
                     Pose2D{});

    const std::vector<Eigen::Vector2i> cells = updatedCells(map);
    const bool x_major = std::abs(offset.dx) >= std::abs(offset.dy);
    const int major_length = std::max(std::abs(offset.dx), std::abs(offset.dy));
    ASSERT_EQ(static_cast<int>(cells.size()), major_length + 1) << offset.dx << "," << offset.dy;

    // One cell per step along the major axis, each within half a cell of the ideal line, 8-connected.
    std::map<int, int> minor_by_major;
    for (const Eigen::Vector2i& cell : cells) {
      const int major = x_major ? cell.x() - start.x() : cell.y() - start.y();
      const int minor = x_major ? cell.y() - start.y() : cell.x() - start.x();
      EXPECT_TRUE(minor_by_major.emplace(major, minor).second) << "two cells in one column";
      const double major_delta = x_major ? offset.dx : offset.dy;
      const double minor_delta = x_major ? offset.dy : offset.dx;
      EXPECT_LE(std::abs(minor - major * minor_delta / major_delta), 0.5 + 1e-9);
      if (cell == end) {
        EXPECT_EQ(map.logOdds(cell.x(), cell.y()), map.logOddsOccupiedUpdate());
        EXPECT_TRUE(map.isOccupied(cell.x(), cell.y()));
      } else {
        EXPECT_FLOAT_EQ(map.logOdds(cell.x(), cell.y()), map.logOddsFreeUpdate());
        EXPECT_TRUE(map.isFree(cell.x(), cell.y()));
      }
    }
    const int major_sign = (x_major ? offset.dx : offset.dy) > 0 ? 1 : -1;
    int previous_minor = 0;
    for (int k = 0; k <= major_length; ++k) {
      const auto found = minor_by_major.find(k * major_sign);
      ASSERT_NE(found, minor_by_major.end()) << "gap at step " << k;
      EXPECT_LE(std::abs(found->second - previous_minor), 1);
      previous_minor = found->second;
    }
    EXPECT_EQ(minor_by_major[0], 0) << "the laser's cell is on the ray";
  }
}

TEST(OccupancyGridMap, OneScanUpdatesEachCellOnce) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> x_dist(-1.99, 1.99);
  std::uniform_real_distribution<double> y_dist(-1.49, 1.49);
  OccupancyGridMap map = smallMap();
  ScanPoints scan = rays({0.13, -0.07}, {});
  for (int i = 0; i < 400; ++i) {
    scan.points.emplace_back(x_dist(rng), y_dist(rng));
  }
  map.updateByScan(scan, Pose2D{});
  int free_cells = 0;
  for (const Eigen::Vector2i& cell : updatedCells(map)) {
    const double log_odds = map.logOdds(cell.x(), cell.y());
    const bool is_end = std::any_of(scan.points.begin(), scan.points.end(),
                                    [&](const Eigen::Vector2d& p) { return map.cellOf(p) == cell; });
    EXPECT_FLOAT_EQ(log_odds, is_end ? map.logOddsOccupiedUpdate() : map.logOddsFreeUpdate());
    free_cells += is_end ? 0 : 1;
  }
  EXPECT_GT(free_cells, 300);
}

TEST(OccupancyGridMap, OccupiedMarkWinsWhicheverRayComesFirst) {
  for (const bool hit_first : {true, false}) {
    OccupancyGridMap map = smallMap();
    const Eigen::Vector2d hit = map.cellCenter(25, 15);
    const Eigen::Vector2d through = map.cellCenter(32, 15);
    map.updateByScan(rays(map.cellCenter(20, 15), hit_first ? std::vector<Eigen::Vector2d>{hit, through}
                                                            : std::vector<Eigen::Vector2d>{through, hit}),
                     Pose2D{});
    EXPECT_EQ(map.logOdds(25, 15), map.logOddsOccupiedUpdate());
    EXPECT_FLOAT_EQ(map.logOdds(28, 15), map.logOddsFreeUpdate());
    EXPECT_EQ(map.logOdds(32, 15), map.logOddsOccupiedUpdate());
  }
}

TEST(OccupancyGridMap, FreeRaysClearTheirWholeLengthAndMarkNoEnd) {
  OccupancyGridMap map = smallMap();
  ScanPoints scan = rays(map.cellCenter(20, 15), {map.cellCenter(20, 20)});
  scan.free_rays = {map.cellCenter(26, 15), {kNan, 0.0}};
  map.updateByScan(scan, Pose2D{});
  EXPECT_EQ(updatedCells(map).size(), 12u);  // 6 of the hit's column, 6 of the free ray's row (one shared)
  EXPECT_TRUE(map.isOccupied(20, 20));
  for (int x = 21; x <= 26; ++x) EXPECT_TRUE(map.isFree(x, 15)) << x;
  EXPECT_TRUE(map.isUnknown(27, 15));
}

TEST(OccupancyGridMap, LastUpdateListsItsCellsAndWhichWereHits) {
  OccupancyGridMap map = smallMap();
  map.updateByScan(rays(map.cellCenter(20, 15), {map.cellCenter(23, 15)}), Pose2D{});
  map.updateByScan(rays(map.cellCenter(20, 15), {map.cellCenter(20, 17)}), Pose2D{});
  std::map<std::pair<int, int>, bool> last;  // (x, y) -> marked occupied
  for (const int index : map.lastUpdatedCells())
    last[{index % map.sizeX(), index / map.sizeX()}] = map.lastUpdateMarkedOccupied(index);
  const std::map<std::pair<int, int>, bool> expected{{{20, 15}, false}, {{20, 16}, false}, {{20, 17}, true}};
  EXPECT_EQ(last, expected);
  map.clear();
  EXPECT_TRUE(map.lastUpdatedCells().empty());
}

TEST(OccupancyGridMap, ZeroLengthRayMarksItsCellOccupied) {
  OccupancyGridMap map = smallMap();
  map.updateByScan(rays({0.01, 0.02}, {{0.08, 0.07}}), Pose2D{});
  const std::vector<Eigen::Vector2i> cells = updatedCells(map);
  ASSERT_EQ(cells.size(), 1u);
  EXPECT_EQ(cells[0], Eigen::Vector2i(20, 15));
  EXPECT_EQ(map.logOdds(20, 15), map.logOddsOccupiedUpdate());
}

TEST(OccupancyGridMap, RayLeavingTheMapIsTracedToTheEdgeWithoutHit) {
  OccupancyGridMap map = smallMap();
  map.updateByScan(rays(map.cellCenter(20, 15), {{10.0, 0.05}}), Pose2D{});
  const std::vector<Eigen::Vector2i> cells = updatedCells(map);
  EXPECT_EQ(cells.size(), 20u);  // columns 20 .. 39 of row 15
  for (const Eigen::Vector2i& cell : cells) {
    EXPECT_EQ(cell.y(), 15);
    EXPECT_TRUE(map.isFree(cell.x(), cell.y()));
  }
  EXPECT_TRUE(map.isFree(39, 15));
}

TEST(OccupancyGridMap, RayEnteringTheMapIsTracedFromTheEdge) {
  OccupancyGridMap map = smallMap();
  map.updateByScan(rays({-5.0, 0.05}, {map.cellCenter(25, 15)}), Pose2D{});
  const std::vector<Eigen::Vector2i> cells = updatedCells(map);
  EXPECT_EQ(cells.size(), 26u);  // columns 0 .. 25 of row 15
  for (int x = 0; x < 25; ++x) {
    EXPECT_TRUE(map.isFree(x, 15)) << x;
  }
  EXPECT_TRUE(map.isOccupied(25, 15));
}

TEST(OccupancyGridMap, RayCrossingOrMissingTheMapAndHugeOrBadPoints) {
  OccupancyGridMap map = smallMap();
  map.updateByScan(rays({-5.0, 0.05}, {{5.0, 0.05}}), Pose2D{});  // crosses the whole map
  EXPECT_EQ(updatedCells(map).size(), 40u);
  for (int x = 0; x < 40; ++x) {
    EXPECT_TRUE(map.isFree(x, 15)) << x;
  }
  map.clear();
  map.updateByScan(rays({-5.0, 10.0}, {{5.0, 10.0}, {-5.0, -10.0}}), Pose2D{});  // misses it
  EXPECT_TRUE(updatedCells(map).empty());

  map.updateByScan(rays({0.05, 0.05}, {{1e12, 3e11}, {-1e300, 1e300}, {kNan, 1.0}, {kInf, 0.0}, {0.0, -kInf}}),
                   Pose2D{});
  const std::vector<Eigen::Vector2i> cells = updatedCells(map);
  ASSERT_FALSE(cells.empty());
  for (const Eigen::Vector2i& cell : cells) {
    EXPECT_TRUE(map.isFree(cell.x(), cell.y()));
  }
  EXPECT_TRUE(map.isFree(39, 20) || map.isFree(39, 19) || map.isFree(39, 21));  // left through the right edge

  // A laser outside the map whose rays never enter it, and a non-finite laser origin.
  map.clear();
  map.updateByScan(rays({100.0, 100.0}, {{101.0, 100.0}}), Pose2D{});
  map.updateByScan(rays({kNan, 0.0}, {{0.5, 0.5}}), Pose2D{});
  map.updateByScan(rays({0.0, 0.0}, {{0.5, 0.5}}), Pose2D{0.0, 0.0, kNan});
  EXPECT_TRUE(updatedCells(map).empty());
}

TEST(OccupancyGridMap, NonFinitePointsAreSkipped) {
  OccupancyGridMap with_bad = smallMap();
  OccupancyGridMap without = smallMap();
  const Eigen::Vector2d good(0.73, -0.41);
  with_bad.updateByScan(rays({0.0, 0.0}, {{kNan, 0.3}, good, {0.2, kInf}, {-kInf, kNan}}), Pose2D{});
  without.updateByScan(rays({0.0, 0.0}, {good}), Pose2D{});
  std::vector<int8_t> a, b;
  with_bad.toOccupancyData(&a);
  without.toOccupancyData(&b);
  EXPECT_EQ(a, b);
  EXPECT_EQ(updatedCells(with_bad).size(), updatedCells(without).size());
}

TEST(OccupancyGridMap, ScanIsPlacedByThePose) {
  OccupancyGridMap map = smallMap();
  // Laser mounted 0.2 m ahead of the base; base at (0.5, -0.3) facing +y: the laser sits at (0.5, -0.1) and a
  // point 0.6 m ahead of the base lies at (0.5, 0.3).
  map.updateByScan(rays({0.2, 0.0}, {{0.6, 0.0}}), Pose2D{0.5, -0.3, M_PI / 2});
  const Eigen::Vector2i laser = map.cellOf({0.5 + 1e-9, -0.1 + 1e-9});
  const Eigen::Vector2i hit = map.cellOf({0.5 + 1e-9, 0.3 + 1e-9});
  EXPECT_TRUE(map.isOccupied(hit.x(), hit.y()));
  EXPECT_TRUE(map.isFree(laser.x(), laser.y()));
  EXPECT_EQ(updatedCells(map).size(), static_cast<std::size_t>(hit.y() - laser.y() + 1));
}

TEST(OccupancyGridMap, OccupancyDataIsRowMajor) {
  OccupancyGridMap map(20, 10, 0.1, {0.0, 0.0}, 0.4, 0.9);
  // Ray from cell (1, 2) to cell (5, 2): cells 1..4 free, 5 occupied, in row 2.
  map.updateByScan(rays(map.cellCenter(1, 2), {map.cellCenter(5, 2)}), Pose2D{});
  std::vector<int8_t> data{1, 2, 3};  // stale content must be replaced
  map.toOccupancyData(&data);
  ASSERT_EQ(data.size(), 200u);
  EXPECT_EQ(data[2 * 20 + 5], 100);
  for (int x = 1; x <= 4; ++x) {
    EXPECT_EQ(data[2 * 20 + x], 0) << x;
  }
  EXPECT_EQ(data[5 * 2 + 2], -1);  // the transposed index stays unknown
  EXPECT_EQ(std::count(data.begin(), data.end(), -1), 200 - 5);
}

TEST(OccupancyGridMap, QueriesOutsideTheMapReadUnknown) {
  OccupancyGridMap map = smallMap();
  map.updateByScan(rays(map.cellCenter(0, 0), {map.cellCenter(39, 29)}), Pose2D{});
  for (const Eigen::Vector2i& cell : {Eigen::Vector2i(-1, 0), Eigen::Vector2i(0, -1), Eigen::Vector2i(40, 0),
                                      Eigen::Vector2i(0, 30), Eigen::Vector2i(1000000, -1000000)}) {
    EXPECT_TRUE(map.isUnknown(cell.x(), cell.y()));
    EXPECT_FALSE(map.isFree(cell.x(), cell.y()));
    EXPECT_FALSE(map.isOccupied(cell.x(), cell.y()));
    EXPECT_EQ(map.probability(cell.x(), cell.y()), 0.5);
    EXPECT_EQ(map.logOdds(cell.x(), cell.y()), 0.0);
  }
}

TEST(OccupancyGridMap, ClearForgetsEverything) {
  OccupancyGridMap map = smallMap();
  map.updateByScan(rays({0.0, 0.0}, {{1.0, 1.0}, {-1.5, 0.3}}), Pose2D{});
  ASSERT_FALSE(updatedCells(map).empty());
  map.clear();
  EXPECT_TRUE(updatedCells(map).empty());
  EXPECT_EQ(map.interpolate({1.0, 1.0}), 0.0);
  // And it maps again as new.
  map.updateByScan(rays(map.cellCenter(20, 15), {map.cellCenter(30, 15)}), Pose2D{});
  EXPECT_EQ(map.logOdds(30, 15), map.logOddsOccupiedUpdate());
}

TEST(OccupancyGridMap, InterpolationAtCellCentresIsTheCellValue) {
  OccupancyGridMap map = smallMap();
  const ScanPoints scan = rays({0.0, 0.0}, {{1.37, 0.91}, {-1.2, 0.4}, {0.33, -1.2}});
  map.updateByScan(scan, Pose2D{});
  map.updateByScan(rays({0.0, 0.0}, {{1.37, 0.2}}), Pose2D{});  // some cells get two updates
  for (int y = 0; y < map.sizeY(); ++y) {
    for (int x = 0; x < map.sizeX(); ++x) {
      const double expected = map.isUnknown(x, y) ? 0.0 : map.probability(x, y);
      ASSERT_NEAR(map.interpolate(map.cellCenter(x, y)), expected, 1e-6) << x << "," << y;
    }
  }
  // The hit cell's value peaks at its centre, not at a corner.
  const Eigen::Vector2i hit = map.cellOf({1.37, 0.91});
  const Eigen::Vector2d centre = map.cellCenter(hit.x(), hit.y());
  const double at_centre = map.interpolate(centre);
  EXPECT_GT(at_centre, map.interpolate(centre + Eigen::Vector2d(0.03, 0.0)));
  EXPECT_GT(at_centre, map.interpolate(centre + Eigen::Vector2d(-0.03, 0.0)));
  EXPECT_GT(at_centre, map.interpolate(centre + Eigen::Vector2d(0.0, 0.03)));
  EXPECT_GT(at_centre, map.interpolate(centre + Eigen::Vector2d(0.0, -0.03)));
}

TEST(OccupancyGridMap, InterpolationBlendsTheFourSurroundingCentres) {
  OccupancyGridMap map = smallMap();
  map.updateByScan(rays({0.0, 0.0}, {{0.75, 0.35}, {-0.6, 0.8}, {0.2, -0.9}, {0.78, 0.41}}), Pose2D{});
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> x_dist(-1.9, 1.9);
  std::uniform_real_distribution<double> y_dist(-1.4, 1.4);
  const auto value = [&](int x, int y) { return map.isUnknown(x, y) ? 0.0 : map.probability(x, y); };
  for (int i = 0; i < 2000; ++i) {
    const Eigen::Vector2d p(x_dist(rng), y_dist(rng));
    const double u = (p.x() - map.origin().x()) / map.resolution() - 0.5;
    const double v = (p.y() - map.origin().y()) / map.resolution() - 0.5;
    const int x = static_cast<int>(std::floor(u));
    const int y = static_cast<int>(std::floor(v));
    const double fx = u - x;
    const double fy = v - y;
    const double expected = (1 - fx) * (1 - fy) * value(x, y) + fx * (1 - fy) * value(x + 1, y) +
                            (1 - fx) * fy * value(x, y + 1) + fx * fy * value(x + 1, y + 1);
    ASSERT_NEAR(map.interpolate(p), expected, 1e-6);
  }
}

TEST(OccupancyGridMap, InterpolationFadesToZeroHalfACellOutside) {
  OccupancyGridMap map = smallMap();
  // Make cell (0, 15) on the left edge occupied.
  map.updateByScan(rays(map.cellCenter(5, 15), {map.cellCenter(0, 15)}), Pose2D{});
  const double p = map.probability(0, 15);
  const Eigen::Vector2d centre = map.cellCenter(0, 15);
  EXPECT_NEAR(map.interpolate(centre), p, 1e-6);
  EXPECT_NEAR(map.interpolate(centre - Eigen::Vector2d(0.05, 0.0)), 0.5 * p, 1e-6);  // on the map's edge
  EXPECT_NEAR(map.interpolate(centre - Eigen::Vector2d(0.0999, 0.0)), 0.001 * p, 1e-5);
  Eigen::Vector2d gradient;
  EXPECT_EQ(map.interpolate(centre - Eigen::Vector2d(0.1001, 0.0), &gradient), 0.0);
  EXPECT_EQ(gradient, Eigen::Vector2d::Zero());
  EXPECT_EQ(map.interpolate({kNan, 0.0}, &gradient), 0.0);
  EXPECT_EQ(gradient, Eigen::Vector2d::Zero());
  EXPECT_EQ(map.interpolate({1e300, -1e300}, &gradient), 0.0);
  EXPECT_EQ(gradient, Eigen::Vector2d::Zero());
}

}  // namespace
}  // namespace hector_style_mapping
