// costmap_2d::InflationLayer: costs that fall off with the distance to the nearest obstacle.
// navigation_core's LayeredCostmap inflates; this layer only reads its parameters.
#include "move_base/layer_registry.h"

namespace move_base {
namespace {

class InflationLayerROS : public CostmapLayer {
 public:
  void configure(LayerContext& context, ros_params::Reader& params) override {
    navigation_core::InflationOptions& inflation = context.options.inflation;
    params.read("inflation_radius", &inflation.inflation_radius);
    params.read("cost_scaling_factor", &inflation.cost_scaling_factor);
    params.read("inflate_unknown", &inflation.inflate_unknown);
    context.options.inflate = true;
  }
};

}  // namespace

MOVE_BASE_REGISTER_LAYER("costmap_2d::InflationLayer", InflationLayerROS)

}  // namespace move_base
