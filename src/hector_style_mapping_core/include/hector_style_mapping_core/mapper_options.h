#ifndef HECTOR_STYLE_MAPPING_CORE_MAPPER_OPTIONS_H
#define HECTOR_STYLE_MAPPING_CORE_MAPPER_OPTIONS_H

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
  // Ours, not hector_mapping's: the correlative search (SlamProcessor::update, correlativeSearch). Above 0, each
  // scan is searched for within these half-widths round the last pose (or the guess), against the last few
  // scans; off (0) by default, as hector_mapping. For scans far apart without odometry (Radish's logs: 0.5-1 m
  // and up to 60 degrees between scans) 1.6 m and 1.4 rad; docs/MAPPING.md, "Real logs".
  double search_window_linear = 0.0;   // m
  double search_window_angular = 0.0;  // rad
  // How much the search prefers the translation constant velocity (or the guess) predicts: a candidate pays this
  // much mean field value (0..1: the share of points on a wall) per metre away from it. It only decides where
  // the scan cannot, along a featureless corridor. 0.1: a metre off must put a tenth more of the points on walls.
  // Without a guess, scaled by the shorter of the last two scan intervals over the longer (motionPriorWeight).
  double search_motion_weight = 0.1;   // per m
  // Ours: loop closure (LoopClosure): the scans that update the map become keyframes of a pose graph, closed
  // when a keyframe matches an older one's submap; the map is then redrawn from the optimised keyframes. Off
  // by default, as upstream has none.
  bool loop_closure = false;
};

// The largest map_size validate() accepts: beyond it the finest level alone would need gigabytes.
constexpr int kMaxMapSize = 16384;

// "" when `options` can be used; otherwise one message per bad field, joined by "; ", each naming the field, what
// was expected and what was given, e.g. "map_resolution must be > 0 (got -1)".
std::string validate(const MapperOptions& options);

}  // namespace hector_style_mapping

#endif  // HECTOR_STYLE_MAPPING_CORE_MAPPER_OPTIONS_H
