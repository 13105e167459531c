#include "hector_style_mapping_core/likelihood_field.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "hector_style_mapping_core/floor_to_int.h"

namespace hector_style_mapping {

namespace {

// Values below this are far enough (2 sigma) from every hit for a ray through the cell to mark it free.
const float kNearHit = static_cast<float>(std::exp(-2.0));

template <typename Visit>
void forEachPoint(const PlacedScan& placed, Visit visit) {
  for (const Eigen::Vector2d& p : placed.scan.points)
    if (p.allFinite()) visit(transformPoint(placed.pose, p), true);
  for (const Eigen::Vector2d& p : placed.scan.free_rays)
    if (p.allFinite()) visit(transformPoint(placed.pose, p), false);
}

}  // namespace

void LikelihoodField::build(const std::vector<PlacedScan>& scans) {
  Eigen::Vector2d low = Eigen::Vector2d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector2d high = -low;
  bool any = false;
  for (const PlacedScan& placed : scans) {
    forEachPoint(placed, [&](const Eigen::Vector2d& p, bool) {
      low = low.cwiseMin(p), high = high.cwiseMax(p);
      any = true;
    });
    const Eigen::Vector2d origin = transformPoint(placed.pose, placed.scan.origin);
    low = low.cwiseMin(origin), high = high.cwiseMax(origin);
  }
  levels_.resize(kLevels);
  size_x_ = size_y_ = 0;
  if (!any) return;
  // Room for the blur round the outermost hits.
  const double margin = 3.0 * kSigma + 2.0 * kResolution;
  origin_ = low - Eigen::Vector2d::Constant(margin);
  size_x_ = static_cast<int>(std::ceil((high.x() - low.x() + 2.0 * margin) / kResolution)) + 1;
  size_y_ = static_cast<int>(std::ceil((high.y() - low.y() + 2.0 * margin) / kResolution)) + 1;
  levels_[0].assign(static_cast<std::size_t>(size_x_) * static_cast<std::size_t>(size_y_), 0.0f);
  addHits(scans);
  addFreeSpace(scans);
  buildLevels();
}

void LikelihoodField::addHits(const std::vector<PlacedScan>& scans) {
  std::vector<float>& cells = levels_[0];
  constexpr int kMaxRadius = 6;  // cells: 3 sigma
  const int radius = std::min(static_cast<int>(std::ceil(3.0 * kSigma / kResolution)), kMaxRadius);
  const double inverse_two_sigma_squared = 1.0 / (2.0 * kSigma * kSigma);
  for (const PlacedScan& placed : scans) {
    forEachPoint(placed, [&](const Eigen::Vector2d& p, bool hit) {
      if (!hit) return;
      const Eigen::Vector2d c = toCell(p);
      const int cx = floorToInt(c.x() + 0.5), cy = floorToInt(c.y() + 0.5);
      // exp(-d^2 / (2 sigma^2)) is exp of the x part times exp of the y part.
      double along_x[2 * kMaxRadius + 1];
      for (int i = -radius; i <= radius; ++i) {
        const double dx = (cx + i - c.x()) * kResolution;
        along_x[i + radius] = std::exp(-dx * dx * inverse_two_sigma_squared);
      }
      for (int y = std::max(cy - radius, 0); y <= std::min(cy + radius, size_y_ - 1); ++y) {
        const double dy = (y - c.y()) * kResolution;
        const double along_y = std::exp(-dy * dy * inverse_two_sigma_squared);
        for (int x = std::max(cx - radius, 0); x <= std::min(cx + radius, size_x_ - 1); ++x) {
          float& cell = cells[static_cast<std::size_t>(y * size_x_ + x)];
          cell = std::max(cell, static_cast<float>(along_x[x - cx + radius] * along_y));
        }
      }
    });
  }
}

void LikelihoodField::addFreeSpace(const std::vector<PlacedScan>& scans) {
  std::vector<float>& cells = levels_[0];
  for (const PlacedScan& placed : scans) {
    const Eigen::Vector2d start = toCell(transformPoint(placed.pose, placed.scan.origin));
    forEachPoint(placed, [&](const Eigen::Vector2d& p, bool) {
      // Cell by cell from the laser to the ray's end (both inside the grid, which covers them).
      const Eigen::Vector2d end = toCell(p);
      const int steps = static_cast<int>(std::ceil((end - start).cwiseAbs().maxCoeff()));
      const Eigen::Vector2d step = steps > 0 ? Eigen::Vector2d((end - start) / steps) : Eigen::Vector2d::Zero();
      for (int i = 0; i < steps; ++i) {
        const Eigen::Vector2d c = start + i * step;
        // Rounded to the nearest cell; c >= 0 (the grid has a margin round every point), so truncating c + 0.5
        // is floor(c + 0.5) without the call.
        const int x = static_cast<int>(c.x() + 0.5), y = static_cast<int>(c.y() + 0.5);
        float& cell = cells[static_cast<std::size_t>(y * size_x_ + x)];
        if (cell < kNearHit) cell = kFreeValue;
      }
    });
  }
}

void LikelihoodField::buildLevels() {
  for (int level = 1; level < kLevels; ++level) {
    const std::vector<float>& below = levels_[level - 1];
    std::vector<float>& cells = levels_[level];
    cells.resize(below.size());
    const int half = 1 << (level - 1);
    const auto at = [&](int x, int y) {
      return x < size_x_ && y < size_y_ ? below[static_cast<std::size_t>(y * size_x_ + x)] : 0.0f;
    };
    // Where all four cells lie inside, without the bounds checks (the compiler vectorises it); then the rim.
    const int inner_x = std::max(size_x_ - half, 0), inner_y = std::max(size_y_ - half, 0);
    for (int y = 0; y < inner_y; ++y) {
      const float* row = &below[static_cast<std::size_t>(y) * size_x_];
      const float* next = row + static_cast<std::size_t>(half) * size_x_;
      float* out = &cells[static_cast<std::size_t>(y) * size_x_];
      for (int x = 0; x < inner_x; ++x)
        out[x] = std::max(std::max(row[x], row[x + half]), std::max(next[x], next[x + half]));
      for (int x = inner_x; x < size_x_; ++x)
        out[x] = std::max(std::max(at(x, y), at(x + half, y)), std::max(at(x, y + half), at(x + half, y + half)));
    }
    for (int y = inner_y; y < size_y_; ++y)
      for (int x = 0; x < size_x_; ++x)
        cells[static_cast<std::size_t>(y * size_x_ + x)] =
            std::max(std::max(at(x, y), at(x + half, y)), std::max(at(x, y + half), at(x + half, y + half)));
  }
}

double LikelihoodField::interpolate(const Eigen::Vector2d& point) const {
  const Eigen::Vector2d c = toCell(point);
  const int x = floorToInt(c.x()), y = floorToInt(c.y());
  const double fx = x, fy = y;
  const double ax = c.x() - fx, ay = c.y() - fy;
  if (x >= 0 && y >= 0 && x + 1 < size_x_ && y + 1 < size_y_) {
    // All four inside (nearly always): read them without value()'s checks, the same sum.
    const float* low = &levels_[0][static_cast<std::size_t>(y) * size_x_ + x];
    const float* high = low + size_x_;
    return (1.0 - ay) * ((1.0 - ax) * low[0] + ax * low[1]) + ay * ((1.0 - ax) * high[0] + ax * high[1]);
  }
  return (1.0 - ay) * ((1.0 - ax) * value(x, y) + ax * value(x + 1, y)) +
         ay * ((1.0 - ax) * value(x, y + 1) + ax * value(x + 1, y + 1));
}

}  // namespace hector_style_mapping
