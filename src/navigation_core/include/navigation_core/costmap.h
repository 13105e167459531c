#pragma once
// A 2D grid of costs in a world frame, as costmap_2d's Costmap2D: cells of `resolution` metres,
// cell (0, 0)'s corner at the origin, row-major with x fastest. World <-> cell conversions follow
// costmap_2d: a point belongs to the cell whose square contains it; a cell's world point is its centre.
#include <cstdint>
#include <vector>

namespace navigation_core {

class Costmap {
 public:
  Costmap() = default;
  // Throws std::invalid_argument for a resolution that is not positive and finite.
  Costmap(unsigned size_x, unsigned size_y, double resolution, double origin_x, double origin_y,
          std::uint8_t default_value = 0);

  unsigned sizeX() const { return size_x_; }
  unsigned sizeY() const { return size_y_; }
  double resolution() const { return resolution_; }
  double originX() const { return origin_x_; }
  double originY() const { return origin_y_; }

  std::uint8_t cost(unsigned mx, unsigned my) const { return costs_[index(mx, my)]; }
  void setCost(unsigned mx, unsigned my, std::uint8_t cost) { costs_[index(mx, my)] = cost; }
  unsigned index(unsigned mx, unsigned my) const { return my * size_x_ + mx; }
  const std::vector<std::uint8_t>& costs() const { return costs_; }
  std::vector<std::uint8_t>& costs() { return costs_; }

  // The cell containing (wx, wy); false (and mx, my untouched) if that is outside the map.
  bool worldToMap(double wx, double wy, unsigned& mx, unsigned& my) const;
  // The centre of cell (mx, my).
  void mapToWorld(unsigned mx, unsigned my, double& wx, double& wy) const;
  // A distance in metres as whole cells, rounded up (costmap_2d's cellDistance).
  unsigned cellDistance(double world_distance) const;

  // Every cell to `value`.
  void reset(std::uint8_t value);

 private:
  unsigned size_x_ = 0, size_y_ = 0;
  double resolution_ = 0.05;
  double origin_x_ = 0.0, origin_y_ = 0.0;
  std::vector<std::uint8_t> costs_;
};

}  // namespace navigation_core
