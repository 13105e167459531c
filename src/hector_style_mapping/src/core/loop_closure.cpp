#include "hector_style_mapping/loop_closure.h"

#include <algorithm>
#include <cmath>
#include <utility>

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
    graph_.addConstraint(candidate, keyframe, between(pose(candidate), found.pose), constraintInformation());
    ++closures_;
    closed = true;
  }
  if (!closed) return false;
  OptimizerOptions options;
  options.robust_kernel = RobustKernel::kCauchy;
  graph_.optimize(options);
  return true;
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
