#pragma once
// costmap_2d's obstacle layer: sensor points mark cells as obstacles, and the rays to them clear
// the cells they pass through.
#include <vector>

#include "navigation_core/costmap.h"
#include "navigation_core/footprint.h"

namespace navigation_core {

struct Point3 {
  double x = 0.0, y = 0.0, z = 0.0;
};

// One sensor reading in the costmap's frame: where the sensor was, and the points it saw.
struct Observation {
  Point3 origin;
  std::vector<Point3> points;
};

struct ObstacleLayerOptions {  // an observation source's parameters and costmap_2d's defaults
  double obstacle_range = 2.5;       // m: points farther from the sensor do not mark
  double raytrace_range = 3.0;       // m: rays clear no farther than this
  double min_obstacle_height = 0.0;  // m: points outside [min, max] height do not mark
  double max_obstacle_height = 2.0;
  bool marking = true;
  bool clearing = true;
};

// Clears along every ray (the cells from the sensor's to just before the point's, up to
// raytrace_range), then marks the points (as costmap_2d: all clearing first, then marking).
void applyObservation(Costmap& layer, const Observation& observation, const ObstacleLayerOptions& options);

// ObstacleLayer's footprint_clearing_enabled: the cells under the robot (inside its footprint at
// `pose`, and every cell its outline crosses) set free. The robot occupies them, so what a sensor
// marked there is the robot itself, a reflection, or a wall the padding merely grazes; left marked
// it would forbid every move, rotating away included.
void clearFootprint(Costmap& layer, const Footprint& footprint, const Pose2& pose);

}  // namespace navigation_core
