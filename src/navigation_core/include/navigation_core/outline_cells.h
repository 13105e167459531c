#pragma once
// The cells under a footprint's outline on a costmap: each edge's cells from one vertex's cell to
// the next's, as a Bresenham line walks them (costmap_2d's footprint check walks its edges so).
// Inline and in integers: the local planner runs it for every pose of every sampled trajectory,
// and the obstacle layer walks its clearing rays with the same line walker.
#include <cstdlib>

#include "navigation_core/costmap.h"
#include "navigation_core/footprint.h"

namespace navigation_core {

// visit(index) for the cells of the line from cell (x0, y0) to cell (x1, y1) on a grid `size_x`
// cells wide, in order, the first cell left out and the last included (an outline's edges then
// visit each vertex's cell once). visit returns false to stop, and then this returns false.
template <typename Visit>
bool forEachLineCellAfter(int x0, int y0, int x1, int y1, unsigned size_x, Visit&& visit) {
  const int dx = std::abs(x1 - x0), dy = std::abs(y1 - y0);
  const int step_x = x1 >= x0 ? 1 : -1;
  const int step_y = y1 >= y0 ? static_cast<int>(size_x) : -static_cast<int>(size_x);
  const bool x_major = dx >= dy;
  const int major = x_major ? dx : dy, minor = x_major ? dy : dx;
  const int major_step = x_major ? step_x : step_y, minor_step = x_major ? step_y : step_x;
  int index = y0 * static_cast<int>(size_x) + x0, error = major / 2;
  for (int i = 0; i < major; ++i) {
    index += major_step;
    error += minor;
    if (error >= major) {
      index += minor_step;
      error -= major;
    }
    if (!visit(static_cast<unsigned>(index))) return false;
  }
  return true;
}

// The cell of footprint vertex `v` with the robot at `pose` (heading cosine c, sine s): false when
// it lies off the costmap.
inline bool outlineVertexCell(const Costmap& costmap, const Pose2& pose, double c, double s, const Point2& v, int& mx,
                              int& my) {
  const double fx = (pose.x + c * v.x - s * v.y - costmap.originX()) / costmap.resolution();
  const double fy = (pose.y + s * v.x + c * v.y - costmap.originY()) / costmap.resolution();
  if (!(fx >= 0 && fy >= 0 && fx < static_cast<double>(costmap.sizeX()) && fy < static_cast<double>(costmap.sizeY())))
    return false;
  mx = static_cast<int>(fx), my = static_cast<int>(fy);
  return true;
}

// visit(index) for every cell of the footprint's outline at `pose`, whose heading's cosine and
// sine are c and s (the first vertex's cell twice). Returns false when visit stopped the walk or a
// vertex lies off the costmap (where nothing is known: costmap_2d's check fails there too).
template <typename Visit>
bool forEachOutlineCell(const Costmap& costmap, const Footprint& footprint, const Pose2& pose, double c, double s,
                        Visit&& visit) {
  if (footprint.empty()) return true;
  int first_x, first_y;
  if (!outlineVertexCell(costmap, pose, c, s, footprint.front(), first_x, first_y)) return false;
  // The first vertex's cell, also for an outline that lies in one cell.
  if (!visit(static_cast<unsigned>(first_y) * costmap.sizeX() + static_cast<unsigned>(first_x))) return false;
  int x0 = first_x, y0 = first_y;
  for (std::size_t i = 1; i <= footprint.size(); ++i) {
    int x1 = first_x, y1 = first_y;
    if (i < footprint.size() && !outlineVertexCell(costmap, pose, c, s, footprint[i], x1, y1)) return false;
    if (!forEachLineCellAfter(x0, y0, x1, y1, costmap.sizeX(), visit)) return false;
    x0 = x1, y0 = y1;
  }
  return true;
}

}  // namespace navigation_core
