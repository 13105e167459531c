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
  const PoseTransform to_map(placed.pose);
  for (const Eigen::Vector2d& p : placed.scan.points)
    if (p.allFinite()) visit(to_map(p), true);
  for (const Eigen::Vector2d& p : placed.scan.free_rays)
    if (p.allFinite()) visit(to_map(p), false);
}

constexpr double kMargin = 3.0 * LikelihoodField::kSigma + 2.0 * LikelihoodField::kResolution;  // the blur's room

// The box round a scan's points, rays and laser (map frame), grown into; false without finite points.
bool growExtent(const PlacedScan& placed, Eigen::Vector2d* lowest, Eigen::Vector2d* highest) {
  const Eigen::Vector2d laser = transformPoint(placed.pose, placed.scan.origin);
  *lowest = lowest->cwiseMin(laser), *highest = highest->cwiseMax(laser);
  bool any = false;
  forEachPoint(placed, [&](const Eigen::Vector2d& p, bool) {
    *lowest = lowest->cwiseMin(p), *highest = highest->cwiseMax(p);
    any = true;
  });
  return any;
}

// The cells, [first, last] on the lattice through `lattice_point` (a cell's centre), that a grid round the box
// [lowest, highest] needs, with room for the blur.
void cellRange(const Eigen::Vector2d& lattice_point, const Eigen::Vector2d& lowest, const Eigen::Vector2d& highest,
               Eigen::Vector2i* first, Eigen::Vector2i* last) {
  const Eigen::Vector2d low =
      (lowest - Eigen::Vector2d::Constant(kMargin) - lattice_point) / LikelihoodField::kResolution;
  const Eigen::Vector2d high =
      (highest + Eigen::Vector2d::Constant(kMargin) - lattice_point) / LikelihoodField::kResolution;
  *first = Eigen::Vector2i(floorToInt(low.x()), floorToInt(low.y()));
  *last = Eigen::Vector2i(-floorToInt(-high.x()), -floorToInt(-high.y()));
}

// row[k] = exp(-q (offset + k - radius)^2) for k = 0 .. 2 radius (cells from a hit `offset` cells from the nearest
// cell centre): from three exp calls, not 2 radius + 1, as exp(-q offset^2) exp(-2 q offset i) exp(-q i^2). Exp was
// a seventh of the mapper's time on a dense log; the products differ from the direct values by a few ulp.
void gaussianRow(double offset, int radius, double q, double* row) {
  const double centre = std::exp(-q * offset * offset);
  const double ratio = std::exp(-2.0 * q * offset);
  const double squares = std::exp(-q);  // exp(-q i^2) = squares^(i^2)
  // Outward from the centre: factor_i = ratio^i, square_i = exp(-q i^2).
  row[radius] = centre;
  double up = 1.0, down = 1.0, square = 1.0, odd = squares;  // square_(i+1) = square_i * squares^(2i+1)
  const double inverse_ratio = 1.0 / ratio;
  for (int i = 1; i <= radius; ++i) {
    up *= ratio, down *= inverse_ratio;
    square *= odd, odd *= squares * squares;
    row[radius + i] = centre * up * square;
    row[radius - i] = centre * down * square;
  }
}

// A cell's value with a hit's value `v` added: the largest value, except that a cell where a ray passed stays free
// unless the hit lies within 2 sigma (what build() gives adding every hit before any ray).
inline float withHit(float cell, float v) {
  // Without a branch, so that a row of the blur is one vector operation.
  const bool stays_free = cell == LikelihoodField::kFreeValue && v < kNearHit;
  return stays_free ? cell : std::max(cell, v);
}

}  // namespace

void LikelihoodField::allocate(const Eigen::Vector2d& lattice_point, const Eigen::Vector2i& first,
                               const Eigen::Vector2i& last) {
  levels_.resize(kLevels);
  lattice_point_ = lattice_point;
  first_cell_ = first.cast<double>();
  size_x_ = last.x() - first.x() + 1;
  size_y_ = last.y() - first.y() + 1;
  levels_[0].assign(static_cast<std::size_t>(size_x_) * static_cast<std::size_t>(size_y_), 0.0f);
  levels_ready_ = 1;
}

Eigen::Vector2d LikelihoodField::ownLatticePoint(const std::vector<PlacedScan>& scans) {
  Eigen::Vector2d lowest = Eigen::Vector2d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector2d highest = -lowest;
  for (const PlacedScan& placed : scans) growExtent(placed, &lowest, &highest);
  return lowest - Eigen::Vector2d::Constant(kMargin);
}

