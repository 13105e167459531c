#ifndef HECTOR_STYLE_MAPPING_CORE_LIKELIHOOD_FIELD_H
#define HECTOR_STYLE_MAPPING_CORE_LIKELIHOOD_FIELD_H

#include <algorithm>
#include <vector>

#include <Eigen/Core>

#include "hector_style_mapping_core/floor_to_int.h"
#include "hector_style_mapping_core/pose_2d.h"
#include "hector_style_mapping_core/scan_points.h"

namespace hector_style_mapping {

// A scan with the pose (map frame) of the robot's base when it was taken.
struct PlacedScan {
  Pose2D pose;
  ScanPoints scan;
};

// What the correlative search scores a scan against: a grid built from a few recent scans, each cell saying how
// well a new scan point falling there agrees with them (after Olson, "Real-time correlative scan matching",
// ICRA 2009).
//  - Near a hit of the recent scans: exp(-d^2 / (2 kSigma^2)), d the distance to the nearest hit. The blur lets
//    sparse scans match: one-degree beams ten metres out land 17 cm apart, so a new scan's points seldom fall on
//    an old scan's points, but they fall near the walls those points lie on.
//  - Where the recent scans' rays passed and no hit lies within 2 kSigma: kFreeValue. A wall cannot stand where
//    the laser just saw through. Without this a scan slid along a corridor, its far points out in the open,
//    scores as well as the true pose; with it, far points on the corridor's end must fall on that end.
//  - Elsewhere (never seen): 0.
// Points outside the grid read 0. For branch and bound it also holds, per level l, the largest value over each
// block of 2^l x 2^l cells (blockMax), an upper bound on any point's value within the block.
// The cells' centres lie on a lattice kResolution apart through the grid's lowest corner: each field's own, so
// that where the scans' walls fall between cell centres changes from field to field and the grid's pull on them
// averages out over a log instead of adding up (with one lattice for all, fixed in the map frame, the absolute
// error on Radish's logs doubled: docs/MAPPING.md). A field built on top of another keeps the other's lattice.
class LikelihoodField {
 public:
  static constexpr double kResolution = 0.05;  // m per cell
  // Blur of the hits: about the spread of a laser's range error and its beams' footprint at a few metres, and
  // coarse enough that the search can step rotations by kSigma at the farthest points.
  static constexpr double kSigma = 0.1;        // m
  static constexpr float kFreeValue = -1.0f;
  // Levels 0 .. kLevels - 1: blocks up to 32 cells (1.6 m) a side, so that a search window of metres starts
  // from few candidates.
  static constexpr int kLevels = 6;

  // The grid covering `scans` (their hits, rays and free rays, with a margin); empty without finite points.
  explicit LikelihoodField(const std::vector<PlacedScan>& scans) { build(scans); }
  LikelihoodField() = default;  // empty
  // Builds it again from `scans`, reusing the memory (a mapper rebuilds it with every map update), with its
  // cells' centres on the lattice through the grid's lowest corner, or through `lattice_point`; block maxima
  // for the first `levels` levels (see ensureLevels()).
  void build(const std::vector<PlacedScan>& scans, int levels = kLevels);
  void build(const std::vector<PlacedScan>& scans, const Eigen::Vector2d& lattice_point, int levels = kLevels);
  // The field of `base`'s scans and `scan` on base's lattice, the same cell for cell as build() of them all
  // through base.latticePoint(), at the cost of one scan's hits and rays (and the copy and the levels): a mapper
  // searches each scan against the same few recent scans and the last one. A base without finite points counts
  // as no scans. `base` must not be this field.
  void buildOnTop(const LikelihoodField& base, const PlacedScan& scan, int levels = kLevels);
  // Builds the block maxima of levels up to `levels` - 1 that are not built yet. A search reads only the levels
  // its window needs (a mapper's small windows on a dense log leave the coarsest out: a tenth of its time).
  void ensureLevels(int levels);
  // Levels whose block maxima are built: blockMax() is for those only.
  int levels() const { return levels_ready_; }
  // A cell centre of the lattice (map frame).
  const Eigen::Vector2d& latticePoint() const { return lattice_point_; }
  // The lattice point build(scans) takes: the lowest corner of the grid round them.
  static Eigen::Vector2d ownLatticePoint(const std::vector<PlacedScan>& scans);

