// costmap_2d::StaticLayer: the map on map_topic (and, with subscribe_to_updates, its
// <map_topic>_updates) written into the costmap.
#include <map_msgs/OccupancyGridUpdate.h>
#include <nav_msgs/OccupancyGrid.h>
#include <tf2/utils.h>

#include <cmath>

#include "move_base/layer_registry.h"
#include "move_base/ros_params.h"
#include "navigation_core/static_layer.h"

namespace move_base {
namespace {

namespace nc = navigation_core;

class StaticLayerROS : public CostmapLayer {
 public:
  void configure(LayerContext& context, ros_params::Reader& params) override {
    context_ = &context;
    params.read("track_unknown_space", &options_.track_unknown_space);
    params.read("unknown_cost_value", &options_.unknown_cost_value);
    params.read("lethal_cost_threshold", &options_.lethal_cost_threshold);
    params.read("trinary_costmap", &options_.trinary_costmap);
    params.read("first_map_only", &first_map_only_);
    if (params.get("use_maximum", false))
      ROS_WARN("%s/use_maximum: not supported; the static map is written over the costmap.",
               context.nh.getNamespace().c_str());
    params.read("map_topic", &topic_);
    params.read("subscribe_to_updates", &subscribe_to_updates_);
  }

  void start(nc::LayeredCostmap& costmap) override {
    costmap_ = &costmap;
    ros::NodeHandle node;
    subscribers_.push_back(node.subscribe(topic_, 1, &StaticLayerROS::onMap, this));
    if (subscribe_to_updates_) subscribers_.push_back(node.subscribe(topic_ + "_updates", 10, &StaticLayerROS::onUpdate, this));
  }

  bool waitingForMap() const override { return !have_map_; }

 private:
  void onMap(const nav_msgs::OccupancyGridConstPtr& map) {
    std::lock_guard<std::mutex> guard(context_->mutex);
    if (first_map_only_ && have_map_) return;
    const auto& info = map->info;
    const char* ns = context_->nh.getNamespace().c_str();
    if (map->data.size() != static_cast<std::size_t>(info.width) * info.height || info.resolution <= 0) {
      ROS_ERROR("%s: the map on %s is malformed (%zu values for %u x %u cells, resolution %g); ignored.", ns,
                topic_.c_str(), map->data.size(), info.width, info.height, info.resolution);
      return;
    }
    if (std::abs(tf2::getYaw(info.origin.orientation)) > 1e-3)
      ROS_WARN_ONCE("%s: the map's origin is rotated; the rotation is ignored, as costmap_2d does.", ns);
    map_ = *map;
    const std::string map_frame = frameId(map->header.frame_id);
    if (!context_->rolling_window && !map_frame.empty() && map_frame != context_->global_frame)
      ROS_WARN_THROTTLE(10, "%s: the map is in frame %s, the costmap's global_frame is %s; the map is used as if "
                        "it were in %s.", ns, map_frame.c_str(), context_->global_frame.c_str(),
                        context_->global_frame.c_str());
    apply();
    have_map_ = true;
  }

  void onUpdate(const map_msgs::OccupancyGridUpdateConstPtr& update) {
    std::lock_guard<std::mutex> guard(context_->mutex);
    if (!have_map_ || first_map_only_) return;
    const auto& info = map_.info;
    if (update->x < 0 || update->y < 0 || update->x + update->width > info.width ||
        update->y + update->height > info.height ||
        update->data.size() != static_cast<std::size_t>(update->width) * update->height) {
      ROS_ERROR("%s: a map update outside the map or malformed; ignored.", context_->nh.getNamespace().c_str());
      return;
    }
    for (unsigned y = 0; y < update->height; ++y)
      for (unsigned x = 0; x < update->width; ++x)
        map_.data[(update->y + y) * info.width + update->x + x] = update->data[y * update->width + x];
    apply();
  }

  void apply() {
    const auto& info = map_.info;
    costmap_->setStaticMap(nc::staticCostmap(map_.data, info.width, info.height, info.resolution,
                                             info.origin.position.x, info.origin.position.y, options_));
  }

  LayerContext* context_ = nullptr;
  nc::LayeredCostmap* costmap_ = nullptr;
  nc::StaticLayerOptions options_;  // upstream's defaults: track_unknown_space true, trinary true ...
  bool first_map_only_ = false, subscribe_to_updates_ = false, have_map_ = false;
  std::string topic_ = "map";
  nav_msgs::OccupancyGrid map_;  // kept for updates
  std::vector<ros::Subscriber> subscribers_;
};

}  // namespace

MOVE_BASE_REGISTER_LAYER("costmap_2d::StaticLayer", StaticLayerROS)

}  // namespace move_base
