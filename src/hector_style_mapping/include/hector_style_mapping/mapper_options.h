#ifndef HECTOR_STYLE_MAPPING_MAPPER_OPTIONS_H
#define HECTOR_STYLE_MAPPING_MAPPER_OPTIONS_H

#include <string>

namespace hector_style_mapping {

// Everything the SLAM core can be tuned with. The defaults are hector_mapping's ROS parameter defaults and the
// field names are its parameter names, so a node can load them one to one.
struct MapperOptions {
  double map_resolution = 0.025;            // m per cell at the finest level
  int map_size = 1024;                      // cells per side at the finest level
  double map_start_x = 0.5;                 // where the map frame origin lies, as a fraction of the map's width
  double map_start_y = 0.5;                 //   ... and of its height
  int map_multi_res_levels = 3;             // each level halves the resolution of the one below
  double update_factor_free = 0.4;          // probability an observed-free cell update stands for
  double update_factor_occupied = 0.9;      // probability a hit stands for
  double map_update_distance_thresh = 0.4;  // m the pose must move before the map is updated again
  double map_update_angle_thresh = 0.9;     // rad the pose must turn before the map is updated again
  // Ours, not hector_mapping's: the constant-velocity prediction and the correlative search round it
  // (see SlamProcessor::update). The search's half-widths grow with the time since the last scan
  // and stop at these. Off (0) by default: on Radish's real logs it does not yet hold the pose
  // (docs/MAPPING.md); e.g. 1.0 m and 0.6 rad for scans far apart.
  double search_window_linear = 0.0;   // m
  double search_window_angular = 0.0;  // rad
};

// The largest map_size validate() accepts: beyond it the finest level alone would need gigabytes.
constexpr int kMaxMapSize = 16384;

// "" when `options` can be used; otherwise one message per bad field, joined by "; ", each naming the field, what
// was expected and what was given, e.g. "map_resolution must be > 0 (got -1)".
std::string validate(const MapperOptions& options);

}  // namespace hector_style_mapping

#endif  // HECTOR_STYLE_MAPPING_MAPPER_OPTIONS_H
