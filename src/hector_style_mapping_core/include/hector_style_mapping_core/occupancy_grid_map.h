#ifndef HECTOR_STYLE_MAPPING_CORE_OCCUPANCY_GRID_MAP_H
#define HECTOR_STYLE_MAPPING_CORE_OCCUPANCY_GRID_MAP_H

#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "hector_style_mapping_core/pose_2d.h"
#include "hector_style_mapping_core/scan_points.h"

namespace hector_style_mapping {

// One resolution level of the map: a grid of log-odds occupancy cells.
//
// Geometry: cell (x, y) covers [origin + (x, y) * resolution, origin + (x + 1, y + 1) * resolution) in the map
// frame, and its value is taken to sit at the cell's centre, origin + (x + 0.5, y + 0.5) * resolution. Both the ray
// update (an end point marks the cell that contains it) and the interpolation use that same convention.
class OccupancyGridMap {
 public:
  // Log-odds never leave [-kLogOddsLimit, kLogOddsLimit] (probabilities about 0.03 .. 0.97). Without a bound a cell
  // seen free a thousand times would need hundreds of hits before it turned occupied (a door closing, a parked
  // car); with it, two hits turn the most certain free cell occupied and nine misses clear the most certain wall
  // (with the default update factors), while the matcher still sees nearly 0 and 1.
  static constexpr float kLogOddsLimit = 3.5f;

  // Throws std::invalid_argument unless both sizes are > 0, resolution > 0 and the update factors lie in (0, 1).
  OccupancyGridMap(int size_x, int size_y, double resolution,
                   const Eigen::Vector2d& origin /* map-frame position of cell (0,0)'s lower-left corner */,
                   double update_factor_free, double update_factor_occupied);

  int sizeX() const { return size_x_; }
  int sizeY() const { return size_y_; }
  double resolution() const { return resolution_; }
  const Eigen::Vector2d& origin() const { return origin_; }

  // Ray update of one scan taken with the robot's base at `pose` (map frame): a Bresenham line from the cell of the
  // laser origin to the cell of every end point; the cells on the way (the laser's own cell included) get one
  // "free" update, the end cell one "occupied" update. No cell is updated twice by one scan: an occupied mark wins
  // over a free one. Rays are clipped to the map: the part inside is traced, an end point outside marks nothing
  // occupied. A ray whose end lies in the laser's own cell marks that cell occupied. Non-finite points are skipped.
  // The scan's free_rays are traced the same way, their end cells marked free.
  void updateByScan(const ScanPoints& scan, const Pose2D& pose);

  // The cells the last updateByScan() changed (row-major indices), and whether it marked a cell occupied (else
  // free): for counts kept beside the map (slam_gmapping's hits per visit). Empty after clear().
  const std::vector<int>& lastUpdatedCells() const { return marked_cells_; }
  bool lastUpdateMarkedOccupied(int index) const { return stamp_[index] == occupied_stamp_ - 2u; }

  // Bilinear interpolation of the occupancy probability at map-frame point `p` between the four surrounding cell
  // centres, and (if asked) its gradient in 1/m (d/dx, d/dy in the map frame). Unknown cells, and the cells one
  // would need beyond the map's edge, count as 0, so the function is continuous everywhere; points more than half
  // a cell outside the map give 0 and a zero gradient. On the lines through cell centres the gradient jumps; there
  // it is the one-sided derivative towards larger coordinates.
  double interpolate(const Eigen::Vector2d& p, Eigen::Vector2d* gradient = nullptr) const;

  // Per-cell state for publishing, row-major (index = y * sizeX + x), as nav_msgs/OccupancyGrid's data:
  // -1 unknown (never updated, or log-odds exactly 0), 0 free (log-odds < 0), 100 occupied (log-odds > 0).
  void toOccupancyData(std::vector<int8_t>* data) const;

  // Cell queries; a cell outside the map reads as unknown (probability 0.5, neither free nor occupied).
  double probability(int x, int y) const;  // 0..1, 0.5 for unknown
  double logOdds(int x, int y) const;      // 0 for unknown
  bool isOccupied(int x, int y) const;     // log-odds > 0
  bool isFree(int x, int y) const;         // log-odds < 0
  bool isUnknown(int x, int y) const;      // never updated since construction or clear()
  bool isInside(int x, int y) const { return x >= 0 && y >= 0 && x < size_x_ && y < size_y_; }

  // The cell containing map-frame point `p` (it may lie outside the map; (-1, -1) for a non-finite point), and the
  // map-frame centre of cell (x, y).
  Eigen::Vector2i cellOf(const Eigen::Vector2d& p) const;
  Eigen::Vector2d cellCenter(int x, int y) const;

  // The log-odds one free / occupied update adds: log(p / (1 - p)) of the update factors.
  double logOddsFreeUpdate() const { return log_odds_free_; }
  double logOddsOccupiedUpdate() const { return log_odds_occupied_; }

  // What the matchers read, row-major (index = y * sizeX + x): the occupancy probability, 0 for
  // unknown cells.
  const std::vector<float>& matchValues() const { return match_value_; }

  // Every cell back to unknown.
  void clear();

 private:
  // Marks the cells of one ray for this scan's update (see updateByScan). Cells are continuous cell coordinates.
  void markRay(const Eigen::Vector2d& start, const Eigen::Vector2d& end, bool end_is_hit);
  // Marks the Bresenham line from cell (x0, y0) to cell (x1, y1), both inside the map, as free; the last cell is
  // marked occupied instead if `end_is_hit`.
  void markLine(int x0, int y0, int x1, int y1, bool end_is_hit);
  void markFree(int index);
  void markOccupied(int index);
  float cellValueOrZero(int x, int y) const;

  int size_x_;
  int size_y_;
  double resolution_;
  double inverse_resolution_;
  Eigen::Vector2d origin_;
  float log_odds_free_;
  float log_odds_occupied_;

  std::vector<float> log_odds_;
  // What the matcher interpolates: the occupancy probability, 0 for unknown cells. Kept up to date by every
  // update so matching never evaluates exp(); the map changes far less often than it is read.
  std::vector<float> match_value_;
  // The last scan that touched each cell: 0 = never (unknown); scan k marks free with 2k+1 and occupied with 2k+2,
  // so a cell already marked by the current scan is recognised without clearing anything between scans.
  std::vector<std::uint32_t> stamp_;
  std::uint32_t free_stamp_ = 1;
  std::uint32_t occupied_stamp_ = 2;
  // Cells marked by the scan being applied (or the last one applied); kept between scans so updates do not
  // allocate once it has grown.
  std::vector<int> marked_cells_;
};

}  // namespace hector_style_mapping

#endif  // HECTOR_STYLE_MAPPING_CORE_OCCUPANCY_GRID_MAP_H