void LikelihoodField::build(const std::vector<PlacedScan>& scans, int levels) {
  build(scans, ownLatticePoint(scans), levels);
}

void LikelihoodField::build(const std::vector<PlacedScan>& scans, const Eigen::Vector2d& lattice_point, int levels) {
  Eigen::Vector2d lowest = Eigen::Vector2d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector2d highest = -lowest;
  bool any = false;
  for (const PlacedScan& placed : scans) any = growExtent(placed, &lowest, &highest) || any;
  levels_.resize(kLevels);
  size_x_ = size_y_ = 0;
  levels_ready_ = kLevels;  // all of an empty grid's
  if (!any) return;
  Eigen::Vector2i first, last;
  cellRange(lattice_point, lowest, highest, &first, &last);
  allocate(lattice_point, first, last);
  for (const PlacedScan& placed : scans) addHits(placed);
  for (const PlacedScan& placed : scans) addFreeSpace(placed);
  ensureLevels(levels);
}

void LikelihoodField::buildOnTop(const LikelihoodField& base, const PlacedScan& scan, int levels) {
  if (base.size_x_ == 0) {  // no finite point below: the scan alone
    build({scan}, levels);
    return;
  }
  Eigen::Vector2d lowest = Eigen::Vector2d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector2d highest = -lowest;
  const bool any = growExtent(scan, &lowest, &highest);
  // The union of the base's cells and the scan's, on the base's lattice: what build() of all their scans on it
  // covers (a range is monotone in the box).
  Eigen::Vector2i first, last;
  cellRange(base.lattice_point_, lowest, highest, &first, &last);
  const Eigen::Vector2i base_first = base.first_cell_.cast<int>();
  const Eigen::Vector2i base_last = base_first + Eigen::Vector2i(base.size_x_ - 1, base.size_y_ - 1);
  allocate(base.lattice_point_, first.cwiseMin(base_first), last.cwiseMax(base_last));
  const Eigen::Vector2i offset = base_first - first_cell_.cast<int>();
  for (int y = 0; y < base.size_y_; ++y)
    std::copy_n(&base.levels_[0][static_cast<std::size_t>(y) * base.size_x_], base.size_x_,
                &levels_[0][static_cast<std::size_t>(y + offset.y()) * size_x_ + offset.x()]);
  if (any) {
    addHits(scan);
    addFreeSpace(scan);
  }
  ensureLevels(levels);
}

void LikelihoodField::addHits(const PlacedScan& placed) {
  std::vector<float>& cells = levels_[0];
  constexpr int kMaxRadius = 6;  // cells: 3 sigma
  const int radius = std::min(static_cast<int>(std::ceil(3.0 * kSigma / kResolution)), kMaxRadius);
  const double q = kResolution * kResolution / (2.0 * kSigma * kSigma);  // per cell squared
  forEachPoint(placed, [&](const Eigen::Vector2d& p, bool hit) {
    if (!hit) return;
    const Eigen::Vector2d c = toCell(p);
    const int cx = floorToInt(c.x() + 0.5), cy = floorToInt(c.y() + 0.5);
    // exp(-d^2 / (2 sigma^2)) is exp of the x part times exp of the y part.
    double along_x[2 * kMaxRadius + 1], along_y[2 * kMaxRadius + 1];
    gaussianRow(cx - c.x(), radius, q, along_x);
    gaussianRow(cy - c.y(), radius, q, along_y);
    const int x_first = std::max(cx - radius, 0), x_last = std::min(cx + radius, size_x_ - 1);
    for (int y = std::max(cy - radius, 0); y <= std::min(cy + radius, size_y_ - 1); ++y) {
      float* row = &cells[static_cast<std::size_t>(y) * size_x_];
      const double along = along_y[y - cy + radius];
      for (int x = x_first; x <= x_last; ++x)
        row[x] = withHit(row[x], static_cast<float>(along_x[x - cx + radius] * along));
    }
  });
}

void LikelihoodField::addFreeSpace(const PlacedScan& placed) {
  std::vector<float>& cells = levels_[0];
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

void LikelihoodField::ensureLevels(int levels) {
  for (int level = levels_ready_; level < std::min(levels, kLevels); ++level, levels_ready_ = level) {
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

}  // namespace hector_style_mapping
