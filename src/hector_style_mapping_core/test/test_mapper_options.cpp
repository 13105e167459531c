#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "hector_style_mapping_core/mapper_options.h"
#include "hector_style_mapping_core/multi_resolution_map.h"
#include "hector_style_mapping_core/slam_processor.h"
#include "hector_style_mapping_core/testing/mentions.h"

namespace hector_style_mapping {
namespace {

using testing::mentions;

TEST(MapperOptions, DefaultsAreHectorMappingsParameterDefaults) {
  const MapperOptions options;
  EXPECT_EQ(options.map_resolution, 0.025);
  EXPECT_EQ(options.map_size, 1024);
  EXPECT_EQ(options.map_start_x, 0.5);
  EXPECT_EQ(options.map_start_y, 0.5);
  EXPECT_EQ(options.map_multi_res_levels, 3);
  EXPECT_EQ(options.update_factor_free, 0.4);
  EXPECT_EQ(options.update_factor_occupied, 0.9);
  EXPECT_EQ(options.map_update_distance_thresh, 0.4);
  EXPECT_EQ(options.map_update_angle_thresh, 0.9);
  EXPECT_EQ(options.search_window_linear, 0.0);  // ours: off, as hector_mapping has no search
  EXPECT_EQ(options.search_window_angular, 0.0);
  EXPECT_EQ(options.search_motion_weight, 0.1);
  EXPECT_EQ(validate(options), "");
}

TEST(MapperOptions, AcceptsTheLecturesRobotSetting) {
  MapperOptions options;
  options.map_resolution = 0.05;
  options.map_size = 2048;
  options.map_multi_res_levels = 2;
  EXPECT_EQ(validate(options), "");
}

// Each case breaks one field; the message must name it and show the bad value.
struct BadOption {
  const char* field;
  void (*breakIt)(MapperOptions*);
  const char* shown_value;
};

TEST(MapperOptions, RejectsEachBadFieldByName) {
  const BadOption cases[] = {
      {"map_resolution", [](MapperOptions* o) { o->map_resolution = -1.0; }, "got -1"},
      {"map_resolution", [](MapperOptions* o) { o->map_resolution = 0.0; }, "got 0"},
      {"map_resolution", [](MapperOptions* o) { o->map_resolution = std::nan(""); }, "got nan"},
      {"map_resolution",
       [](MapperOptions* o) { o->map_resolution = std::numeric_limits<double>::infinity(); }, "got inf"},
      {"map_size", [](MapperOptions* o) { o->map_size = 0; }, "got 0"},
      {"map_size", [](MapperOptions* o) { o->map_size = kMaxMapSize * 2; }, "got 32768"},
      {"map_size", [](MapperOptions* o) { o->map_size = 1022; }, "got 1022"},  // not a multiple of 4
      {"map_start_x", [](MapperOptions* o) { o->map_start_x = 1.5; }, "got 1.5"},
      {"map_start_y", [](MapperOptions* o) { o->map_start_y = -0.1; }, "got -0.1"},
      {"map_multi_res_levels", [](MapperOptions* o) { o->map_multi_res_levels = 0; }, "got 0"},
      {"map_multi_res_levels", [](MapperOptions* o) { o->map_multi_res_levels = 20; }, "got 20"},
      {"update_factor_free", [](MapperOptions* o) { o->update_factor_free = 0.5; }, "got 0.5"},
      {"update_factor_free", [](MapperOptions* o) { o->update_factor_free = 0.0; }, "got 0"},
      {"update_factor_occupied", [](MapperOptions* o) { o->update_factor_occupied = 0.3; }, "got 0.3"},
      {"update_factor_occupied", [](MapperOptions* o) { o->update_factor_occupied = 1.0; }, "got 1"},
      {"map_update_distance_thresh", [](MapperOptions* o) { o->map_update_distance_thresh = -0.1; }, "got -0.1"},
      {"map_update_angle_thresh", [](MapperOptions* o) { o->map_update_angle_thresh = std::nan(""); }, "got nan"},
      {"search_window_linear", [](MapperOptions* o) { o->search_window_linear = -1.0; }, "got -1"},
      {"search_window_angular", [](MapperOptions* o) { o->search_window_angular = 4.0; }, "got 4"},
      {"search_motion_weight", [](MapperOptions* o) { o->search_motion_weight = -0.5; }, "got -0.5"},
  };
  for (const BadOption& bad : cases) {
    MapperOptions options;
    bad.breakIt(&options);
    const std::string message = validate(options);
    EXPECT_TRUE(mentions(message, bad.field)) << "field " << bad.field << ": " << message;
    EXPECT_TRUE(mentions(message, bad.shown_value)) << "field " << bad.field << ": " << message;
    EXPECT_TRUE(mentions(message, "must be")) << message;
  }
}

TEST(MapperOptions, ResolutionMessageReadsAsDocumented) {
  MapperOptions options;
  options.map_resolution = -1.0;
  EXPECT_EQ(validate(options), "map_resolution must be > 0 and finite (got -1)");
}

TEST(MapperOptions, ReportsEveryBadFieldAtOnce) {
  MapperOptions options;
  options.map_resolution = 0.0;
  options.update_factor_occupied = 0.2;
  const std::string message = validate(options);
  EXPECT_TRUE(mentions(message, "map_resolution"));
  EXPECT_TRUE(mentions(message, "update_factor_occupied"));
  EXPECT_TRUE(mentions(message, "; "));
}

TEST(MapperOptions, MapSizeMustDivideIntoEveryLevel) {
  MapperOptions options;
  options.map_size = 1000;  // 1000 / 4 = 250 cells at level 2: fine
  EXPECT_EQ(validate(options), "");
  options.map_size = 1001;
  EXPECT_TRUE(mentions(validate(options), "map_size"));
  options.map_size = 4;  // only one cell at level 2
  EXPECT_TRUE(mentions(validate(options), "map_size"));
  options.map_multi_res_levels = 1;
  options.map_size = 1001;  // a single level can have any size
  EXPECT_EQ(validate(options), "");
}

TEST(MapperOptions, ClassesRefuseBadOptionsWithTheMessage) {
  MapperOptions options;
  options.map_resolution = -1.0;
  try {
    const SlamProcessor processor(options);
    FAIL() << "SlamProcessor accepted a negative resolution";
  } catch (const std::invalid_argument& error) {
    EXPECT_TRUE(mentions(error.what(), "map_resolution must be > 0"));
  }
  EXPECT_THROW(MultiResolutionMap{options}, std::invalid_argument);
}

}  // namespace
}  // namespace hector_style_mapping