  // Cell coordinates of a map-frame point: cell (i, j)'s centre at (i, j).
  Eigen::Vector2d toCell(const Eigen::Vector2d& point) const {
    return (point - lattice_point_) / kResolution - first_cell_;
  }
  // The value of cell (x, y); 0 outside the grid.
  float value(int x, int y) const {
    return x >= 0 && y >= 0 && x < size_x_ && y < size_y_ ? levels_[0][static_cast<std::size_t>(y * size_x_ + x)]
                                                         : 0.0f;
  }
  // The largest value over cells [x, x + 2^level) x [y, y + 2^level), cells outside counting as 0; level 0 is
  // value(). For level < levels(). A block reaching over the grid's low edge may get more than its largest value:
  // still a bound.
  float blockMax(int level, int x, int y) const {
    const int size = 1 << level;
    if (x + size <= 0 || y + size <= 0 || x >= size_x_ || y >= size_y_ || size_x_ == 0) return 0.0f;
    // A block reaching over the grid's low edge: the block at the edge covers the part inside, 0 the rest.
    const float inside = levels_[static_cast<std::size_t>(level)]
                                [static_cast<std::size_t>(std::max(y, 0) * size_x_ + std::max(x, 0))];
    return x < 0 || y < 0 ? std::max(inside, 0.0f) : inside;
  }
  // Bilinear interpolation between the cell centres round a map-frame point. Inline: the search's refinement
  // calls it for every point of every candidate (a quarter of the mapper's time on a dense log).
  double interpolate(const Eigen::Vector2d& point) const {
    const Eigen::Vector2d c = toCell(point);
    const int x = floorToInt(c.x()), y = floorToInt(c.y());
    const double ax = c.x() - x, ay = c.y() - y;
    if (x >= 0 && y >= 0 && x + 1 < size_x_ && y + 1 < size_y_) {
      // All four inside (nearly always): read them without value()'s checks, the same sum.
      const float* low = &levels_[0][static_cast<std::size_t>(y) * size_x_ + x];
      const float* high = low + size_x_;
      return (1.0 - ay) * ((1.0 - ax) * low[0] + ax * low[1]) + ay * ((1.0 - ax) * high[0] + ax * high[1]);
    }
    return (1.0 - ay) * ((1.0 - ax) * value(x, y) + ax * value(x + 1, y)) +
           ay * ((1.0 - ax) * value(x, y + 1) + ax * value(x + 1, y + 1));
  }

  int sizeX() const { return size_x_; }
  int sizeY() const { return size_y_; }

 private:
  // Sizes the grid to cells [first, last] of the lattice through `lattice_point`, all 0.
  void allocate(const Eigen::Vector2d& lattice_point, const Eigen::Vector2i& first, const Eigen::Vector2i& last);
  void addHits(const PlacedScan& placed);
  void addFreeSpace(const PlacedScan& placed);

  Eigen::Vector2d lattice_point_{0.0, 0.0};  // map frame
  Eigen::Vector2d first_cell_{0.0, 0.0};     // cell (0, 0) here, in lattice cells from lattice_point_
  int size_x_ = 0;
  int size_y_ = 0;
  // levels_[l][y * size_x_ + x] = blockMax(l, x, y); cells past the grid's end count as 0.
  std::vector<std::vector<float>> levels_;
  int levels_ready_ = kLevels;  // levels_[0 .. levels_ready_ - 1] are built
};

}  // namespace hector_style_mapping

#endif  // HECTOR_STYLE_MAPPING_CORE_LIKELIHOOD_FIELD_H
