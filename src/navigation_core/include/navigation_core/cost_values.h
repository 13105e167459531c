#pragma once
// A costmap cell's cost, as costmap_2d defines it (cost_values.h): what planners, rviz's costmap
// colour scheme and every costmap_2d user reads.
#include <cstdint>

namespace navigation_core {

constexpr std::uint8_t kFreeSpace = 0;
constexpr std::uint8_t kInscribedInflatedObstacle = 253;  // the robot's centre here means a collision
constexpr std::uint8_t kLethalObstacle = 254;             // an obstacle in this cell
constexpr std::uint8_t kNoInformation = 255;              // unknown

}  // namespace navigation_core
