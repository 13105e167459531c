#include "hector_style_mapping_core/anchored_trajectory.h"

namespace hector_style_mapping {

void AnchoredTrajectory::append(const Pose2D& pose, const LoopClosure& loops) {
  const int newest = loops.keyframes() - 1;
  if (newest < 0) {
    anchors_.push_back({-1, pose});
  } else {
    anchors_.push_back({newest, between(loops.pose(newest), pose)});
  }
}

Pose2D AnchoredTrajectory::pose(std::size_t i, const LoopClosure& loops) const {
  const Anchor& anchor = anchors_.at(i);
  if (anchor.keyframe < 0) return anchor.offset;
  return compose(loops.pose(anchor.keyframe), anchor.offset);
}

}  // namespace hector_style_mapping
