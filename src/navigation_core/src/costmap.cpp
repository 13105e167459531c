#include "navigation_core/costmap.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace navigation_core {

Costmap::Costmap(unsigned size_x, unsigned size_y, double resolution, double origin_x, double origin_y,
                 std::uint8_t default_value)
    : size_x_(size_x), size_y_(size_y), resolution_(resolution), origin_x_(origin_x), origin_y_(origin_y) {
  if (!(resolution > 0) || !std::isfinite(resolution))
    throw std::invalid_argument("costmap resolution: expected a positive number of metres, got " +
                                std::to_string(resolution));
  if (!std::isfinite(origin_x) || !std::isfinite(origin_y))
    throw std::invalid_argument("costmap origin: expected finite coordinates");
  costs_.assign(static_cast<std::size_t>(size_x) * size_y, default_value);
}

bool Costmap::worldToMap(double wx, double wy, unsigned& mx, unsigned& my) const {
  const double fx = (wx - origin_x_) / resolution_, fy = (wy - origin_y_) / resolution_;
  if (!(fx >= 0 && fy >= 0 && fx < size_x_ && fy < size_y_)) return false;  // also NaN
  mx = static_cast<unsigned>(fx);
  my = static_cast<unsigned>(fy);
  return true;
}

void Costmap::mapToWorld(unsigned mx, unsigned my, double& wx, double& wy) const {
  wx = origin_x_ + (mx + 0.5) * resolution_;
  wy = origin_y_ + (my + 0.5) * resolution_;
}

unsigned Costmap::cellDistance(double world_distance) const {
  return static_cast<unsigned>(std::max(0.0, std::ceil(world_distance / resolution_)));
}

void Costmap::reset(std::uint8_t value) { std::fill(costs_.begin(), costs_.end(), value); }

}  // namespace navigation_core
