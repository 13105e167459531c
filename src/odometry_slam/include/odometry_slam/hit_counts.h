#ifndef ODOMETRY_SLAM_HIT_COUNTS_H
#define ODOMETRY_SLAM_HIT_COUNTS_H

#include <cstdint>
#include <vector>

#include "hector_style_mapping_core/occupancy_grid_map.h"

namespace odometry_slam {

// A box of cells, [x0, x1) x [y0, y1); empty when x0 >= x1 or y0 >= y1.
struct CellBox {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  bool empty() const { return x0 >= x1 || y0 >= y1; }
  int width() const { return empty() ? 0 : x1 - x0; }
  int height() const { return empty() ? 0 : y1 - y0; }
};

// gmapping's map model beside the matcher's log-odds grid: per cell, how many scans saw it and how many of those
// ended a beam in it; a cell is occupied when hits / visits > occ_thresh. Counts follow the cells one
// OccupancyGridMap update changed, so both grids always agree on which cells are known.
class HitCounts {
 public:
  HitCounts(int size_x, int size_y);

  // Counts the cells `map`'s last updateByScan() changed; `map` must have this grid's size.
  void addLastUpdate(const hector_style_mapping::OccupancyGridMap& map);

  // -1 never seen, 100 when hits / visits > occ_thresh, else 0 (nav_msgs/OccupancyGrid's values).
  int8_t state(int x, int y, double occ_thresh) const;
  // The states of `box` (inside the grid), row-major from its lower-left cell.
  void states(const CellBox& box, double occ_thresh, std::vector<int8_t>* out) const;

  // The smallest box holding every cell seen so far (empty before the first update).
  const CellBox& seenBox() const { return seen_; }
  int sizeX() const { return size_x_; }
  int sizeY() const { return size_y_; }

  void clear();

 private:
  int size_x_, size_y_;
  std::vector<std::uint16_t> hits_, visits_;
  CellBox seen_;
};

}  // namespace odometry_slam

#endif  // ODOMETRY_SLAM_HIT_COUNTS_H
