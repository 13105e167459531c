#include "hector_style_mapping_core/occupancy_grid_map.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "hector_style_mapping_core/floor_to_int.h"

namespace hector_style_mapping {

namespace {

float logOddsOf(double probability) { return static_cast<float>(std::log(probability / (1.0 - probability))); }

float probabilityOf(float log_odds) { return 1.0f / (1.0f + std::exp(-log_odds)); }

bool insideHalfOpen(double value, double size) { return value >= 0.0 && value < size; }

}  // namespace

OccupancyGridMap::OccupancyGridMap(int size_x, int size_y, double resolution, const Eigen::Vector2d& origin,
                                   double update_factor_free, double update_factor_occupied)
    : size_x_(size_x),
      size_y_(size_y),
      resolution_(resolution),
      inverse_resolution_(1.0 / resolution),
      origin_(origin),
      log_odds_free_(0.0f),
      log_odds_occupied_(0.0f) {
  const bool factors_ok = update_factor_free > 0.0 && update_factor_free < 1.0 && update_factor_occupied > 0.0 &&
                          update_factor_occupied < 1.0;
  if (!(size_x > 0 && size_y > 0 && resolution > 0.0 && std::isfinite(resolution) && origin.allFinite() &&
        factors_ok) ||
      static_cast<long long>(size_x) * size_y > std::numeric_limits<int>::max()) {
    std::ostringstream message;
    message << "OccupancyGridMap: invalid geometry or update factors (size " << size_x << " x " << size_y
            << ", resolution " << resolution << ", origin " << origin.transpose() << ", update factors "
            << update_factor_free << " / " << update_factor_occupied << ")";
    throw std::invalid_argument(message.str());
  }
  log_odds_free_ = logOddsOf(update_factor_free);
  log_odds_occupied_ = logOddsOf(update_factor_occupied);
  const std::size_t cell_count = static_cast<std::size_t>(size_x) * static_cast<std::size_t>(size_y);
  log_odds_.assign(cell_count, 0.0f);
  match_value_.assign(cell_count, 0.0f);
  stamp_.assign(cell_count, 0u);
}

void OccupancyGridMap::clear() {
  std::fill(log_odds_.begin(), log_odds_.end(), 0.0f);
  std::fill(match_value_.begin(), match_value_.end(), 0.0f);
  std::fill(stamp_.begin(), stamp_.end(), 0u);
  marked_cells_.clear();
  free_stamp_ = 1;
  occupied_stamp_ = 2;
}

void OccupancyGridMap::updateByScan(const ScanPoints& scan, const Pose2D& pose) {
  // Stamps grow by two per scan; after about two billion scans, fold every touched cell back to the oldest stamp.
  if (occupied_stamp_ >= std::numeric_limits<std::uint32_t>::max() - 2u) {
    for (std::uint32_t& stamp : stamp_) {
      stamp = stamp == 0u ? 0u : 1u;
    }
    free_stamp_ = 2;
    occupied_stamp_ = 3;
  }

  const double c = std::cos(pose.theta);
  const double s = std::sin(pose.theta);
  // Base frame -> continuous cell coordinates, where cell (x, y) spans [x, x + 1) x [y, y + 1).
  const auto toCellCoordinates = [&](const Eigen::Vector2d& base_point) -> Eigen::Vector2d {
    const Eigen::Vector2d map_point(pose.x + c * base_point.x() - s * base_point.y(),
                                    pose.y + s * base_point.x() + c * base_point.y());
    return (map_point - origin_) * inverse_resolution_;
  };

  marked_cells_.clear();
  const Eigen::Vector2d start = toCellCoordinates(scan.origin);
  if (!start.allFinite()) {
    return;
  }
  for (const Eigen::Vector2d& point : scan.points) {
    if (!point.allFinite()) {
      continue;
    }
    markRay(start, toCellCoordinates(point), true);
  }
  for (const Eigen::Vector2d& point : scan.free_rays) {
    if (point.allFinite()) markRay(start, toCellCoordinates(point), false);
  }

  // Applied only now that the scan is fully marked, so an occupied mark that overrides an earlier free mark of the
  // same scan never has to undo a clamped update.
  for (const int index : marked_cells_) {
    const float change = stamp_[index] == occupied_stamp_ ? log_odds_occupied_ : log_odds_free_;
    const float log_odds = std::clamp(log_odds_[index] + change, -kLogOddsLimit, kLogOddsLimit);
    log_odds_[index] = log_odds;
    match_value_[index] = probabilityOf(log_odds);
  }
  free_stamp_ += 2;
  occupied_stamp_ += 2;
}

void OccupancyGridMap::markRay(const Eigen::Vector2d& start, const Eigen::Vector2d& end, bool end_is_hit) {
  const double size_x = size_x_;
  const double size_y = size_y_;
  const bool start_inside = insideHalfOpen(start.x(), size_x) && insideHalfOpen(start.y(), size_y);
  const bool end_inside = insideHalfOpen(end.x(), size_x) && insideHalfOpen(end.y(), size_y);
  if (start_inside && end_inside) {
    markLine(static_cast<int>(start.x()), static_cast<int>(start.y()), static_cast<int>(end.x()),
             static_cast<int>(end.y()), end_is_hit);
    return;
  }

  // Liang-Barsky clipping of the segment to the map rectangle [0, size_x] x [0, size_y].
  const Eigen::Vector2d delta = end - start;
  double t_enter = 0.0;
  double t_leave = 1.0;
  const double sizes[2] = {size_x, size_y};
  for (int axis = 0; axis < 2; ++axis) {
    if (delta[axis] == 0.0) {
      if (!(start[axis] >= 0.0 && start[axis] <= sizes[axis])) {
        return;
      }
      continue;
    }
    double t_low = (0.0 - start[axis]) / delta[axis];
    double t_high = (sizes[axis] - start[axis]) / delta[axis];
    if (t_low > t_high) {
      std::swap(t_low, t_high);
    }
    t_enter = std::max(t_enter, t_low);
    t_leave = std::min(t_leave, t_high);
  }
  if (!(t_enter <= t_leave)) {
    return;  // the ray misses the map (or the arithmetic overflowed)
  }
  const Eigen::Vector2d first = start_inside ? start : Eigen::Vector2d(start + t_enter * delta);
  const Eigen::Vector2d last = end_inside ? end : Eigen::Vector2d(start + t_leave * delta);
  if (!first.allFinite() || !last.allFinite()) {
    return;
  }
  // A clipped point lies on the rectangle's edge up to rounding; keep its cell inside the map.
  const auto cellIndex = [](double coordinate, int size) {
    return static_cast<int>(std::clamp(std::floor(coordinate), 0.0, static_cast<double>(size - 1)));
  };
  markLine(cellIndex(first.x(), size_x_), cellIndex(first.y(), size_y_), cellIndex(last.x(), size_x_),
           cellIndex(last.y(), size_y_), end_inside && end_is_hit);
}

void OccupancyGridMap::markLine(int x0, int y0, int x1, int y1, bool end_is_hit) {
  const int dx = std::abs(x1 - x0);
  const int dy = std::abs(y1 - y0);
  const int step_x = x0 < x1 ? 1 : -1;
  const int step_y = y0 < y1 ? size_x_ : -size_x_;
  int index = y0 * size_x_ + x0;
  int error = dx - dy;
  // Integer Bresenham: max(dx, dy) steps, each one cell along the major axis and sometimes one along the minor.
  for (int step = std::max(dx, dy); step > 0; --step) {
    markFree(index);
    const int doubled_error = 2 * error;
    if (doubled_error > -dy) {
      error -= dy;
      index += step_x;
    }
    if (doubled_error < dx) {
      error += dx;
      index += step_y;
    }
  }
  if (end_is_hit) {
    markOccupied(index);
  } else {
    markFree(index);
  }
}

void OccupancyGridMap::markFree(int index) {
  if (stamp_[index] < free_stamp_) {
    stamp_[index] = free_stamp_;
    marked_cells_.push_back(index);
  }
}

void OccupancyGridMap::markOccupied(int index) {
  if (stamp_[index] < occupied_stamp_) {
    if (stamp_[index] != free_stamp_) {
      marked_cells_.push_back(index);
    }
    stamp_[index] = occupied_stamp_;
  }
}

float OccupancyGridMap::cellValueOrZero(int x, int y) const {
  return isInside(x, y) ? match_value_[static_cast<std::size_t>(y) * size_x_ + x] : 0.0f;
}

double OccupancyGridMap::interpolate(const Eigen::Vector2d& p, Eigen::Vector2d* gradient) const {
  // Continuous coordinates in which cell centres sit on integers.
  const double u = (p.x() - origin_.x()) * inverse_resolution_ - 0.5;
  const double v = (p.y() - origin_.y()) * inverse_resolution_ - 0.5;
  // Written as !(inside) so that NaN lands here too.
  if (!(u > -1.0 && v > -1.0 && u < size_x_ && v < size_y_)) {
    if (gradient != nullptr) {
      gradient->setZero();
    }
    return 0.0;
  }
  const int x = floorToInt(u);
  const int y = floorToInt(v);
  const double u_floor = x;
  const double v_floor = y;
  const double fx = u - u_floor;  // weight of the right-hand column
  const double fy = v - v_floor;  // weight of the upper row

  double v00, v10, v01, v11;  // v<column offset><row offset>
  if (x >= 0 && y >= 0 && x + 1 < size_x_ && y + 1 < size_y_) {
    const float* lower = match_value_.data() + static_cast<std::size_t>(y) * size_x_ + x;
    const float* upper = lower + size_x_;
    v00 = lower[0];
    v10 = lower[1];
    v01 = upper[0];
    v11 = upper[1];
  } else {
    v00 = cellValueOrZero(x, y);
    v10 = cellValueOrZero(x + 1, y);
    v01 = cellValueOrZero(x, y + 1);
    v11 = cellValueOrZero(x + 1, y + 1);
  }

  const double lower_row = v00 + fx * (v10 - v00);
  const double upper_row = v01 + fx * (v11 - v01);
  if (gradient != nullptr) {
    // d/du of the bilinear form is the x-difference blended by the row weight fy, d/dv the y-difference blended
    // by the column weight fx; dividing by the resolution turns per-cell into per-metre.
    const double d_du = (1.0 - fy) * (v10 - v00) + fy * (v11 - v01);
    const double d_dv = upper_row - lower_row;
    *gradient = Eigen::Vector2d(d_du, d_dv) * inverse_resolution_;
  }
  return lower_row + fy * (upper_row - lower_row);
}

void OccupancyGridMap::toOccupancyData(std::vector<int8_t>* data) const {
  data->resize(log_odds_.size());
  for (std::size_t i = 0; i < log_odds_.size(); ++i) {
    const float log_odds = log_odds_[i];
    int8_t state = -1;
    if (stamp_[i] != 0u) {
      if (log_odds < 0.0f) {
        state = 0;
      } else if (log_odds > 0.0f) {
        state = 100;
      }
    }
    (*data)[i] = state;
  }
}

double OccupancyGridMap::logOdds(int x, int y) const {
  return isInside(x, y) ? log_odds_[static_cast<std::size_t>(y) * size_x_ + x] : 0.0;
}

double OccupancyGridMap::probability(int x, int y) const {
  return isUnknown(x, y) ? 0.5 : 1.0 / (1.0 + std::exp(-logOdds(x, y)));
}

bool OccupancyGridMap::isOccupied(int x, int y) const { return !isUnknown(x, y) && logOdds(x, y) > 0.0; }

bool OccupancyGridMap::isFree(int x, int y) const { return !isUnknown(x, y) && logOdds(x, y) < 0.0; }

bool OccupancyGridMap::isUnknown(int x, int y) const {
  return !isInside(x, y) || stamp_[static_cast<std::size_t>(y) * size_x_ + x] == 0u;
}

Eigen::Vector2i OccupancyGridMap::cellOf(const Eigen::Vector2d& p) const {
  const Eigen::Vector2d cell = ((p - origin_) * inverse_resolution_).array().floor();
  if (!cell.allFinite()) {
    return Eigen::Vector2i(-1, -1);
  }
  // Clamped to int's range so far-away points cannot overflow the conversion.
  const double limit = static_cast<double>(std::numeric_limits<int>::max() / 2);
  return cell.cwiseMax(-limit).cwiseMin(limit).cast<int>();
}

Eigen::Vector2d OccupancyGridMap::cellCenter(int x, int y) const {
  return origin_ + (Eigen::Vector2d(x, y).array() + 0.5).matrix() * resolution_;
}

}  // namespace hector_style_mapping
