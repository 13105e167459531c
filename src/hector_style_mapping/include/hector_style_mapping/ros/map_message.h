#ifndef HECTOR_STYLE_MAPPING_ROS_MAP_MESSAGE_H
#define HECTOR_STYLE_MAPPING_ROS_MAP_MESSAGE_H

#include <nav_msgs/OccupancyGrid.h>

#include "hector_style_mapping_core/occupancy_grid_map.h"

namespace hector_style_mapping {

// `grid` as nav_msgs/OccupancyGrid info and data (-1 unknown, 0 free, 100 occupied); the header is the
// caller's. info.origin is the map-frame pose of cell (0, 0)'s corner, as map_server expects.
void fillOccupancyGrid(const OccupancyGridMap& grid, nav_msgs::OccupancyGrid* message);

}  // namespace hector_style_mapping

#endif  // HECTOR_STYLE_MAPPING_ROS_MAP_MESSAGE_H
