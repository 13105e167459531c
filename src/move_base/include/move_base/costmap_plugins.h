#pragma once
// Which layers a costmap has: its `plugins` list ({name, type} each) or, without one, the layers
// costmap_2d makes of the pre-Hydro parameters (static_map, observation_sources, ...), whose values
// are moved into the layers' namespaces on the parameter server as costmap_2d moves them.
#include <ros/ros.h>

#include <vector>

#include "navigation_core/legacy_costmap_params.h"
#include "ros_params/reader.h"

namespace move_base {

// `params`: a Reader on the costmap's namespace `nh`. A malformed entry is an error said here,
// and left out.
std::vector<navigation_core::LayerSpec> costmapPlugins(const ros::NodeHandle& nh, ros_params::Reader& params);

}  // namespace move_base
