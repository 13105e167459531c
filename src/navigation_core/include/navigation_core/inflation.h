#pragma once
// costmap_2d's inflation layer: costs falling off with the distance from lethal cells, so that
// planners keep the robot's centre away from walls.
//
//   distance 0 (the obstacle)             LETHAL (254)
//   distance <= inscribed radius          INSCRIBED (253): the footprint would touch the obstacle
//   further, up to the inflation radius   252 * exp(-cost_scaling_factor * (distance - inscribed radius))
//
// Distances are Euclidean between cell centres, to the nearest lethal cell as found by spreading
// out from every lethal cell through 4-connected neighbours in order of distance (costmap_2d's
// method). A cell keeps the larger of its cost and the inflated one; an unknown cell takes only an
// inscribed or lethal cost (any non-zero one with inflate_unknown), as upstream.
#include <cstdint>
#include <vector>

#include "navigation_core/costmap.h"

namespace navigation_core {

struct InflationOptions {  // costmap_2d's parameters and defaults
  double inflation_radius = 0.55;     // m
  double cost_scaling_factor = 10.0;  // 1/m
  bool inflate_unknown = false;
};

class Inflation {
 public:
  // Throws std::invalid_argument naming the parameter for a negative or non-finite value.
  Inflation(const InflationOptions& options, double inscribed_radius, double resolution);

  // The cost of a cell `distance` cells (Euclidean) from the nearest lethal cell.
  std::uint8_t costAt(double distance_cells) const;
  // Inflates every lethal cell of `map` (whose resolution must be the one given above).
  void apply(Costmap& map) const;

  unsigned cellRadius() const { return cell_radius_; }

 private:
  InflationOptions options_;
  double inscribed_radius_;
  double resolution_;
  unsigned cell_radius_;
  // By |dx|, |dy| up to cell_radius_ + 1: the cost there and the rank of the distance (which
  // bucket of the spreading front the cell joins; kBeyondRadius in inflation.cpp past the radius).
  std::vector<std::uint8_t> cost_table_;
  std::vector<unsigned> rank_table_;
  unsigned ranks_ = 0;
};

}  // namespace navigation_core
