#include "odometry_slam/hit_counts.h"

#include <algorithm>
#include <limits>
#include <stdexcept>

namespace odometry_slam {

HitCounts::HitCounts(int size_x, int size_y) : size_x_(size_x), size_y_(size_y) {
  if (size_x <= 0 || size_y <= 0) throw std::invalid_argument("HitCounts: sizes must be > 0");
  const std::size_t cells = static_cast<std::size_t>(size_x) * static_cast<std::size_t>(size_y);
  hits_.assign(cells, 0);
  visits_.assign(cells, 0);
}

void HitCounts::clear() {
  std::fill(hits_.begin(), hits_.end(), 0);
  std::fill(visits_.begin(), visits_.end(), 0);
  seen_ = CellBox{};
}

void HitCounts::addLastUpdate(const hector_style_mapping::OccupancyGridMap& map) {
  if (map.sizeX() != size_x_ || map.sizeY() != size_y_)
    throw std::invalid_argument("HitCounts::addLastUpdate: the map's size differs from the counts'");
  for (const int index : map.lastUpdatedCells()) {
    // Halving both keeps the ratio once a cell has been seen 65535 times.
    if (visits_[index] == std::numeric_limits<std::uint16_t>::max()) {
      visits_[index] /= 2;
      hits_[index] /= 2;
    }
    ++visits_[index];
    if (map.lastUpdateMarkedOccupied(index)) ++hits_[index];
    const int x = index % size_x_;
    const int y = index / size_x_;
    if (seen_.empty()) {
      seen_ = CellBox{x, y, x + 1, y + 1};
    } else {
      seen_.x0 = std::min(seen_.x0, x);
      seen_.y0 = std::min(seen_.y0, y);
      seen_.x1 = std::max(seen_.x1, x + 1);
      seen_.y1 = std::max(seen_.y1, y + 1);
    }
  }
}

int8_t HitCounts::state(int x, int y, double occ_thresh) const {
  if (x < 0 || y < 0 || x >= size_x_ || y >= size_y_) return -1;
  const std::size_t index = static_cast<std::size_t>(y) * size_x_ + x;
  const int visits = visits_[index];
  if (visits == 0) return -1;
  return static_cast<double>(hits_[index]) / visits > occ_thresh ? 100 : 0;
}

void HitCounts::states(const CellBox& box, double occ_thresh, std::vector<int8_t>* out) const {
  out->resize(static_cast<std::size_t>(box.width()) * box.height());
  std::size_t i = 0;
  for (int y = box.y0; y < box.y1; ++y)
    for (int x = box.x0; x < box.x1; ++x) (*out)[i++] = state(x, y, occ_thresh);
}

}  // namespace odometry_slam
