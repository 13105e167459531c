#include "hector_style_mapping/ros/map_message.h"

namespace hector_style_mapping {

void fillOccupancyGrid(const OccupancyGridMap& grid, nav_msgs::OccupancyGrid* message) {
  nav_msgs::MapMetaData& info = message->info;
  info.resolution = static_cast<float>(grid.resolution());
  info.width = static_cast<uint32_t>(grid.sizeX());
  info.height = static_cast<uint32_t>(grid.sizeY());
  info.origin.position.x = grid.origin().x();
  info.origin.position.y = grid.origin().y();
  info.origin.position.z = 0.0;
  info.origin.orientation.x = info.origin.orientation.y = info.origin.orientation.z = 0.0;
  info.origin.orientation.w = 1.0;
  grid.toOccupancyData(&message->data);
}

}  // namespace hector_style_mapping
