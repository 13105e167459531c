#pragma once
// costmap_2d's Costmap2DROS: a layered costmap named `name` (global_costmap, local_costmap) whose
// parameters live in ~name, with its layers from the `plugins` list or, without one, from the
// pre-Hydro parameters as costmap_2d translates them (costmap_plugins.h); each layer's ROS side is
// found by its type name (layer_registry.h, src/layers/). It keeps itself up to date at
// update_frequency (sim time) in a thread of its own and publishes ~name/costmap,
// ~name/costmap_updates (at publish_frequency) and ~name/footprint.
#include <ros/ros.h>
#include <tf2_ros/buffer.h>

#include <atomic>
#include <deque>
#include <memory>
#include <mutex>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include "move_base/costmap_layer.h"
#include "navigation_core/layered_costmap.h"
#include "navigation_core/legacy_costmap_params.h"
#include "navigation_core/local_planner.h"

namespace move_base {

class CostmapROS {
 public:
  CostmapROS(const std::string& name, tf2_ros::Buffer& tf);
  ~CostmapROS();
  CostmapROS(const CostmapROS&) = delete;
  CostmapROS& operator=(const CostmapROS&) = delete;

  const std::string& name() const { return name_; }
  const std::string& globalFrame() const { return global_frame_; }
  const std::string& baseFrame() const { return base_frame_; }
  // The robot's pose in the global frame from tf; false (with a throttled warning) when tf has none
  // or it is older than transform_tolerance.
  bool robotPose(navigation_core::Pose2& pose) const;

  // The combined costmap; hold lock() while reading it.
  std::unique_lock<std::mutex> lock() const { return std::unique_lock<std::mutex>(mutex_); }
  const navigation_core::Costmap& costmap() const { return layers_->master(); }
  const navigation_core::Footprint& footprint() const { return footprint_; }
  double circumscribedRadius() const { return circumscribed_radius_; }
  // False while an observation source with an expected_update_rate has fallen silent.
  bool isCurrent() const;
  // Has a static layer that has not had its map yet.
  bool waitingForMap() const;

  // The obstacle layers back to unseen everywhere (clear_costmaps) or outside a square of side
  // `size` about (x, y) (clear_costmap_recovery); the costmap is recombined at once.
  void resetObstacles();
  void resetObstaclesOutside(double x, double y, double size);

 private:
  void addLayer(const navigation_core::LayerSpec& spec);
  void updateLoop();
  void updateMap();  // under mutex_
  void publishCostmap(bool full);
  void publishFootprint(const navigation_core::Pose2& pose);

  std::string name_;
  tf2_ros::Buffer& tf_;
  ros::NodeHandle nh_;  // ~name
  std::string global_frame_ = "map", base_frame_ = "base_link";
  double transform_tolerance_ = 0.3, update_frequency_ = 5.0, publish_frequency_ = 0.0;
  bool rolling_window_ = false, always_send_full_costmap_ = false;
  navigation_core::Footprint footprint_;
  double circumscribed_radius_ = 0.0;

  navigation_core::LayeredCostmapOptions options_;
  std::unique_ptr<navigation_core::LayeredCostmap> layers_;
  mutable std::mutex mutex_;  // before the plugins: their callbacks lock it until they are gone
  std::deque<LayerContext> contexts_;  // the plugins' (a deque: layers keep pointers to theirs)
  std::set<std::string> kinds_seen_;
  std::vector<std::unique_ptr<CostmapLayer>> plugins_;

  ros::Publisher costmap_pub_, updates_pub_, footprint_pub_;
  std::atomic<bool> running_{true};
  std::thread thread_;
};

}  // namespace move_base
