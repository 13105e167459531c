#ifndef ODOMETRY_SLAM_ODOMETRY_SLAM_H
#define ODOMETRY_SLAM_ODOMETRY_SLAM_H

#include <string>

#include <Eigen/Core>

#include "hector_style_mapping_core/multi_resolution_map.h"
#include "hector_style_mapping_core/pose_2d.h"
#include "hector_style_mapping_core/scan_matcher.h"
#include "hector_style_mapping_core/scan_points.h"
#include "odometry_slam/hit_counts.h"

namespace odometry_slam {

using hector_style_mapping::Pose2D;
using hector_style_mapping::ScanPoints;

// What the core is tuned with; names after slam_gmapping's parameters, defaults its defaults.
struct OdometrySlamOptions {
  // The map: cells of `delta` m over [xmin, xmax] x [ymin, ymax] of the map frame (a square of the longer side).
  double delta = 0.05;
  double xmin = -100.0, ymin = -100.0, xmax = 100.0, ymax = 100.0;
  // A scan is processed once the odometry has travelled linear_update m or turned angular_update rad since the
  // last processed scan (summed scan by scan, as gmapping), or temporal_update s have passed (< 0: time alone
  // never does). The first scan always is.
  double linear_update = 1.0;
  double angular_update = 0.5;
  double temporal_update = -1.0;
  // The odometry's error (gmapping's srr, srt, str, stt): standard deviation of the translation per metre
  // travelled and per radian turned, of the rotation per metre and per radian. They bound how far a match may
  // move the odometry's prediction (OdometrySlam::kGateSigmas).
  double srr = 0.1, srt = 0.2, str = 0.1, stt = 0.2;
  // A cell is occupied when more than this share of the scans that saw it ended a beam in it.
  double occ_thresh = 0.25;
};

// "" when `options` can be used, else one complaint per bad field, "; "-joined, naming the field.
std::string validate(const OdometrySlamOptions& options);

// 2D SLAM for a robot with odometry: every processed scan starts from the odometry's motion since the last one
// and is refined by Gauss-Newton scan-to-map matching (hector_style_mapping's matcher, coarse to fine); a match
// that strays further from the odometry than its error model allows is refused and the odometry kept. Between
// processed scans the pose is the odometry moved by the last correction (map -> odom), as in gmapping.
class OdometrySlam {
 public:
  // A match may move the prediction by this many of the odometry's standard deviations, plus one cell and
  // kMinAngleGate, so a robot at rest (temporal updates) may still be corrected by a cell's rounding.
  static constexpr double kGateSigmas = 3.0;
  static constexpr double kMinAngleGate = 0.035;  // rad, 2 degrees

  enum class Outcome {
    kSkipped,        // not moved enough: pose() follows the odometry, map unchanged
    kFirst,          // the first scan: the map starts with it at the odometry's pose (map frame = odom frame)
    kMatched,        // matched and added to the map
    kMatchRefused,   // the match strayed too far; added at the odometry's prediction
    kNoPoints,       // processing was due, but the scan has no finite point: nothing changed
  };

  // Throws std::invalid_argument with validate()'s message.
  explicit OdometrySlam(const OdometrySlamOptions& options);

  // One scan (points in the base frame) with the odometry's pose of the base (odom frame) at its time, in s.
  Outcome addScan(const ScanPoints& scan, const Pose2D& odometry, double time);

  // The base's pose in the map frame at the last scan given, and map -> odom (the correction).
  const Pose2D& pose() const { return pose_; }
  const Pose2D& mapToOdom() const { return map_to_odom_; }
  // Of the last processed scan's pose (x, y in m, theta in rad): the match's (hector_style_mapping's
  // matchCovariance) or, for a refused match, the odometry's error model. Zero before the second processed scan.
  const Eigen::Matrix3d& covariance() const { return covariance_; }
  // Differential entropy of a Gaussian with covariance(), in nats (-inf while it is zero).
  double poseEntropy() const;

  int processedScans() const { return processed_; }
  int refusedMatches() const { return refused_; }

  const hector_style_mapping::MultiResolutionMap& map() const { return map_; }
  const HitCounts& hitCounts() const { return counts_; }
  double occThresh() const { return options_.occ_thresh; }

  // Empty map; the next scan is the first again.
  void reset();

 private:
  bool due(const Pose2D& odometry, double time);
  void insert(const ScanPoints& scan, const Pose2D& odometry, double time);

  OdometrySlamOptions options_;
  hector_style_mapping::MultiResolutionMap map_;
  hector_style_mapping::ScanMatcher matcher_;
  HitCounts counts_;
  Pose2D pose_, map_to_odom_;
  Eigen::Matrix3d covariance_ = Eigen::Matrix3d::Zero();
  int processed_ = 0, refused_ = 0;
  // The odometry at the last scan given and at the last processed one; the motion summed since that one.
  Pose2D last_odometry_, processed_odometry_;
  double processed_time_ = 0.0;
  double travelled_ = 0.0, turned_ = 0.0;
};

}  // namespace odometry_slam

#endif  // ODOMETRY_SLAM_ODOMETRY_SLAM_H
