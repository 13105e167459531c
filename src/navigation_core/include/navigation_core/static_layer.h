#pragma once
// costmap_2d's static layer: an OccupancyGrid's values (-1 unknown, 0..100 occupied probability
// in per cent) as costs.
#include <cstdint>
#include <vector>

#include "navigation_core/costmap.h"

namespace navigation_core {

struct StaticLayerOptions {  // costmap_2d's parameters and defaults
  bool track_unknown_space = true;   // unknown stays unknown (else it is free)
  int unknown_cost_value = -1;       // the map value that means unknown
  int lethal_cost_threshold = 100;   // values from here on are obstacles
  bool trinary_costmap = true;       // free, lethal or unknown only (else scaled)
};

// One map value as a cost.
std::uint8_t staticCost(std::int8_t value, const StaticLayerOptions& options);

// A costmap the size, resolution and origin of the map (data row-major, x fastest, as in
// nav_msgs/OccupancyGrid). Throws std::invalid_argument if data does not hold width * height values.
Costmap staticCostmap(const std::vector<std::int8_t>& data, unsigned width, unsigned height, double resolution,
                      double origin_x, double origin_y, const StaticLayerOptions& options);

}  // namespace navigation_core
