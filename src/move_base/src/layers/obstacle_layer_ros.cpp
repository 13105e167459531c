// costmap_2d::ObstacleLayer (and VoxelLayer, run as one): the observation sources named in
// observation_sources mark and clear the costmap's obstacle grid.
#include <memory>
#include <sstream>

#include "move_base/layer_registry.h"
#include "move_base/ros_params.h"
#include "observation_source.h"

namespace move_base {
namespace {

class ObstacleLayerROS : public CostmapLayer {
 public:
  void configure(LayerContext& context, ros_params::Reader& params) override {
    navigation_core::LayeredCostmapOptions& options = context.options;
    if (context.first("obstacles")) {  // the one obstacle grid takes the first layer's settings
      options.obstacle_track_unknown_space = options.track_unknown_space;
      params.read("track_unknown_space", &options.obstacle_track_unknown_space);
      options.footprint_clearing_enabled = true;
      params.read("footprint_clearing_enabled", &options.footprint_clearing_enabled);
    }
    if (params.get("combination_method", 1) != 1)
      ROS_WARN("%s: only 1 (maximum) is supported; the obstacles are combined by maximum.",
               params.path("combination_method").c_str());
    for (const char* searched : {"obstacle_range", "raytrace_range"}) params.has(searched);  // by its sources
    double max_obstacle_height = 2.0;
    params.read("max_obstacle_height", &max_obstacle_height);
    std::istringstream names(params.get<std::string>("observation_sources", ""));
    std::string name;
    while (names >> name) {
      params.has(name);  // its namespace: read by the source
      ros_params::Reader source_params(ros::NodeHandle(context.nh, name));
      auto source = std::make_unique<ObservationSource>(name, context, source_params, max_obstacle_height);
      reportParams(source_params);
      if (!source->supported()) continue;
      sources_.push_back(std::move(source));
    }
  }

  void start(navigation_core::LayeredCostmap& /*costmap*/) override {
    for (const auto& source : sources_) source->subscribe();
  }

  void prepare(const ros::Time& now) override {
    for (const auto& source : sources_) source->keep(now);
  }

  void addObservations(navigation_core::LayeredCostmap& costmap, bool marking) const override {
    for (const auto& source : sources_) source->addTo(costmap, marking);
  }

  bool isCurrent(const ros::Time& now) const override {
    bool current = true;
    for (const auto& source : sources_) current = source->isCurrent(now) && current;  // each silent one warned
    return current;
  }

 private:
  std::vector<std::unique_ptr<ObservationSource>> sources_;
};

// A VoxelLayer's columns flattened to 2D cells: its voxel parameters are accepted without effect.
class VoxelLayerROS : public ObstacleLayerROS {
 public:
  void configure(LayerContext& context, ros_params::Reader& params) override {
    ROS_WARN("%s: a costmap_2d::VoxelLayer is run as an obstacle layer (its columns flattened to 2D cells).",
             context.nh.getNamespace().c_str());
    for (const char* name : {"origin_z", "z_resolution", "z_voxels", "unknown_threshold", "mark_threshold",
                             "publish_voxel_map"})
      params.has(name);
    ObstacleLayerROS::configure(context, params);
  }
};

}  // namespace

MOVE_BASE_REGISTER_LAYER("costmap_2d::ObstacleLayer", ObstacleLayerROS)
MOVE_BASE_REGISTER_LAYER("costmap_2d::VoxelLayer", VoxelLayerROS)

}  // namespace move_base
