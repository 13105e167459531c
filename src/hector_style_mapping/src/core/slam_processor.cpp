#include "hector_style_mapping/slam_processor.h"

#include <algorithm>
#include <cmath>

#include <Eigen/LU>

namespace hector_style_mapping {

namespace {

bool hasFinitePoint(const ScanPoints& scan) {
  return std::any_of(scan.points.begin(), scan.points.end(),
                     [](const Eigen::Vector2d& point) { return point.allFinite(); });
}

Eigen::Matrix3d covarianceFrom(const ScanMatchResult& match, const Eigen::Matrix3d& hessian) {
  const Eigen::Vector3d prior_information(1.0 / SlamProcessor::kUnconstrainedTranslationVariance,
                                          1.0 / SlamProcessor::kUnconstrainedTranslationVariance,
                                          1.0 / SlamProcessor::kUnconstrainedRotationVariance);
  const double residual_variance = match.squared_residual_sum / std::max(match.point_count - 3, 1);
  const Eigen::Matrix3d information = hessian + Eigen::Matrix3d(prior_information.asDiagonal());
  Eigen::Matrix3d covariance = residual_variance * information.inverse();
  // Exactly symmetric, whatever the rounding of the inverse.
  return 0.5 * (covariance + covariance.transpose());
}

}  // namespace

SlamProcessor::SlamProcessor(const MapperOptions& options) : options_(options), map_(options) {}

void SlamProcessor::reset(const Pose2D& start) {
  map_.clear();
  pose_ = {start.x, start.y, normalizeAngle(start.theta)};
  last_map_update_pose_ = pose_;
  covariance_.setZero();
  last_match_ = ScanMatchResult{};
  map_updated_by_last_scan_ = false;
  map_update_count_ = 0;
}

void SlamProcessor::update(const ScanPoints& scan, const Pose2D* guess) {
  if (!hasFinitePoint(scan)) {
    map_updated_by_last_scan_ = false;
    return;
  }

  const bool guess_usable =
      guess != nullptr && std::isfinite(guess->x) && std::isfinite(guess->y) && std::isfinite(guess->theta);
  Pose2D estimate = guess_usable ? *guess : pose_;
  for (int level = map_.levels() - 1; level >= 0; --level) {
    const int iterations = level == 0 ? kFinestLevelIterations : kCoarseLevelIterations;
    last_match_ = matcher_.matchWithDetails(map_.level(level), scan, estimate, iterations);
    estimate = last_match_.pose;
  }
  pose_ = estimate;
  covariance_ = covarianceFrom(last_match_, matcher_.surfaceNormalHessian(map_.finest(), scan, pose_));

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
