#include "hector_style_mapping_core/slam_processor.h"

#include <algorithm>
#include <cmath>

#include <Eigen/LU>

#include "hector_style_mapping_core/correlative_search.h"

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

SlamProcessor::SlamProcessor(const MapperOptions& options, LoopClosureThreading threading)
    : options_(options), map_(options), threading_(threading) {
  reset();
}

void SlamProcessor::reset(const Pose2D& start) {
  map_.clear();
  pose_ = {start.x, start.y, normalizeAngle(start.theta)};
  previous_pose_ = pose_;
  last_map_update_pose_ = pose_;
  covariance_.setZero();
  last_match_ = ScanMatchResult{};
  map_updated_by_last_scan_ = false;
  map_update_count_ = 0;
  search_count_ = 0;
  window_.clear();
  unmapped_scan_.reset();
  window_field_stale_ = true;
  field_stale_ = true;
  recent_intervals_.clear();
  last_interval_ = 0.0;
  keyframe_poses_.clear();
  keyframe_scans_.clear();
  adoptions_ = 0;
  const bool search = options_.search_window_linear > 0.0 && options_.search_window_angular > 0.0;
  loop_closure_.reset();  // its work in hand is dropped, before a new one starts
  if (search && options_.loop_closure) loop_closure_ = std::make_unique<LoopClosureWorker>(options_, threading_);
}

double motionPriorWeight(double weight, double last_interval, double interval) {
  const bool known = last_interval > 0.0 && interval > 0.0 && std::isfinite(last_interval) && std::isfinite(interval);
  return known ? weight * std::min(last_interval, interval) / std::max(last_interval, interval) : weight;
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

  adoptClosedLoop();

  const bool guess_usable =
      guess != nullptr && std::isfinite(guess->x) && std::isfinite(guess->y) && std::isfinite(guess->theta);
  const bool search = options_.search_window_linear > 0.0 && options_.search_window_angular > 0.0;
  const Pose2D start = guess_usable ? *guess : pose_;
  if (search && !window_.empty()) {
    // The search decides where the scan fits the recent scans best.
    // The guess, or else constant velocity per scan, for the translation: along a featureless corridor it
    // decides.
    const Eigen::Vector2d expected = guess_usable ? Eigen::Vector2d(guess->x, guess->y)
                                                  : Eigen::Vector2d(2.0 * pose_.x - previous_pose_.x,
                                                                    2.0 * pose_.y - previous_pose_.y);
    const TranslationPrior prior{expected, guess_usable ? options_.search_motion_weight
                                                        : motionPriorWeight(options_.search_motion_weight,
                                                                            last_interval_, seconds_since_last_scan)};
    const SearchWindow window = searchWindow(seconds_since_last_scan);
    const SearchResult found = correlativeSearch(searchField(searchLevels(window)), scan, start, window, prior);
    // Gauss-Newton on the finest level then settles it on the whole map, unless it wanders off further than
    // the search's own resolution: then the map disagrees with the recent scans (drift), and they know better.
    last_match_ = matcher_.matchWithDetails(map_.finest(), scan, found.pose, kFinestLevelIterations);
    if (std::hypot(last_match_.pose.x - found.pose.x, last_match_.pose.y - found.pose.y) >
            LikelihoodField::kResolution ||
        std::abs(angleDifference(last_match_.pose.theta, found.pose.theta)) > found.angle_step) {
      last_match_ = matcher_.matchWithDetails(map_.finest(), scan, found.pose, 0);
    }
    ++search_count_;
  } else {
    last_match_ = matchThroughLevels(scan, start);
  }

  previous_pose_ = pose_;
  pose_ = last_match_.pose;
  last_interval_ = seconds_since_last_scan;
  covariance_ = matchCovariance(last_match_, matcher_.surfaceNormalHessian(map_.finest(), scan, pose_));

  map_updated_by_last_scan_ = map_update_count_ == 0 || movedEnoughForMapUpdate();
  if (search) {
    // Turning on the spot, map updates lie a turn apart: the scan just matched overlaps the next one most.
    if (map_updated_by_last_scan_) {
      unmapped_scan_.reset();
    } else {
      unmapped_scan_ = PlacedScan{pose_, scan};
    }
    field_stale_ = true;
  }
  if (map_updated_by_last_scan_) {
    map_.updateByScan(scan, pose_);
    last_map_update_pose_ = pose_;
    if (search) {
      window_.push_back({pose_, scan});
      if (window_.size() > kSearchedScans) window_.erase(window_.begin());
      window_field_stale_ = true;
    }
    ++map_update_count_;
    if (loop_closure_) addKeyframe(scan);
  }
}

