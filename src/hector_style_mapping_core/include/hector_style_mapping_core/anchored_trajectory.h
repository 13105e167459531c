#ifndef HECTOR_STYLE_MAPPING_CORE_ANCHORED_TRAJECTORY_H
#define HECTOR_STYLE_MAPPING_CORE_ANCHORED_TRAJECTORY_H

#include <cstddef>
#include <vector>

#include "hector_style_mapping_core/pose_2d.h"

namespace hector_style_mapping {

// The path the mapper reports, kept in step with loop closure. Each pose is held relative to the newest
// keyframe when it was added, so that when a closed loop moves the keyframes, the path moves with them, as the
// map does (it is redrawn from them). Poses added before the first keyframe, or with loop closure off (no
// keyframes), stay as given.
class AnchoredTrajectory {
 public:
  // `keyframes`: the keyframes' current poses (SlamProcessor::keyframePoses()).
  void append(const Pose2D& pose, const std::vector<Pose2D>& keyframes);
  // Pose `i` (in the order appended) from its keyframe's current estimate in `keyframes`, the one it was
  // appended with.
  Pose2D pose(std::size_t i, const std::vector<Pose2D>& keyframes) const;
  std::size_t size() const { return anchors_.size(); }
  void clear() { anchors_.clear(); }

 private:
  struct Anchor {
    int keyframe;   // -1: none, `offset` is the pose itself
    Pose2D offset;  // the pose seen from the keyframe
  };
  std::vector<Anchor> anchors_;
};

}  // namespace hector_style_mapping

#endif  // HECTOR_STYLE_MAPPING_CORE_ANCHORED_TRAJECTORY_H
