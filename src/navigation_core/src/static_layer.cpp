#include "navigation_core/static_layer.h"

#include <stdexcept>
#include <string>

#include "navigation_core/cost_values.h"

namespace navigation_core {

std::uint8_t staticCost(std::int8_t value, const StaticLayerOptions& options) {
  // costmap_2d compares the map byte as unsigned with the parameter cast the same way (-1 -> 255).
  const auto byte = static_cast<std::uint8_t>(value);
  if (byte == static_cast<std::uint8_t>(options.unknown_cost_value))
    return options.track_unknown_space ? kNoInformation : kFreeSpace;
  if (byte >= options.lethal_cost_threshold) return kLethalObstacle;
  if (options.trinary_costmap) return kFreeSpace;
  return static_cast<std::uint8_t>(static_cast<double>(byte) / options.lethal_cost_threshold * kLethalObstacle);
}

Costmap staticCostmap(const std::vector<std::int8_t>& data, unsigned width, unsigned height, double resolution,
                      double origin_x, double origin_y, const StaticLayerOptions& options) {
  if (data.size() != static_cast<std::size_t>(width) * height)
    throw std::invalid_argument("map: expected width * height = " + std::to_string(std::size_t(width) * height) +
                                " values, got " + std::to_string(data.size()));
  Costmap map(width, height, resolution, origin_x, origin_y);
  for (std::size_t i = 0; i < data.size(); ++i) map.costs()[i] = staticCost(data[i], options);
  return map;
}

}  // namespace navigation_core
