#include "navigation_core/obstacle_layer.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "navigation_core/cost_values.h"
#include "navigation_core/outline_cells.h"

namespace navigation_core {
namespace {

// Frees the cells of the line from (x0, y0) towards (x1, y1) (Bresenham), at most max_length
// cells along the major axis plus the cell where it stops, as costmap_2d's raytraceLine.
void clearLine(Costmap& layer, int x0, int y0, int x1, int y1, unsigned max_length) {
  const int dx = x1 - x0, dy = y1 - y0;
  // Shortened to max_length cells only when longer (a square root per ray otherwise: 720 a scan).
  const double length2 = static_cast<double>(dx) * dx + static_cast<double>(dy) * dy;
  const double max2 = static_cast<double>(max_length) * max_length;
  const double scale = length2 <= max2 ? 1.0 : max_length / std::sqrt(length2);
  const int major = std::max(std::abs(dx), std::abs(dy));
  const int end = std::min(static_cast<int>(scale * major), major);
  std::vector<std::uint8_t>& costs = layer.costs();
  costs[layer.index(static_cast<unsigned>(x0), static_cast<unsigned>(y0))] = kFreeSpace;
  int steps = 0;
  forEachLineCellAfter(x0, y0, x1, y1, layer.sizeX(), [&](unsigned cell) {
    if (++steps > end) return false;
    costs[cell] = kFreeSpace;
    return true;
  });
}

}  // namespace

void applyObservation(Costmap& layer, const Observation& observation, const ObstacleLayerOptions& options) {
  const Point3& o = observation.origin;
  unsigned ox, oy;
  if (!layer.worldToMap(o.x, o.y, ox, oy)) return;  // a sensor off the map clears nothing (upstream warns)
  if (options.clearing) {
    const double min_x = layer.originX(), min_y = layer.originY();
    const double max_x = min_x + layer.sizeX() * layer.resolution(), max_y = min_y + layer.sizeY() * layer.resolution();
    const unsigned max_cells = layer.cellDistance(options.raytrace_range);
    for (const Point3& p : observation.points) {
      double wx = p.x, wy = p.y;
      if (!std::isfinite(wx) || !std::isfinite(wy)) continue;
      // Clip the ray to the map, keeping its direction.
      const auto clip = [&](double& a, double& b, double oa, double ob, double bound) {
        const double t = (bound - oa) / (a - oa);
        a = bound;
        b = ob + (b - ob) * t;
      };
      if (wx < min_x) clip(wx, wy, o.x, o.y, min_x);
      if (wy < min_y) clip(wy, wx, o.y, o.x, min_y);
      if (wx > max_x - 1e-9) clip(wx, wy, o.x, o.y, max_x - 1e-9);
      if (wy > max_y - 1e-9) clip(wy, wx, o.y, o.x, max_y - 1e-9);
      unsigned ex, ey;
      if (!layer.worldToMap(wx, wy, ex, ey)) continue;
      clearLine(layer, static_cast<int>(ox), static_cast<int>(oy), static_cast<int>(ex), static_cast<int>(ey), max_cells);
    }
  }
  if (options.marking) {
    const double range2 = options.obstacle_range * options.obstacle_range;
    for (const Point3& p : observation.points) {
      if (!(p.z <= options.max_obstacle_height && p.z >= options.min_obstacle_height)) continue;  // also NaN
      const double d2 = (p.x - o.x) * (p.x - o.x) + (p.y - o.y) * (p.y - o.y) + (p.z - o.z) * (p.z - o.z);
      if (!(d2 < range2)) continue;
      unsigned mx, my;
      if (layer.worldToMap(p.x, p.y, mx, my)) layer.setCost(mx, my, kLethalObstacle);
    }
  }
}

}  // namespace navigation_core

namespace navigation_core {

void clearFootprint(Costmap& layer, const Footprint& footprint, const Pose2& pose) {
  if (footprint.size() < 3) return;
  // The outline's cells, as the local planner's footprint check walks them.
  double min_x = pose.x, max_x = pose.x, min_y = pose.y, max_y = pose.y;
  forEachOutlinePoint(footprint, pose, 0.5 * layer.resolution(), [&](double x, double y) {
    unsigned mx, my;
    if (layer.worldToMap(x, y, mx, my)) layer.setCost(mx, my, kFreeSpace);
    min_x = std::min(min_x, x), max_x = std::max(max_x, x);
    min_y = std::min(min_y, y), max_y = std::max(max_y, y);
    return true;
  });
  // The interior: cells whose centres lie inside the polygon (even-odd rule).
  const double c = std::cos(pose.theta), s = std::sin(pose.theta);
  std::vector<Point2> polygon;
  for (const Point2& v : footprint) polygon.push_back({pose.x + c * v.x - s * v.y, pose.y + s * v.x + c * v.y});
  const double res = layer.resolution();
  const long x0 = std::max(0L, static_cast<long>(std::floor((min_x - layer.originX()) / res)));
  const long y0 = std::max(0L, static_cast<long>(std::floor((min_y - layer.originY()) / res)));
  const long x1 = std::min(static_cast<long>(layer.sizeX()) - 1, static_cast<long>(std::floor((max_x - layer.originX()) / res)));
  const long y1 = std::min(static_cast<long>(layer.sizeY()) - 1, static_cast<long>(std::floor((max_y - layer.originY()) / res)));
  for (long my = y0; my <= y1; ++my) {
    for (long mx = x0; mx <= x1; ++mx) {
      double wx, wy;
      layer.mapToWorld(static_cast<unsigned>(mx), static_cast<unsigned>(my), wx, wy);
      bool inside = false;
      for (std::size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
        const Point2 &a = polygon[i], &b = polygon[j];
        if ((a.y > wy) != (b.y > wy) && wx < a.x + (wy - a.y) * (b.x - a.x) / (b.y - a.y)) inside = !inside;
      }
      if (inside) layer.setCost(static_cast<unsigned>(mx), static_cast<unsigned>(my), kFreeSpace);
    }
  }
}

}  // namespace navigation_core
