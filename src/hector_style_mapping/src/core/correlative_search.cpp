#include "hector_style_mapping/correlative_search.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace hector_style_mapping {

namespace {

// The rotation step: the farthest points (the 95th percentile of ranges, so that a few stray far
// returns do not make the step needlessly fine) move by one cell.
double angularStep(const std::vector<Eigen::Vector2d>& points, double resolution) {
  std::vector<double> ranges;
  ranges.reserve(points.size());
  for (const Eigen::Vector2d& p : points) ranges.push_back(p.norm());
  const std::size_t k = std::min(ranges.size() - 1, static_cast<std::size_t>(0.95 * ranges.size()));
  std::nth_element(ranges.begin(), ranges.begin() + static_cast<long>(k), ranges.end());
  return resolution / std::max(ranges[k], 4.0 * resolution);
}

}  // namespace

SearchResult correlativeSearch(const OccupancyGridMap& map, const ScanPoints& scan, const Pose2D& centre,
                               const SearchWindow& window) {
  SearchResult result;
  result.pose = centre;
  std::vector<Eigen::Vector2d> points;
  points.reserve(scan.points.size());
  for (const Eigen::Vector2d& p : scan.points)
    if (p.allFinite()) points.push_back(p);
  if (points.empty()) return result;

  const double resolution = map.resolution();
  const double angle_step = angularStep(points, resolution);
  const int angles = static_cast<int>(std::ceil(std::max(window.angular, 0.0) / angle_step));
  const int shifts = static_cast<int>(std::ceil(std::max(window.linear, 0.0) / resolution));
  const int nx = map.sizeX(), ny = map.sizeY();
  const std::vector<float>& values = map.matchValues();

  std::vector<int> cell_x(points.size()), cell_y(points.size());
  double best_sum = -1.0, best_distance = 0.0;
  for (int a = -angles; a <= angles; ++a) {
    const double theta = centre.theta + a * angle_step;
    const Pose2D rotated{centre.x, centre.y, theta};
    int min_x = nx, min_y = ny, max_x = -1, max_y = -1;
    for (std::size_t i = 0; i < points.size(); ++i) {
      const Eigen::Vector2i cell = map.cellOf(transformPoint(rotated, points[i]));
      cell_x[i] = cell.x();
      cell_y[i] = cell.y();
      min_x = std::min(min_x, cell.x()), max_x = std::max(max_x, cell.x());
      min_y = std::min(min_y, cell.y()), max_y = std::max(max_y, cell.y());
    }
    // Every shifted point inside the map: read without bounds checks (the common case).
    const bool inside = min_x - shifts >= 0 && min_y - shifts >= 0 && max_x + shifts < nx && max_y + shifts < ny;
    for (int dy = -shifts; dy <= shifts; ++dy) {
      for (int dx = -shifts; dx <= shifts; ++dx) {
        double sum = 0.0;
        if (inside) {
          for (std::size_t i = 0; i < points.size(); ++i)
            sum += values[static_cast<std::size_t>((cell_y[i] + dy) * nx + cell_x[i] + dx)];
        } else {
          for (std::size_t i = 0; i < points.size(); ++i) {
            const int x = cell_x[i] + dx, y = cell_y[i] + dy;
            if (x >= 0 && y >= 0 && x < nx && y < ny) sum += values[static_cast<std::size_t>(y * nx + x)];
          }
        }
        ++result.candidates;
        // Distance from the centre in cells, a turn counted as the farthest points' shift.
        const double distance = std::hypot(dx, dy) + std::abs(a);
        if (sum > best_sum || (sum == best_sum && distance < best_distance)) {
          best_sum = sum;
          best_distance = distance;
          result.pose = {centre.x + dx * resolution, centre.y + dy * resolution, normalizeAngle(theta)};
        }
      }
    }
  }
  result.score = best_sum / static_cast<double>(points.size());
  return result;
}

}  // namespace hector_style_mapping
