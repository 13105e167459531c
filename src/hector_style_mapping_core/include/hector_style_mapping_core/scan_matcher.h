#ifndef HECTOR_STYLE_MAPPING_CORE_SCAN_MATCHER_H
#define HECTOR_STYLE_MAPPING_CORE_SCAN_MATCHER_H

#include <Eigen/Core>

#include "hector_style_mapping_core/occupancy_grid_map.h"
#include "hector_style_mapping_core/pose_2d.h"
#include "hector_style_mapping_core/scan_points.h"

namespace hector_style_mapping {

// What one scan-to-map match found.
struct ScanMatchResult {
  Pose2D pose;                                        // the refined pose, theta in (-pi, pi]
  Eigen::Matrix3d hessian = Eigen::Matrix3d::Zero();  // H = sum J^T J at `pose`, in metres / radians
  double squared_residual_sum = 0.0;                  // sum (1 - M(S_i))^2 at `pose`
  int point_count = 0;                                // finite scan points that took part
  int iterations = 0;                                 // Gauss-Newton steps accepted
};

// Gauss-Newton scan-to-map matching (Kohlbrecher et al. 2011): finds the pose xi minimising
// sum_i (1 - M(S_i(xi)))^2, where S_i(xi) is scan point i moved into the map frame by xi and M the map's
// interpolated occupancy probability. Each iteration steps by H^-1 sum J_i^T (1 - M(S_i)) with
// J_i = grad M(S_i) * dS_i/dxi and H = sum J_i^T J_i, and differs from the paper's plain iteration in three ways:
//  - directions H does not constrain (one wall only, a featureless corridor, an empty map) get no step: H is
//    inverted only on its well-conditioned eigen-subspace, with the rotation scaled by the scan's RMS range so
//    metres and radians compare;
//  - a step turns by at most kMaxRotationStep and moves by at most kMaxTranslationStepCells cells of the map,
//    about how far the linearisation of a bilinear map holds;
//  - a step that does not lower the cost is halved (twice at most) and otherwise refused, which ends the match.
class ScanMatcher {
 public:
  static constexpr double kMaxRotationStep = 0.2;         // rad per iteration
  static constexpr double kMaxTranslationStepCells = 2.0;  // cells of the matched map per iteration
  // Directions whose (scaled) eigenvalue is below this fraction of the largest count as unconstrained.
  static constexpr double kRelativeEigenvalueFloor = 1e-4;
  // How far along a surface surfaceNormalHessian() fits its normals, where beams are dense enough.
  static constexpr double kNormalRadius = 0.2;  // m

  // Refines `guess` (map frame) against one level; returns the matched pose and fills the 3x3 Hessian
  // H = sum J^T J at the result (metres / radians) if asked. `iterations` is the maximum number of Gauss-Newton
  // steps; the match stops early when a step is negligible (1e-3 cell and 1e-4 rad) or would not lower the cost.
  // A scan without finite points returns `guess` and a zero Hessian.
  Pose2D match(const OccupancyGridMap& map, const ScanPoints& scan, const Pose2D& guess, int iterations,
               Eigen::Matrix3d* hessian = nullptr) const;

  // The same match, reporting also the residual and how it went.
  ScanMatchResult matchWithDetails(const OccupancyGridMap& map, const ScanPoints& scan, const Pose2D& guess,
                                   int iterations) const;

  // sum J^T J at `pose` like match()'s Hessian, except that each point's map gradient is reduced to its component
  // along the surface normal the scan shows around that point. What this removes is the gradient along a wall,
  // which comes from the map's texture (cells eroded by grazing rays, the pattern of earlier beams) rather than
  // from geometry, and which makes H claim a featureless corridor pins the robot along it. Normals come from a
  // line fit to the point's neighbours in the scan (consecutive in `points`, so points must be in beam order; at
  // least two per side, more up to kNormalRadius away); where no straight surface is found (corners, clutter,
  // isolated points) the full gradient is kept, so on unordered points this equals match()'s Hessian.
  Eigen::Matrix3d surfaceNormalHessian(const OccupancyGridMap& map, const ScanPoints& scan, const Pose2D& pose) const;
};

}  // namespace hector_style_mapping

#endif  // HECTOR_STYLE_MAPPING_CORE_SCAN_MATCHER_H
