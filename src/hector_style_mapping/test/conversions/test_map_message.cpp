// OccupancyGridMap -> nav_msgs/OccupancyGrid: geometry for map_server, and cell states.
#include <gtest/gtest.h>

#include "hector_style_mapping/ros/map_message.h"

namespace hector_style_mapping {
namespace {

TEST(FillOccupancyGrid, CarriesTheGeometryAndTheCellStates) {
  OccupancyGridMap grid(40, 20, 0.1, Eigen::Vector2d(-2.0, -1.0), 0.4, 0.9);
  ScanPoints scan;
  scan.points.emplace_back(1.05, 0.05);  // a hit in the cell whose corner is (1.0, 0.0)
  grid.updateByScan(scan, Pose2D{});

  nav_msgs::OccupancyGrid message;
  fillOccupancyGrid(grid, &message);
  EXPECT_FLOAT_EQ(message.info.resolution, 0.1f);
  EXPECT_EQ(message.info.width, 40u);
  EXPECT_EQ(message.info.height, 20u);
  EXPECT_DOUBLE_EQ(message.info.origin.position.x, -2.0);
  EXPECT_DOUBLE_EQ(message.info.origin.position.y, -1.0);
  EXPECT_DOUBLE_EQ(message.info.origin.orientation.w, 1.0);
  ASSERT_EQ(message.data.size(), 800u);
  auto at = [&](double x, double y) {  // cell containing map-frame point (x, y), row-major
    const int cx = static_cast<int>((x + 2.0) / 0.1), cy = static_cast<int>((y + 1.0) / 0.1);
    return message.data[cy * 40 + cx];
  };
  EXPECT_EQ(at(1.05, 0.05), 100);   // the hit
  EXPECT_EQ(at(0.55, 0.05), 0);     // on the ray: free
  EXPECT_EQ(at(0.05, 0.05), 0);     // where the ray started
  EXPECT_EQ(at(-1.5, 0.8), -1);     // never seen
}

}  // namespace
}  // namespace hector_style_mapping
