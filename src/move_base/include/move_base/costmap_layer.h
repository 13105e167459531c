#pragma once
// One layer of a costmap on its ROS side, as a costmap_2d plugin is: it reads its parameters from
// ~<costmap>/<layer>, sets its part of the layered costmap's options, then (once the costmap
// exists) subscribes to what it needs and feeds the costmap. navigation_core's LayeredCostmap
// does the arithmetic; a layer only turns ROS messages into its calls. A new layer is one file
// with one MOVE_BASE_REGISTER_LAYER line (layer_registry.h).
#include <ros/ros.h>
#include <tf2_ros/buffer.h>

#include <mutex>
#include <set>
#include <string>

#include "navigation_core/layered_costmap.h"
#include "ros_params/reader.h"

namespace move_base {

// What a layer is told about the costmap it belongs to.
struct LayerContext {
  std::string name;       // the layer's name in `plugins`
  ros::NodeHandle nh;     // ~<costmap>/<layer>
  tf2_ros::Buffer& tf;
  std::string global_frame;
  double transform_tolerance;
  bool rolling_window;
  navigation_core::LayeredCostmapOptions& options;  // the costmap's, before it is made
  std::mutex& mutex;  // held while anyone touches the layered costmap
  std::set<std::string>& kinds_seen;  // for first(): kinds of layer configured before this one

  // True for the first layer of `kind` in the costmap (only it sets the kind's shared options,
  // as the one obstacle grid takes the first obstacle layer's track_unknown_space).
  bool first(const std::string& kind) { return kinds_seen.insert(kind).second; }
};

class CostmapLayer {
 public:
  virtual ~CostmapLayer() = default;

  // Reads the layer's parameters through `params` (a Reader on ~<costmap>/<layer>: what it never
  // asks for is warned about as misspelt) and sets its part of context.options.
  virtual void configure(LayerContext& context, ros_params::Reader& params) = 0;
  // The costmap exists: subscribe. Callbacks hold context.mutex while they touch `costmap`.
  virtual void start(navigation_core::LayeredCostmap& /*costmap*/) {}
  // Under the mutex, before each update: take in what has arrived since the last one.
  virtual void prepare(const ros::Time& /*now*/) {}
  // Under the mutex: add the layer's observations, clearing only or marking only. Every layer
  // clears before any marks, as costmap_2d's obstacle layer does with its sources, so one sensor's
  // free rays do not erase what another saw.
  virtual void addObservations(navigation_core::LayeredCostmap& /*costmap*/, bool /*marking*/) const {}
  // Under the mutex: false while a sensor it expects has fallen silent.
  virtual bool isCurrent(const ros::Time& /*now*/) const { return true; }
  // Under the mutex: true while it waits for a map it needs.
  virtual bool waitingForMap() const { return false; }
};

}  // namespace move_base
