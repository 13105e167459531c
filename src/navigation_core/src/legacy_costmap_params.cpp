#include "navigation_core/legacy_costmap_params.h"

#include <sstream>

namespace navigation_core {

LegacyCostmapTranslation translateLegacyCostmapParams(const std::set<std::string>& present, bool static_map,
                                                      const std::string& map_type,
                                                      const std::string& observation_sources) {
  LegacyCostmapTranslation t;
  const auto move = [&](const std::string& name, const std::string& layer, bool keep_original = false) {
    if (present.count(name)) t.moves.push_back({name, layer + "/" + name, keep_original});
  };
  if (static_map) {
    t.plugins.push_back({"static_layer", "costmap_2d::StaticLayer"});
    for (const char* name : {"map_topic", "unknown_cost_value", "lethal_cost_threshold"}) move(name, "static_layer");
    move("track_unknown_space", "static_layer", true);  // the obstacle layer takes it too
  }
  if (map_type == "voxel") {
    t.plugins.push_back({"obstacle_layer", "costmap_2d::VoxelLayer"});
    for (const char* name : {"origin_z", "z_resolution", "z_voxels", "mark_threshold", "unknown_threshold",
                             "publish_voxel_map"})
      move(name, "obstacle_layer");
  } else {
    t.plugins.push_back({"obstacle_layer", "costmap_2d::ObstacleLayer"});
  }
  for (const char* name : {"max_obstacle_height", "raytrace_range", "obstacle_range", "track_unknown_space"})
    move(name, "obstacle_layer");
  std::istringstream sources(observation_sources);
  for (std::string source; sources >> source;) move(source, "obstacle_layer");
  move("observation_sources", "obstacle_layer");
  t.plugins.push_back({"inflation_layer", "costmap_2d::InflationLayer"});
  for (const char* name : {"cost_scaling_factor", "inflation_radius"}) move(name, "inflation_layer");
  return t;
}

}  // namespace navigation_core
