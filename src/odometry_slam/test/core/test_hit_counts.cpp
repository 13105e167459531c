#include <cstdint>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "hector_style_mapping_core/occupancy_grid_map.h"
#include "odometry_slam/hit_counts.h"

namespace odometry_slam {
namespace {

using hector_style_mapping::OccupancyGridMap;
using hector_style_mapping::Pose2D;
using hector_style_mapping::ScanPoints;

// 40 x 30 cells of 0.1 m; the map frame's origin is the lower-left corner of cell (20, 15).
OccupancyGridMap smallMap() { return OccupancyGridMap(40, 30, 0.1, {-2.0, -1.5}, 0.4, 0.9); }

// One ray from the centre of cell (20, 15) to the centre of cell (x, 15), counted.
void ray(OccupancyGridMap* map, HitCounts* counts, int x) {
  ScanPoints scan;
  scan.origin = map->cellCenter(20, 15);
  scan.points = {map->cellCenter(x, 15)};
  map->updateByScan(scan, Pose2D{});
  counts->addLastUpdate(*map);
}

TEST(HitCounts, OccupiedWhenTheShareOfHitsExceedsTheThreshold) {
  OccupancyGridMap map = smallMap();
  HitCounts counts(40, 30);
  ray(&map, &counts, 25);                             // cell 25 hit once
  for (int i = 0; i < 3; ++i) ray(&map, &counts, 30);  // ... then seen through three times: 1 hit in 4 visits
  EXPECT_EQ(counts.state(25, 15, 0.25), 0);          // 0.25 is not more than 0.25
  EXPECT_EQ(counts.state(25, 15, 0.24), 100);
  EXPECT_EQ(counts.state(30, 15, 0.25), 100);         // 3 of 3
  EXPECT_EQ(counts.state(22, 15, 0.0), 0);            // only ever seen through
  EXPECT_EQ(counts.state(31, 15, 0.25), -1);          // never seen
  EXPECT_EQ(counts.state(-1, 15, 0.25), -1);          // outside
  // The log-odds map calls cell 25 occupied (one hit outweighs three misses there): the counts are what
  // occ_thresh is about.
  EXPECT_TRUE(map.isOccupied(25, 15));
}

TEST(HitCounts, SeenBoxAndStatesOfABox) {
  OccupancyGridMap map = smallMap();
  HitCounts counts(40, 30);
  EXPECT_TRUE(counts.seenBox().empty());
  ray(&map, &counts, 24);
  const CellBox& box = counts.seenBox();
  EXPECT_EQ(box.x0, 20);
  EXPECT_EQ(box.x1, 25);
  EXPECT_EQ(box.y0, 15);
  EXPECT_EQ(box.y1, 16);
  std::vector<int8_t> states;
  counts.states(CellBox{19, 15, 26, 17}, 0.25, &states);
  const std::vector<int8_t> expected{-1, 0, 0, 0, 0, 100, -1, -1, -1, -1, -1, -1, -1, -1};
  EXPECT_EQ(states, expected);
  counts.clear();
  EXPECT_TRUE(counts.seenBox().empty());
  EXPECT_EQ(counts.state(24, 15, 0.25), -1);
}

TEST(HitCounts, ManyVisitsKeepTheirShare) {
  OccupancyGridMap map = smallMap();
  HitCounts counts(40, 30);
  // 70000 visits of cell 21, one in ten a hit: past the 16-bit counters, the share stays about 0.1.
  for (int i = 0; i < 70000; ++i) ray(&map, &counts, i % 10 == 0 ? 21 : 22);
  EXPECT_EQ(counts.state(21, 15, 0.09), 100);
  EXPECT_EQ(counts.state(21, 15, 0.11), 0);
}

TEST(HitCounts, RefusesAMapOfAnotherSize) {
  OccupancyGridMap map = smallMap();
  HitCounts counts(20, 30);
  EXPECT_THROW(counts.addLastUpdate(map), std::invalid_argument);
  EXPECT_THROW(HitCounts(0, 3), std::invalid_argument);
}

}  // namespace
}  // namespace odometry_slam
