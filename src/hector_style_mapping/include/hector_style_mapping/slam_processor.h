#ifndef HECTOR_STYLE_MAPPING_SLAM_PROCESSOR_H
#define HECTOR_STYLE_MAPPING_SLAM_PROCESSOR_H

#include <Eigen/Core>

#include "hector_style_mapping/mapper_options.h"
#include "hector_style_mapping/multi_resolution_map.h"
#include "hector_style_mapping/pose_2d.h"
#include "hector_style_mapping/scan_matcher.h"
#include "hector_style_mapping/scan_points.h"

namespace hector_style_mapping {

// The SLAM loop a node drives once per scan: match the scan against the multi-resolution map, then add it to the
// map when the robot has moved far enough.
class SlamProcessor {
 public:
  // Gauss-Newton steps allowed per scan on each coarser level and on the finest one. Matches stop early once a step
  // is negligible, so on average about 5 and 4 are taken; the caps only matter when the robot moved a lot since
  // the last scan. They were chosen with the maze tests: 5 / 10 lose track without odometry at 0.12 m and 0.18 rad
  // per scan, 10 / 20 do not (SlamProcessor.TracksFastMotionWithoutOdometry).
  static constexpr int kCoarseLevelIterations = 10;
  static constexpr int kFinestLevelIterations = 20;

  // Variances the covariance can at most reach along a direction the scans do not constrain (a featureless
  // corridor, an empty map): (10 m)^2 and (pi rad)^2. They act as a weak prior, see covariance().
  static constexpr double kUnconstrainedTranslationVariance = 100.0;
  static constexpr double kUnconstrainedRotationVariance = M_PI * M_PI;

  // Throws std::invalid_argument with validate()'s message if the options are not valid.
  explicit SlamProcessor(const MapperOptions& options);

  // The fastest a robot the mapper serves plausibly moves and turns: with the time since the last
  // scan, they size the correlative search's window (up to the options' search_window_*). Brisk
  // walking pace and half a turn a second: more than the robots we know (a Pioneer 3-DX 1.2 m/s,
  // a TurtleBot 0.7 m/s).
  static constexpr double kPlausibleSpeed = 1.5;       // m/s
  static constexpr double kPlausibleTurnRate = M_PI;   // rad/s

  // Matches the scan from the coarsest level to the finest and updates every level of the map if this is the
  // first scan since construction / reset() or the matched pose moved more than map_update_distance_thresh or
  // turned more than map_update_angle_thresh since the last map update.
  //
  // The match starts at `guess` (odometry, say) if given; otherwise, with the search on (the options'
  // search_window_linear and _angular > 0) and `seconds_since_last_scan` > 0, at the pose the last motion
  // predicts (the last scan-to-scan motion scaled to this interval: constant velocity), and otherwise at the last
  // pose, as hector_mapping. With the search on and the interval known, a correlative
  // search (correlativeSearch) on the coarsest level also looks for the scan round that start, over the motion
  // the robot could plausibly have made in that time beyond the prediction (kPlausibleSpeed, kPlausibleTurnRate,
  // capped by search_window_linear / _angular); the search's pose, refined, replaces the start's match when it
  // fits the finest level better. On synthetic scans half a metre apart this keeps the pose; on Radish's real
  // logs it does not yet (docs/MAPPING.md).
  //
  // A scan without finite points changes nothing (pose, covariance and map stay; mapUpdatedByLastScan() becomes
  // false), even when a guess is given. A guess with a non-finite field is ignored. Keep the scan's points in
  // beam order: the covariance's surface normals are fitted to neighbouring points.
  void update(const ScanPoints& scan, const Pose2D* guess = nullptr, double seconds_since_last_scan = 0.0);

  // Updates whose pose came from the correlative search (it fitted better than the match from the predicted
  // pose), since construction / the last reset(); for diagnostics.
  int searchWinCount() const { return search_win_count_; }

  // The base frame's pose in the map frame after the last scan (the start pose before any).
  const Pose2D& pose() const { return pose_; }

  // Covariance of pose() (x, y in m, theta in rad, map frame), from the finest level's Hessian at the matched pose:
  //   covariance = s^2 * (H_n + P)^-1
  // - H_n = ScanMatcher::surfaceNormalHessian(): sum J^T J with each map gradient reduced to the scan's surface
  //   normal, so a featureless corridor comes out long along its axis (the plain H, lastMatch().hessian, picks up
  //   map texture along walls and claims the position along a corridor is known to millimetres);
  // - s^2 = sum (1 - M)^2 / (n - 3), the residual variance of the n scan points: a poor fit is less certain;
  // - P = diag(1 / kUnconstrainedTranslationVariance (x, y), 1 / kUnconstrainedRotationVariance), a weak prior that
  //   keeps the matrix finite and positive definite along directions the scan cannot see (empty map, corridor) and
  //   is negligible elsewhere (H is typically 1e4 .. 1e6 per m^2).
  // The residuals are treated as independent, which they are not quite, so in well-structured places the figure
  // is optimistic (sub-millimetre): inflate it before fusing with odometry. Zero before the first scan.
  const Eigen::Matrix3d& covariance() const { return covariance_; }

  bool mapUpdatedByLastScan() const { return map_updated_by_last_scan_; }
  // Map updates since construction / the last reset().
  int mapUpdateCount() const { return map_update_count_; }

  // Empty map, pose = start (theta normalised), covariance zero; the next scan updates the map.
  void reset(const Pose2D& start = Pose2D{});

  const MultiResolutionMap& map() const { return map_; }
  const MapperOptions& options() const { return options_; }
  // The finest level's match of the last scan (pose, Hessian, residual), for diagnostics.
  const ScanMatchResult& lastMatch() const { return last_match_; }

 private:
  bool movedEnoughForMapUpdate() const;
  // Gauss-Newton from `start` through every level, coarsest first; the finest level's match.
  ScanMatchResult matchThroughLevels(const ScanPoints& scan, const Pose2D& start) const;

  MapperOptions options_;
  MultiResolutionMap map_;
  ScanMatcher matcher_;
  Pose2D pose_;
  Pose2D last_map_update_pose_;
  Eigen::Matrix3d covariance_ = Eigen::Matrix3d::Zero();
  ScanMatchResult last_match_;
  bool map_updated_by_last_scan_ = false;
  int map_update_count_ = 0;
  // The motion between the last two matched scans and the time it took (0: none yet).
  Pose2D last_motion_;
  double last_motion_seconds_ = 0.0;
  int search_win_count_ = 0;
};

// Gauss-Newton from `start` through every level of `map`, coarsest first, with SlamProcessor's iteration caps;
// the finest level's match. For other front ends on the same matcher.
ScanMatchResult matchThroughLevels(const ScanMatcher& matcher, const MultiResolutionMap& map, const ScanPoints& scan,
                                   const Pose2D& start);

// SlamProcessor::covariance()'s formula for a match and the surface-normal Hessian at its pose; for other
// front ends on the same matcher.
Eigen::Matrix3d matchCovariance(const ScanMatchResult& match, const Eigen::Matrix3d& surface_normal_hessian);

}  // namespace hector_style_mapping

#endif  // HECTOR_STYLE_MAPPING_SLAM_PROCESSOR_H
