#include "hector_style_mapping_core/loop_closure.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include <Eigen/Cholesky>

namespace hector_style_mapping {

namespace {

Eigen::Matrix3d constraintInformation() {
  const double t = 1.0 / (LoopClosure::kTranslationSigma * LoopClosure::kTranslationSigma);
  const double r = 1.0 / (LoopClosure::kRotationSigma * LoopClosure::kRotationSigma);
  return Eigen::Vector3d(t, t, r).asDiagonal();
}

}  // namespace

bool LoopClosure::addKeyframe(const ScanPoints& scan, const Pose2D& matched) {
  const int keyframe = graph_.addNode(matched);
  scans_.push_back(scan);
  if (keyframe > 0)
    graph_.addConstraint(keyframe - 1, keyframe, between(pose(keyframe - 1), matched), constraintInformation());
  if (keyframe % kTryEvery != 0) return false;

  bool closed = false;
  for (const int candidate : candidatesFor(keyframe)) {
    ++attempts_;
    std::vector<PlacedScan> submap;
    const int last = std::min(candidate + kSubmapHalfWidth, keyframe - kMinKeyframeGap);
    for (int i = std::max(candidate - kSubmapHalfWidth, 0); i <= last; ++i)
      submap.push_back({pose(i), scans_[static_cast<std::size_t>(i)]});
    submap_.build(submap);
    const SearchResult found = correlativeSearch(submap_, scan, matched, {kWindowLinear, kWindowAngular});
    if (found.score < kMinScore) continue;
    const Pose2D relative = between(pose(candidate), found.pose);
    if (!agreesWithChain(candidate, keyframe, relative)) {
      ++inconsistent_;
      continue;
    }
    const SearchResult elsewhere = correlativeSearchElsewhere(submap_, scan, matched, {kWindowLinear, kWindowAngular},
                                                              Eigen::Vector2d(found.pose.x, found.pose.y), kDistinct);
    if (elsewhere.score > kMaxElsewhereRatio * found.score) {
      ++ambiguous_;
      continue;
    }
    graph_.addConstraint(candidate, keyframe, relative, constraintInformation());
    closures_.push_back({candidate, keyframe, relative, found.score, elsewhere.score});
    closed = true;
  }
  if (!closed) return false;
  OptimizerOptions options;
  options.robust_kernel = RobustKernel::kCauchy;
  graph_.optimize(options);
  return true;
}

bool LoopClosure::agreesWithChain(int from, int to, const Pose2D& relative) const {
  // The covariance of `to` seen from `from` along the chain of steps between them, each step's noise
  // kTranslationSigma / kRotationSigma in its own frame (first-order propagation through compose()).
  const double t = kTranslationSigma * kTranslationSigma, r = kRotationSigma * kRotationSigma;
  const Eigen::Matrix3d step_noise = Eigen::Vector3d(t, t, r).asDiagonal();
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  Pose2D chained;
  for (int i = from; i < to; ++i) {
    const Pose2D step = between(pose(i), pose(i + 1));
    const double c = std::cos(chained.theta), s = std::sin(chained.theta);
    Eigen::Matrix3d along_chain = Eigen::Matrix3d::Identity();  // d compose / d chained
    along_chain(0, 2) = -s * step.x - c * step.y;
    along_chain(1, 2) = c * step.x - s * step.y;
    Eigen::Matrix3d along_step = Eigen::Matrix3d::Identity();  // d compose / d step
    along_step.topLeftCorner<2, 2>() << c, -s, s, c;
    covariance = along_chain * covariance * along_chain.transpose() + along_step * step_noise * along_step.transpose();
    chained = compose(chained, step);
  }
  // The match is itself a constraint with that noise.
  covariance += step_noise;
  const Eigen::Vector3d error(relative.x - chained.x, relative.y - chained.y,
                              angleDifference(relative.theta, chained.theta));
  return error.dot(covariance.ldlt().solve(error)) <= kMaxChainDistance2;
}

std::vector<int> LoopClosure::candidatesFor(int keyframe) const {
  const Pose2D& here = pose(keyframe);
  std::vector<std::pair<double, int>> near;
  for (int i = 0; i + kMinKeyframeGap <= keyframe; ++i) {
    const double distance = std::hypot(pose(i).x - here.x, pose(i).y - here.y);
    if (distance <= kCandidateRadius) near.emplace_back(distance, i);
  }
  std::sort(near.begin(), near.end());
  // The nearest first, then the nearest of other passes: keyframes at least kMinKeyframeGap from those taken.
  std::vector<int> chosen;
  for (const auto& [distance, i] : near) {
    if (static_cast<int>(chosen.size()) == kCandidatesPerTry) break;
    if (std::all_of(chosen.begin(), chosen.end(), [&](int c) { return std::abs(c - i) >= kMinKeyframeGap; }))
      chosen.push_back(i);
  }
  return chosen;
}

}  // namespace hector_style_mapping
