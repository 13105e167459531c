#pragma once
// Costmap layers by costmap_2d's type names, as the simulator's plugins are found by library
// name. Each layer's .cpp registers itself with one line:
//
//   MOVE_BASE_REGISTER_LAYER("costmap_2d::InflationLayer", InflationLayerROS)
//
// where InflationLayerROS derives from CostmapLayer and is default-constructible.
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "move_base/costmap_layer.h"

namespace move_base {

using LayerFactory = std::function<std::unique_ptr<CostmapLayer>()>;

// False (and nothing changes) if `type` is registered already.
bool registerLayer(const std::string& type, LayerFactory factory);
// A new layer of `type`, or nullptr when no layer has that type.
std::unique_ptr<CostmapLayer> makeLayer(const std::string& type);
std::vector<std::string> layerTypes();  // sorted

}  // namespace move_base

#define MOVE_BASE_LAYER_CONCAT_(a, b) a##b
#define MOVE_BASE_LAYER_VARIABLE_(line) MOVE_BASE_LAYER_CONCAT_(registered_layer_, line)
#define MOVE_BASE_REGISTER_LAYER(TYPE, CLASS)                                                         \
  namespace {                                                                                         \
  const bool MOVE_BASE_LAYER_VARIABLE_(__LINE__) = ::move_base::registerLayer(                        \
      TYPE, []() -> std::unique_ptr<::move_base::CostmapLayer> { return std::make_unique<CLASS>(); }); \
  }
