// Pre-Hydro costmap parameters into layers, as costmap_2d translates them.
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "navigation_core/legacy_costmap_params.h"

namespace navigation_core {
namespace {

bool moved(const LegacyCostmapTranslation& t, const std::string& from, const std::string& to, bool keep = false) {
  for (const ParamMove& m : t.moves)
    if (m.from == from && m.to == to && m.keep_original == keep) return true;
  return false;
}

TEST(LegacyCostmapParams, APreHydroGlobalCostmapBecomesThreeLayers) {
  // The names a pre-Hydro costmap_common_params.yaml + global_costmap_params.yaml pair has (the
  // navigation tutorial's, which the Pioneer report follows).
  const std::set<std::string> present = {
      "global_frame", "robot_base_frame", "update_frequency", "static_map", "obstacle_range", "raytrace_range",
      "footprint", "inflation_radius", "observation_sources", "laser_scan_sensor", "transform_tolerance"};
  const LegacyCostmapTranslation t = translateLegacyCostmapParams(present, true, "", "laser_scan_sensor");
  ASSERT_EQ(t.plugins.size(), 3u);
  EXPECT_EQ(t.plugins[0].name, "static_layer");
  EXPECT_EQ(t.plugins[0].type, "costmap_2d::StaticLayer");
  EXPECT_EQ(t.plugins[1].type, "costmap_2d::ObstacleLayer");
  EXPECT_EQ(t.plugins[2].type, "costmap_2d::InflationLayer");
  EXPECT_TRUE(moved(t, "obstacle_range", "obstacle_layer/obstacle_range"));
  EXPECT_TRUE(moved(t, "raytrace_range", "obstacle_layer/raytrace_range"));
  EXPECT_TRUE(moved(t, "laser_scan_sensor", "obstacle_layer/laser_scan_sensor"));
  EXPECT_TRUE(moved(t, "observation_sources", "obstacle_layer/observation_sources"));
  EXPECT_TRUE(moved(t, "inflation_radius", "inflation_layer/inflation_radius"));
  // The costmap's own parameters stay where they are.
  EXPECT_EQ(t.moves.size(), 5u);
}

TEST(LegacyCostmapParams, WithoutStaticMapThereIsNoStaticLayer) {
  const LegacyCostmapTranslation t = translateLegacyCostmapParams({"rolling_window", "obstacle_range"}, false, "", "");
  ASSERT_EQ(t.plugins.size(), 2u);
  EXPECT_EQ(t.plugins[0].name, "obstacle_layer");
  EXPECT_EQ(t.plugins[1].name, "inflation_layer");
  EXPECT_TRUE(moved(t, "obstacle_range", "obstacle_layer/obstacle_range"));
}

TEST(LegacyCostmapParams, TrackUnknownSpaceIsCopiedToTheStaticLayerAndMovedToTheObstacleLayer) {
  const LegacyCostmapTranslation t =
      translateLegacyCostmapParams({"track_unknown_space", "map_topic", "lethal_cost_threshold"}, true, "", "");
  EXPECT_TRUE(moved(t, "track_unknown_space", "static_layer/track_unknown_space", true));
  EXPECT_TRUE(moved(t, "track_unknown_space", "obstacle_layer/track_unknown_space", false));
  EXPECT_TRUE(moved(t, "map_topic", "static_layer/map_topic"));
  EXPECT_TRUE(moved(t, "lethal_cost_threshold", "static_layer/lethal_cost_threshold"));
}

TEST(LegacyCostmapParams, VoxelMapsGetAVoxelLayerWithItsParameters) {
  const LegacyCostmapTranslation t = translateLegacyCostmapParams({"z_voxels", "origin_z", "max_obstacle_height"},
                                                                  false, "voxel", "");
  EXPECT_EQ(t.plugins[0].type, "costmap_2d::VoxelLayer");
  EXPECT_TRUE(moved(t, "z_voxels", "obstacle_layer/z_voxels"));
  EXPECT_TRUE(moved(t, "origin_z", "obstacle_layer/origin_z"));
  EXPECT_TRUE(moved(t, "max_obstacle_height", "obstacle_layer/max_obstacle_height"));
}

TEST(LegacyCostmapParams, EverySourceNamedInObservationSourcesMoves) {
  const LegacyCostmapTranslation t =
      translateLegacyCostmapParams({"scan", "bump", "observation_sources"}, false, "", "  scan bump missing ");
  EXPECT_TRUE(moved(t, "scan", "obstacle_layer/scan"));
  EXPECT_TRUE(moved(t, "bump", "obstacle_layer/bump"));
  EXPECT_EQ(t.moves.size(), 3u);  // "missing" is not there to move
}

}  // namespace
}  // namespace navigation_core
