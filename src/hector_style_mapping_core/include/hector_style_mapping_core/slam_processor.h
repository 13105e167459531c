#ifndef HECTOR_STYLE_MAPPING_CORE_SLAM_PROCESSOR_H
#define HECTOR_STYLE_MAPPING_CORE_SLAM_PROCESSOR_H

#include <memory>
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "hector_style_mapping_core/correlative_search.h"
#include "hector_style_mapping_core/likelihood_field.h"
#include "hector_style_mapping_core/loop_closure_worker.h"
#include "hector_style_mapping_core/mapper_options.h"
#include "hector_style_mapping_core/multi_resolution_map.h"
#include "hector_style_mapping_core/pose_2d.h"
#include "hector_style_mapping_core/scan_matcher.h"
#include "hector_style_mapping_core/scan_points.h"

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

  // Throws std::invalid_argument with validate()'s message if the options are not valid. `threading`: where
  // loop closure works (LoopClosureWorker); inline, a closed loop is adopted as the keyframe that closed it is
  // mapped, in the background at the first scan after it was found; the map comes redrawn either way.
  explicit SlamProcessor(const MapperOptions& options,
                         LoopClosureThreading threading = LoopClosureThreading::kInline);

  // The fastest a robot the mapper serves plausibly moves and turns: with the scan interval, they size the
  // correlative search's window (up to the options' search_window_*). Brisk walking pace and half a turn a
  // second: more than the robots we know (a Pioneer 3-DX 1.2 m/s, a TurtleBot 0.7 m/s).
  static constexpr double kPlausibleSpeed = 1.5;      // m/s
  static constexpr double kPlausibleTurnRate = M_PI;  // rad/s
  // The scan interval is the median of this many recent ones, so that a log's odd stamps do not shrink it.
  static constexpr std::size_t kRecentIntervals = 15;
  // Scans the correlative search matches against: the last ones that updated the map, and the last scan if
  // it did not (turning on the spot, it overlaps the next scan most).
  static constexpr std::size_t kSearchedScans = 3;

  // Matches the scan from the coarsest level to the finest and updates every level of the map if this is the
  // first scan since construction / reset() or the matched pose moved more than map_update_distance_thresh or
  // turned more than map_update_angle_thresh since the last map update.
  //
  // The match starts at `guess` (odometry, say) if given, otherwise at the last pose, as hector_mapping. With
  // the search on (the options' search_window_linear and _angular > 0), a correlative search (correlativeSearch)
  // looks for the scan within a window round the start, against the field of the last kSearchedScans scans
  // that updated the map and the last scan, and Gauss-Newton on the finest level refines its pose (unless it
  // strays further than the search's resolution: then the map has drifted from the recent scans, and the
  // search's pose stands).
  // Without it, Gauss-Newton goes from the start through the levels, coarsest first.
  //
  // The window: the motion a robot could plausibly make (kPlausibleSpeed, kPlausibleTurnRate) over the scan
  // interval, capped by search_window_linear / _angular. The interval is the median of the recent
  // `seconds_since_last_scan` (> 0; 0 when not known), or this scan's own if longer: real logs' stamps are not
  // to be trusted scan by scan (Radish's Intel log has scans 0.0 s apart with 30 degrees of turn between them),
  // but after a gap (scans a busy node skipped, a pause) the robot had that long to move. With none known, the
  // whole configured window.
  //
  // A scan without finite points changes nothing (pose, covariance and map stay; mapUpdatedByLastScan() becomes
  // false), even when a guess is given. A guess with a non-finite field is ignored. Keep the scan's points in
  // beam order: the covariance's surface normals are fitted to neighbouring points.
  void update(const ScanPoints& scan, const Pose2D* guess = nullptr, double seconds_since_last_scan = 0.0);

  // Scans matched by the correlative search since construction / the last reset(); for diagnostics.
  int searchCount() const { return search_count_; }
  // With the options' loop_closure, every scan that updated the map is a keyframe: their poses as the front end
  // knows them (optimised up to the last closed loop it adopted, the later ones moved with them). Empty without.
  const std::vector<Pose2D>& keyframePoses() const { return keyframe_poses_; }
  // Closed loops adopted since construction / the last reset(): when it changes, keyframePoses() moved.
  int loopClosureAdoptions() const { return adoptions_; }
  // What loop closure has done (all zero without).
  LoopClosureStats loopClosureStats() const;
  // In the background: waits until every keyframe has been through loop closure and adopts what it found,
  // as at the end of a log. Inline: nothing to wait for.
  void finishLoopClosure();
  // Adopts a loop the background closed since the last scan, without waiting for the next one (a robot that
  // stopped, a log that ended); true if there was one. Inline: none is ever pending.
  bool adoptClosedLoop();

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

  // The map; after a loop closed, the loop closure worker's redraw from the optimised keyframes, the later ones
  // drawn on top.
  const MultiResolutionMap& map() const { return map_; }
  const MapperOptions& options() const { return options_; }
  // The finest level's match of the last scan (pose, Hessian, residual), for diagnostics.
  const ScanMatchResult& lastMatch() const { return last_match_; }

 private:
  bool movedEnoughForMapUpdate() const;
  // A closed loop: the keyframes it optimised take their new poses, and the pose, the later keyframes, the
  // search's scans and the map move with them.
  void adopt(LoopClosureUpdate update);
  // Hands the scan just mapped to loop closure as a keyframe (and adopts a closure found inline).
  void addKeyframe(const ScanPoints& scan);
  // The field the search matches against, with `levels` levels: the window's scans' (rebuilt as the window
  // changes) with the unmapped scan's on top.
  const LikelihoodField& searchField(int levels);
  // The search's window for this scan; records the interval.
  SearchWindow searchWindow(double seconds_since_last_scan);
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
  int search_count_ = 0;
  Pose2D previous_pose_;  // pose() before the last scan: with it, the search's prior
  std::vector<double> recent_intervals_;  // s, the last kRecentIntervals known ones
  double last_interval_ = 0.0;  // s between the last scan and the one before (<= 0: not known)
  // The last kSearchedScans scans that updated the map, the last scan if it did not, and the search's fields
  // built from them on demand (searchField()): the window's alone, and with the unmapped scan on top.
  std::vector<PlacedScan> window_;
  std::optional<PlacedScan> unmapped_scan_;
  LikelihoodField window_field_;
  bool window_field_stale_ = true;
  LikelihoodField field_;
  bool field_stale_ = true;
  LoopClosureThreading threading_;
  std::unique_ptr<LoopClosureWorker> loop_closure_;  // null without the options' loop_closure and search
  std::vector<Pose2D> keyframe_poses_;
  std::vector<ScanPoints> keyframe_scans_;  // the map is redrawn from these
  int adoptions_ = 0;
};

// Gauss-Newton from `start` through every level of `map`, coarsest first, with SlamProcessor's iteration caps;
// the finest level's match. For other front ends on the same matcher.
ScanMatchResult matchThroughLevels(const ScanMatcher& matcher, const MultiResolutionMap& map, const ScanPoints& scan,
                                   const Pose2D& start);

// SlamProcessor::covariance()'s formula for a match and the surface-normal Hessian at its pose; for other
// front ends on the same matcher.
Eigen::Matrix3d matchCovariance(const ScanMatchResult& match, const Eigen::Matrix3d& surface_normal_hessian);

// The search's motion prior weight for a scan (search_motion_weight, without a guess). Constant velocity per scan
// assumes a steady pace: where the interval before this scan and the one before the last differ (a log's pause,
// say 38 s in which the robot moved 0.17 m, between scans 2.5 s apart), the last step says little of this one,
// and the prior counts for the shorter interval over the longer. Either interval unknown (<= 0, not finite): all
// of `weight`.
double motionPriorWeight(double weight, double last_interval, double interval);

}  // namespace hector_style_mapping

#endif  // HECTOR_STYLE_MAPPING_CORE_SLAM_PROCESSOR_H
