#include "hector_style_mapping_core/anchored_trajectory.h"

namespace hector_style_mapping {

void AnchoredTrajectory::append(const Pose2D& pose, const std::vector<Pose2D>& keyframes) {
  const int newest = static_cast<int>(keyframes.size()) - 1;
  if (newest < 0) {
    anchors_.push_back({-1, pose});
  } else {
    anchors_.push_back({newest, between(keyframes[static_cast<std::size_t>(newest)], pose)});
  }
}

Pose2D AnchoredTrajectory::pose(std::size_t i, const std::vector<Pose2D>& keyframes) const {
  const Anchor& anchor = anchors_.at(i);
  if (anchor.keyframe < 0) return anchor.offset;
  return compose(keyframes.at(static_cast<std::size_t>(anchor.keyframe)), anchor.offset);
}

}  // namespace hector_style_mapping
