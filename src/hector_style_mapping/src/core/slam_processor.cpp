#include "hector_style_mapping/slam_processor.h"

#include <algorithm>
#include <cmath>

#include <Eigen/LU>

#include "hector_style_mapping/correlative_search.h"

namespace hector_style_mapping {

namespace {

bool hasFinitePoint(const ScanPoints& scan) {
  return std::any_of(scan.points.begin(), scan.points.end(),
                     [](const Eigen::Vector2d& point) { return point.allFinite(); });
}

}  // namespace

Eigen::Matrix3d matchCovariance(const ScanMatchResult& match, const Eigen::Matrix3d& hessian) {
  const Eigen::Vector3d prior_information(1.0 / SlamProcessor::kUnconstrainedTranslationVariance,
                                          1.0 / SlamProcessor::kUnconstrainedTranslationVariance,
                                          1.0 / SlamProcessor::kUnconstrainedRotationVariance);
  const double residual_variance = match.squared_residual_sum / std::max(match.point_count - 3, 1);
  const Eigen::Matrix3d information = hessian + Eigen::Matrix3d(prior_information.asDiagonal());
  Eigen::Matrix3d covariance = residual_variance * information.inverse();
  // Exactly symmetric, whatever the rounding of the inverse.
  return 0.5 * (covariance + covariance.transpose());
}

SlamProcessor::SlamProcessor(const MapperOptions& options) : options_(options), map_(options) {}

void SlamProcessor::reset(const Pose2D& start) {
  map_.clear();
  pose_ = {start.x, start.y, normalizeAngle(start.theta)};
  last_map_update_pose_ = pose_;
  covariance_.setZero();
  last_match_ = ScanMatchResult{};
  map_updated_by_last_scan_ = false;
  map_update_count_ = 0;
  last_motion_ = Pose2D{};
  last_motion_seconds_ = 0.0;
  search_win_count_ = 0;
}

ScanMatchResult matchThroughLevels(const ScanMatcher& matcher, const MultiResolutionMap& map, const ScanPoints& scan,
                                   const Pose2D& start) {
  ScanMatchResult match;
  match.pose = start;
  for (int level = map.levels() - 1; level >= 0; --level) {
    const int iterations =
        level == 0 ? SlamProcessor::kFinestLevelIterations : SlamProcessor::kCoarseLevelIterations;
    match = matcher.matchWithDetails(map.level(level), scan, match.pose, iterations);
  }
  return match;
}

ScanMatchResult SlamProcessor::matchThroughLevels(const ScanPoints& scan, const Pose2D& start) const {
  return hector_style_mapping::matchThroughLevels(matcher_, map_, scan, start);
}

void SlamProcessor::update(const ScanPoints& scan, const Pose2D* guess, double seconds_since_last_scan) {
  if (!hasFinitePoint(scan)) {
    map_updated_by_last_scan_ = false;
    return;
  }

  const bool guess_usable =
      guess != nullptr && std::isfinite(guess->x) && std::isfinite(guess->y) && std::isfinite(guess->theta);
  const bool search = options_.search_window_linear > 0.0 && options_.search_window_angular > 0.0;
  const double dt =
      search && std::isfinite(seconds_since_last_scan) ? std::max(seconds_since_last_scan, 0.0) : 0.0;
  Pose2D start = pose_;
  if (guess_usable) {
    start = *guess;
  } else if (dt > 0.0 && last_motion_seconds_ > 0.0) {
    // Constant velocity, capped at twice the last interval's motion (a scan or two dropped).
    const double f = std::min(dt / last_motion_seconds_, 2.0);
    start = compose(pose_, Pose2D{f * last_motion_.x, f * last_motion_.y, f * last_motion_.theta});
  }
  last_match_ = matchThroughLevels(scan, start);

  const SearchWindow window{std::min(kPlausibleSpeed * dt, options_.search_window_linear),
                            std::min(kPlausibleTurnRate * dt, options_.search_window_angular)};
  if (map_update_count_ > 0 && window.linear > 0.0 && window.angular > 0.0) {
    const SearchResult found = correlativeSearch(map_.level(map_.levels() - 1), scan, start, window);
    const bool moved = found.pose.x != start.x || found.pose.y != start.y || found.pose.theta != start.theta;
    if (moved) {  // else its refinement is the match just made
      const ScanMatchResult refined = matchThroughLevels(scan, found.pose);
      // Per point, and ties to the prediction's match.
      const double residual = last_match_.squared_residual_sum / std::max(last_match_.point_count, 1);
      const double refined_residual = refined.squared_residual_sum / std::max(refined.point_count, 1);
      if (refined.point_count > 0 && refined_residual < 0.99 * residual) {
        last_match_ = refined;
        ++search_win_count_;
      }
    }
  }

  const Pose2D previous = pose_;
  pose_ = last_match_.pose;
  if (dt > 0.0) {
    last_motion_ = between(previous, pose_);
    last_motion_seconds_ = dt;
  }
  covariance_ = matchCovariance(last_match_, matcher_.surfaceNormalHessian(map_.finest(), scan, pose_));

  map_updated_by_last_scan_ = map_update_count_ == 0 || movedEnoughForMapUpdate();
  if (map_updated_by_last_scan_) {
    map_.updateByScan(scan, pose_);
    last_map_update_pose_ = pose_;
    ++map_update_count_;
  }
}

bool SlamProcessor::movedEnoughForMapUpdate() const {
  const double distance = std::hypot(pose_.x - last_map_update_pose_.x, pose_.y - last_map_update_pose_.y);
  const double rotation = std::abs(angleDifference(pose_.theta, last_map_update_pose_.theta));
  return distance > options_.map_update_distance_thresh || rotation > options_.map_update_angle_thresh;
}

}  // namespace hector_style_mapping
