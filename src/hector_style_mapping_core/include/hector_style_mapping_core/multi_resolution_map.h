#ifndef HECTOR_STYLE_MAPPING_CORE_MULTI_RESOLUTION_MAP_H
#define HECTOR_STYLE_MAPPING_CORE_MULTI_RESOLUTION_MAP_H

#include <vector>

#include "hector_style_mapping_core/mapper_options.h"
#include "hector_style_mapping_core/occupancy_grid_map.h"
#include "hector_style_mapping_core/pose_2d.h"
#include "hector_style_mapping_core/scan_points.h"

namespace hector_style_mapping {

// The same area mapped at map_multi_res_levels resolutions. Level 0 is the finest (map_resolution, map_size cells
// per side); level i has resolution map_resolution * 2^i and map_size / 2^i cells per side, and every level has
// the same origin corner (-map_start_x, -map_start_y) * map_size * map_resolution, so all cover the same area.
class MultiResolutionMap {
 public:
  // Throws std::invalid_argument with validate()'s message if the options are not valid.
  explicit MultiResolutionMap(const MapperOptions& options);

  int levels() const { return static_cast<int>(levels_.size()); }
  // Throws std::out_of_range unless 0 <= i < levels().
  const OccupancyGridMap& level(int i) const { return levels_.at(static_cast<std::size_t>(i)); }
  const OccupancyGridMap& finest() const { return levels_.front(); }

  // The scan's ray update (OccupancyGridMap::updateByScan) applied to every level.
  void updateByScan(const ScanPoints& scan, const Pose2D& pose);
  // Every cell of every level back to unknown.
  void clear();

 private:
  std::vector<OccupancyGridMap> levels_;
};

}  // namespace hector_style_mapping

#endif  // HECTOR_STYLE_MAPPING_CORE_MULTI_RESOLUTION_MAP_H
