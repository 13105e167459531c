#ifndef HECTOR_STYLE_MAPPING_CORE_LOOP_CLOSURE_H
#define HECTOR_STYLE_MAPPING_CORE_LOOP_CLOSURE_H

#include <vector>

#include <Eigen/Core>

#include "hector_style_mapping_core/correlative_search.h"
#include "hector_style_mapping_core/likelihood_field.h"
#include "hector_style_mapping_core/pose_2d.h"
#include "hector_style_mapping_core/pose_graph.h"
#include "hector_style_mapping_core/scan_points.h"

namespace hector_style_mapping {

// Loop closure for the front end: every scan that updated the map becomes a keyframe, a node of a pose graph
// tied to the previous keyframe by the front end's motion between them. Every few keyframes, the keyframe is
// also searched for (correlativeSearch, no motion prior) in a submap of an older keyframe that lies near it by
// the current estimates: when it fits well, that match ties the two, and the graph is optimised (sparse pose
// adjustment with a Cauchy kernel, so that a confident wrong match in look-alike corridors cannot bend the
// whole loop). What drifted along the way is spread back over the loop.
class LoopClosure {
 public:
  // Keyframes that must lie between the two ends of a closure: nearer ones are the front end's business.
  static constexpr int kMinKeyframeGap = 20;
  // Closures are tried on every kTryEvery-th keyframe, against the older keyframes within kCandidateRadius (by
  // the current estimates): the nearest, and the nearest of up to kCandidatesPerTry - 1 other passes there
  // (keyframes at least kMinKeyframeGap apart), so that a pass that drifted far is still tied to the others.
  static constexpr int kTryEvery = 5;
  static constexpr double kCandidateRadius = 3.0;  // m
  static constexpr int kCandidatesPerTry = 3;
  // The search's half-widths round the keyframe's estimate: the drift a loop of a few hundred metres gathers.
  static constexpr double kWindowLinear = 2.0;  // m
  static constexpr double kWindowAngular = 0.35;  // rad
  // The submap: the candidate and this many keyframes each side of it.
  static constexpr int kSubmapHalfWidth = 2;
  // A closure needs this mean field value (LikelihoodField: 1 on a wall, -1 in seen free space): most points on
  // the submap's walls, few in its free space.
  static constexpr double kMinScore = 0.55;
  // Standard deviations of a constraint, a front-end step or a closure alike: what scan matching leaves on these
  // logs (docs/MAPPING.md: 2-3 cm median, half a degree).
  static constexpr double kTranslationSigma = 0.05;  // m
  static constexpr double kRotationSigma = 0.01;     // rad
  // A match is kept only when it agrees with the keyframes' current estimates as well as the chain of front-end
  // steps between the two allows: its squared Mahalanobis distance under the chain's covariance (those sigmas per
  // step, propagated along it) below chi-square's 99.9 % point for 3 degrees of freedom. Look-alike corridors
  // give confident matches metres along them; a short loop cannot have drifted that far.
  static constexpr double kMaxChainDistance2 = 16.27;
  // ... and only when the same search, leaving out the match's surroundings (kDistinct along x and y), finds
  // nothing scoring above kMaxElsewhereRatio of the match: a second fit nearly as good says the scan cannot tell
  // the two places apart.
  static constexpr double kDistinct = 0.3;  // m
  static constexpr double kMaxElsewhereRatio = 0.9;

  // Adds a keyframe: `scan` (base frame), matched by the front end at `matched` (map frame, consistent with the
  // poses this class returns). True when a loop closed: then every keyframe's pose() may have moved.
  bool addKeyframe(const ScanPoints& scan, const Pose2D& matched);

  int keyframes() const { return static_cast<int>(scans_.size()); }
  // Keyframe i's pose, optimised; its scan.
  const Pose2D& pose(int keyframe) const { return graph_.pose(keyframe); }
  const ScanPoints& scan(int keyframe) const { return scans_[static_cast<std::size_t>(keyframe)]; }
  // An accepted closure: keyframe `to` seen from keyframe `from` at `relative`, with the search's score.
  struct Closure {
    int from;
    int to;
    Pose2D relative;
    double score;
    double elsewhere;  // the best score more than kDistinct from the match
  };
  // Closures accepted, and tried, since construction.
  int closures() const { return static_cast<int>(closures_.size()); }
  const std::vector<Closure>& acceptedClosures() const { return closures_; }
  int attempts() const { return attempts_; }
  // Matches good enough to close a loop but refused: by the chain check (kMaxChainDistance2), as ambiguous
  // (kMaxElsewhereRatio).
  int inconsistent() const { return inconsistent_; }
  int ambiguous() const { return ambiguous_; }

 private:
  // The keyframes to try `keyframe` against (see kCandidatesPerTry), nearest first.
  std::vector<int> candidatesFor(int keyframe) const;
  // Whether `relative`, keyframe `to` seen from keyframe `from`, passes the chain check (kMaxChainDistance2).
  bool agreesWithChain(int from, int to, const Pose2D& relative) const;

  PoseGraph graph_;
  std::vector<ScanPoints> scans_;
  LikelihoodField submap_;
  std::vector<Closure> closures_;
  int attempts_ = 0;
  int inconsistent_ = 0;
  int ambiguous_ = 0;
};

}  // namespace hector_style_mapping

#endif  // HECTOR_STYLE_MAPPING_CORE_LOOP_CLOSURE_H
