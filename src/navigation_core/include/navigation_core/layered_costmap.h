#pragma once
// costmap_2d's layered costmap with its three standard layers, combined as Costmap2DROS does on
// each update: the static map written over the master (StaticLayer without use_maximum), the
// obstacle grid's known cells by maximum (ObstacleLayer's default combination), then inflation.
// A rolling window (the local costmap) keeps the robot in its centre, carrying the obstacle cells
// it still covers when it moves, as costmap_2d's updateOrigin does.
#include <optional>

#include "navigation_core/costmap.h"
#include "navigation_core/footprint.h"
#include "navigation_core/inflation.h"
#include "navigation_core/obstacle_layer.h"
#include "navigation_core/static_layer.h"

namespace navigation_core {

struct LayeredCostmapOptions {
  double width = 10.0, height = 10.0;  // m (a static map's size replaces them unless rolling)
  double resolution = 0.05;
  double origin_x = 0.0, origin_y = 0.0;
  bool rolling_window = false;
  bool track_unknown_space = false;  // cells nothing has seen are unknown (else free)
  bool inflate = true;
  InflationOptions inflation;
  ObstacleLayerOptions obstacles;
  // The obstacle layer's own track_unknown_space: without it, the cells its sensors have not seen
  // are free and, combined by maximum, free the master's unknown cells too (upstream's behaviour).
  // With no obstacle layer at all, leave it true: an all-unknown grid changes nothing.
  bool obstacle_track_unknown_space = true;
  // The obstacle layer's footprint_clearing_enabled (upstream's default): on each update the cells
  // under the robot's footprint are freed in the obstacle grid. Off where there is no obstacle layer.
  bool footprint_clearing_enabled = true;
};

class LayeredCostmap {
 public:
  LayeredCostmap(const LayeredCostmapOptions& options, const Footprint& footprint);

  // The static layer's map. A costmap that does not roll takes its size, resolution and origin
  // (keeping its obstacles if they have not changed). The master is combined again at once.
  void setStaticMap(const Costmap& static_costs);
  // Marks and clears the obstacle grid (kept between updates, as the obstacle layer's), with the
  // options' ranges or an observation source's own.
  void addObservation(const Observation& observation);
  void addObservation(const Observation& observation, const ObstacleLayerOptions& source);
  // Rolling window: centre the costmap on the robot (origin snapped to whole cells).
  void updateOrigin(double robot_x, double robot_y);
  // Combines the layers into the master and returns it; with the robot's pose, first frees the
  // obstacle cells under its footprint (footprint_clearing_enabled).
  const Costmap& update(const std::optional<Pose2>& robot = std::nullopt);

  const Costmap& master() const { return master_; }
  const Footprint& footprint() const { return footprint_; }
  // Every obstacle cell back to unseen (clear_costmaps).
  void resetObstacles();
  // The obstacle cells outside the square of side `size` centred on (x, y) back to unseen, as
  // clear_costmap_recovery's resets do.
  void resetObstaclesOutside(double x, double y, double size);

 private:
  std::uint8_t defaultCost() const;
  std::uint8_t unseenObstacleCost() const;

  LayeredCostmapOptions options_;
  Footprint footprint_;
  Inflation inflation_;
  Costmap master_, obstacles_;
  std::optional<Costmap> static_;
};

}  // namespace navigation_core
