#pragma once
// Pre-Hydro costmap parameters (`static_map: true`, a top-level `observation_sources`,
// `inflation_radius`, ...) as costmap_2d translates them when a costmap has no `plugins` list:
// a static layer if static_map, an obstacle layer (a voxel layer for map_type: voxel), an inflation
// layer, and each layer's parameters moved into its namespace. Names only: the ROS layer moves the
// values.
#include <set>
#include <string>
#include <vector>

namespace navigation_core {

struct LayerSpec {
  std::string name;  // the namespace its parameters live in
  std::string type;  // costmap_2d's plugin type
};

struct ParamMove {
  std::string from;    // relative to the costmap's namespace
  std::string to;
  bool keep_original;  // costmap_2d copies track_unknown_space to the static layer and moves the rest
};

struct LegacyCostmapTranslation {
  std::vector<LayerSpec> plugins;
  std::vector<ParamMove> moves;
};

// `present`: the costmap namespace's top-level parameter names; the other arguments its
// static_map, map_type and observation_sources values (false / "" when absent).
LegacyCostmapTranslation translateLegacyCostmapParams(const std::set<std::string>& present, bool static_map,
                                                      const std::string& map_type,
                                                      const std::string& observation_sources);

}  // namespace navigation_core
