#include "hector_style_mapping_core/multi_resolution_map.h"

#include <stdexcept>
#include <string>

namespace hector_style_mapping {

namespace {

void throwIfInvalid(const MapperOptions& options) {
  const std::string problems = validate(options);
  if (!problems.empty()) {
    throw std::invalid_argument("MultiResolutionMap: " + problems);
  }
}

}  // namespace

MultiResolutionMap::MultiResolutionMap(const MapperOptions& options) {
  throwIfInvalid(options);
  const double side = options.map_size * options.map_resolution;
  const Eigen::Vector2d origin(-options.map_start_x * side, -options.map_start_y * side);
  levels_.reserve(static_cast<std::size_t>(options.map_multi_res_levels));
  for (int i = 0; i < options.map_multi_res_levels; ++i) {
    const int cells = options.map_size >> i;  // validate() guarantees the division is exact
    const double resolution = options.map_resolution * static_cast<double>(1 << i);
    levels_.emplace_back(cells, cells, resolution, origin, options.update_factor_free,
                         options.update_factor_occupied);
  }
}

void MultiResolutionMap::updateByScan(const ScanPoints& scan, const Pose2D& pose) {
  for (OccupancyGridMap& level : levels_) {
    level.updateByScan(scan, pose);
  }
}

void MultiResolutionMap::clear() {
  for (OccupancyGridMap& level : levels_) {
    level.clear();
  }
}

}  // namespace hector_style_mapping
