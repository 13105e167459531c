// The cells under a footprint's outline, as the local planner checks them.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <set>
#include <vector>

#include "navigation_core/outline_cells.h"

namespace navigation_core {
namespace {

std::vector<unsigned> outlineCells(const Costmap& map, const Footprint& footprint, const Pose2& pose, bool* on_map) {
  std::vector<unsigned> cells;
  *on_map = forEachOutlineCell(map, footprint, pose, std::cos(pose.theta), std::sin(pose.theta), [&](unsigned i) {
    cells.push_back(i);
    return true;
  });
  return cells;
}

TEST(OutlineCells, AnAxisAlignedRectangleVisitsItsBorderCellsOnce) {
  const Costmap map(20, 20, 0.05, 0.0, 0.0);
  // Corners in cells (2, 2) and (7, 5): the border of that 6 x 4 block is 16 cells.
  const Footprint f = {{0.12, 0.12}, {0.38, 0.12}, {0.38, 0.28}, {0.12, 0.28}};
  bool on_map = false;
  const std::vector<unsigned> cells = outlineCells(map, f, {}, &on_map);
  ASSERT_TRUE(on_map);
  std::set<unsigned> expected;
  for (unsigned x = 2; x <= 7; ++x) expected.insert({map.index(x, 2), map.index(x, 5)});
  for (unsigned y = 2; y <= 5; ++y) expected.insert({map.index(2, y), map.index(7, y)});
  EXPECT_EQ(std::set<unsigned>(cells.begin(), cells.end()), expected);
  EXPECT_EQ(cells.size(), expected.size() + 1);  // the first vertex's cell twice, no other repeat
}

TEST(OutlineCells, ARotatedOutlineIsUnbrokenAndHugsItsEdges) {
  const Costmap map(40, 40, 0.05, -1.0, -1.0);
  // The Pioneer's padded footprint, turned 30 degrees.
  const Footprint f = {{-0.29, -0.22}, {-0.29, 0.22}, {0.20, 0.22}, {0.20, -0.22}};
  const Pose2 pose{0.013, -0.021, 0.5236};
  bool on_map = false;
  const std::vector<unsigned> cells = outlineCells(map, f, pose, &on_map);
  ASSERT_TRUE(on_map);
  // A closed ring of 8-neighbours: no gap an obstacle cell could hide in.
  for (std::size_t k = 0; k < cells.size(); ++k) {
    const unsigned a = cells[k], b = cells[(k + 1) % cells.size()];
    const int dx = std::abs(static_cast<int>(a % 40) - static_cast<int>(b % 40));
    const int dy = std::abs(static_cast<int>(a / 40) - static_cast<int>(b / 40));
    EXPECT_LE(std::max(dx, dy), 1) << "cells " << k << " and " << k + 1;
  }
  // Each cell's centre within one cell of the outline (Bresenham strays at most half a cell from
  // the line between the vertex cells' centres, which are half a diagonal from the vertices).
  const double c = std::cos(pose.theta), s = std::sin(pose.theta);
  for (unsigned i : cells) {
    double wx, wy;
    map.mapToWorld(i % 40, i / 40, wx, wy);
    double nearest = 1e9;
    for (std::size_t e = 0; e < f.size(); ++e) {
      const Point2 &p = f[e], &q = f[(e + 1) % f.size()];
      const double ax = pose.x + c * p.x - s * p.y, ay = pose.y + s * p.x + c * p.y;
      const double bx = pose.x + c * q.x - s * q.y, by = pose.y + s * q.x + c * q.y;
      const double t = std::clamp(((wx - ax) * (bx - ax) + (wy - ay) * (by - ay)) /
                                      ((bx - ax) * (bx - ax) + (by - ay) * (by - ay)), 0.0, 1.0);
      nearest = std::min(nearest, std::hypot(wx - ax - t * (bx - ax), wy - ay - t * (by - ay)));
    }
    EXPECT_LT(nearest, 0.05) << "cell " << i;
  }
  // About perimeter / resolution cells: 1.86 m of outline, 0.05 m cells, diagonal steps longer.
  EXPECT_GE(cells.size(), 30u);
  EXPECT_LE(cells.size(), 40u);
}

TEST(OutlineCells, AnOutlineInsideOneCellStillChecksThatCell) {
  const Costmap map(10, 10, 0.05, 0.0, 0.0);
  const Footprint tiny = {{-0.01, -0.01}, {-0.01, 0.01}, {0.01, 0.01}, {0.01, -0.01}};
  bool on_map = false;
  const std::vector<unsigned> cells = outlineCells(map, tiny, {0.125, 0.125, 0.0}, &on_map);
  ASSERT_TRUE(on_map);
  EXPECT_EQ(std::set<unsigned>(cells.begin(), cells.end()), std::set<unsigned>{map.index(2, 2)});
}

TEST(OutlineCells, AVertexOffTheMapFailsTheWalk) {
  const Costmap map(10, 10, 0.05, 0.0, 0.0);
  const Footprint f = {{-0.1, -0.1}, {-0.1, 0.1}, {0.1, 0.1}, {0.1, -0.1}};
  bool on_map = true;
  outlineCells(map, f, {0.05, 0.25, 0.0}, &on_map);  // the left edge at x = -0.05
  EXPECT_FALSE(on_map);
  outlineCells(map, f, {0.25, 0.25, 0.0}, &on_map);
  EXPECT_TRUE(on_map);
}

TEST(OutlineCells, StoppingTheVisitStopsTheWalk) {
  const Costmap map(20, 20, 0.05, 0.0, 0.0);
  const Footprint f = {{0.12, 0.12}, {0.38, 0.12}, {0.38, 0.28}, {0.12, 0.28}};
  int visits = 0;
  const bool finished = forEachOutlineCell(map, f, {}, 1.0, 0.0, [&](unsigned) { return ++visits < 3; });
  EXPECT_FALSE(finished);
  EXPECT_EQ(visits, 3);
}

}  // namespace
}  // namespace navigation_core
