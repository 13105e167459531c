#ifndef HECTOR_STYLE_MAPPING_CORRELATIVE_SEARCH_H
#define HECTOR_STYLE_MAPPING_CORRELATIVE_SEARCH_H

#include "hector_style_mapping/occupancy_grid_map.h"
#include "hector_style_mapping/pose_2d.h"
#include "hector_style_mapping/scan_points.h"

namespace hector_style_mapping {

// Half-widths of the region searched round a predicted pose.
struct SearchWindow {
  double linear = 0.0;   // m, along x and along y
  double angular = 0.0;  // rad
};

struct SearchResult {
  Pose2D pose;          // the best pose found (the centre when nothing scores)
  double score = 0.0;   // its mean map value per scan point, 0..1
  long candidates = 0;  // poses scored
};

// Exhaustive correlative search (Olson, "Real-time correlative scan matching", ICRA 2009, in its
// brute-force form): every pose of a grid round `centre`, translations one cell of `map` apart and
// rotations such that the farthest scan point moves about one cell, is scored by the mean matching
// value (occupancy probability, 0 where unknown) of the cells the scan's points fall in. Gauss-Newton
// then refines the winner: the search only has to land in its basin, which a local match from a
// poor prediction (a robot that moved half a metre and turned twenty degrees since the last scan)
// misses. Ties go to the candidate nearest the centre. Cost: candidates x points cell reads.
SearchResult correlativeSearch(const OccupancyGridMap& map, const ScanPoints& scan, const Pose2D& centre,
                               const SearchWindow& window);

}  // namespace hector_style_mapping

#endif  // HECTOR_STYLE_MAPPING_CORRELATIVE_SEARCH_H