void SlamProcessor::addKeyframe(const ScanPoints& scan) {
  const Pose2D step = keyframe_poses_.empty() ? pose_ : between(keyframe_poses_.back(), pose_);
  keyframe_poses_.push_back(pose_);
  keyframe_scans_.push_back(scan);
  loop_closure_->submit(scan, step);
  if (threading_ == LoopClosureThreading::kInline) {
    if (std::optional<LoopClosureUpdate> closed = loop_closure_->take()) adopt(std::move(*closed));
  }
}

void SlamProcessor::adopt(LoopClosureUpdate update) {
  const std::size_t optimised = update.poses.size();
  if (optimised == 0 || optimised > keyframe_poses_.size()) return;  // not ours (cannot happen)
  // Everything after the last optimised keyframe keeps its place relative to it.
  const Pose2D old_anchor = keyframe_poses_[optimised - 1];
  const Pose2D& new_anchor = update.poses.back();
  const auto moved = [&](const Pose2D& pose) { return compose(new_anchor, between(old_anchor, pose)); };
  pose_ = moved(pose_);
  previous_pose_ = moved(previous_pose_);  // so that the motion prior keeps the robot's velocity
  last_map_update_pose_ = moved(last_map_update_pose_);
  for (std::size_t i = 0; i < keyframe_poses_.size(); ++i)
    keyframe_poses_[i] = i < optimised ? update.poses[i] : moved(keyframe_poses_[i]);
  // Redrawn by the worker up to the last optimised keyframe: the later ones on top, in order.
  map_ = std::move(*update.map);
  for (std::size_t i = optimised; i < keyframe_poses_.size(); ++i)
    map_.updateByScan(keyframe_scans_[i], keyframe_poses_[i]);
  window_.clear();
  unmapped_scan_.reset();
  const std::size_t keyframes = keyframe_poses_.size();
  for (std::size_t i = keyframes > kSearchedScans ? keyframes - kSearchedScans : 0; i < keyframes; ++i)
    window_.push_back({keyframe_poses_[i], keyframe_scans_[i]});
  window_field_stale_ = true;
  field_stale_ = true;
  ++adoptions_;
}

LoopClosureStats SlamProcessor::loopClosureStats() const {
  return loop_closure_ ? loop_closure_->stats() : LoopClosureStats{};
}

bool SlamProcessor::adoptClosedLoop() {
  if (!loop_closure_) return false;
  std::optional<LoopClosureUpdate> closed = loop_closure_->take();
  if (!closed) return false;
  adopt(std::move(*closed));
  return true;
}

void SlamProcessor::finishLoopClosure() {
  if (!loop_closure_) return;
  loop_closure_->waitUntilIdle();
  adoptClosedLoop();
}

const LikelihoodField& SlamProcessor::searchField(int levels) {
  if (window_field_stale_) {
    window_field_.build(window_, levels);
    window_field_stale_ = false;
    field_stale_ = true;
  }
  window_field_.ensureLevels(levels);
  if (!unmapped_scan_) return window_field_;
  if (field_stale_) {
    // The unmapped scan on top of the window's field when that gives the field of them all on its own lattice
    // (the scan reaches no lower than the window): the same field, at a quarter of the cost.
    std::vector<PlacedScan> scans = window_;
    scans.push_back(*unmapped_scan_);
    if (LikelihoodField::ownLatticePoint(scans) == window_field_.latticePoint()) {
      field_.buildOnTop(window_field_, *unmapped_scan_, levels);
    } else {
      field_.build(scans, levels);
    }
    field_stale_ = false;
  }
  field_.ensureLevels(levels);
  return field_;
}

SearchWindow SlamProcessor::searchWindow(double seconds_since_last_scan) {
  const bool known = seconds_since_last_scan > 0.0 && std::isfinite(seconds_since_last_scan);
  if (known) {
    recent_intervals_.push_back(seconds_since_last_scan);
    if (recent_intervals_.size() > kRecentIntervals) recent_intervals_.erase(recent_intervals_.begin());
  }
  SearchWindow window{options_.search_window_linear, options_.search_window_angular};
  if (recent_intervals_.empty()) return window;
  std::vector<double> sorted = recent_intervals_;
  std::nth_element(sorted.begin(), sorted.begin() + static_cast<long>(sorted.size() / 2), sorted.end());
  // Never less than this scan's own interval: after scans were skipped (a node that could not keep up), the
  // robot had that long to move.
  const double interval = std::max(sorted[sorted.size() / 2], known ? seconds_since_last_scan : 0.0);
  window.linear = std::min(window.linear, kPlausibleSpeed * interval);
  window.angular = std::min(window.angular, kPlausibleTurnRate * interval);
  return window;
}

bool SlamProcessor::movedEnoughForMapUpdate() const {
  const double distance = std::hypot(pose_.x - last_map_update_pose_.x, pose_.y - last_map_update_pose_.y);
  const double rotation = std::abs(angleDifference(pose_.theta, last_map_update_pose_.theta));
  return distance > options_.map_update_distance_thresh || rotation > options_.map_update_angle_thresh;
}

}  // namespace hector_style_mapping
