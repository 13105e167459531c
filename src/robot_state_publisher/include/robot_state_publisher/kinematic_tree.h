#pragma once
// A robot's joints as robot_state_publisher publishes them, from its URDF: each joint's parent and
// child link and the transform between them at a joint position (KDL's segment pose), the fixed
// joints apart, and the mimic joints' rules. No ROS here: the node (robot_state_publisher_node.cpp)
// turns these into tf messages.
#include <map>
#include <string>
#include <vector>

#include <kdl/frames.hpp>
#include <kdl/segment.hpp>
#include <urdf_model/model.h>

namespace robot_state_publisher {

struct JointFrame {
  std::string joint, parent, child;
  KDL::Segment segment;  // pose(q): the child link's frame in the parent's at position q
};

struct MimicRule {  // position = multiplier * position of `follows` + offset
  std::string joint, follows;
  double multiplier = 1.0, offset = 0.0;
};

class KinematicTree {
 public:
  // Throws std::invalid_argument saying what KDL could not make of the model.
  explicit KinematicTree(const urdf::ModelInterface& model);

  const std::vector<JointFrame>& fixedJoints() const { return fixed_; }
  // nullptr for a joint the URDF does not have or that does not move.
  const JointFrame* movingJoint(const std::string& name) const;
  const std::vector<MimicRule>& mimicRules() const { return mimics_; }
  // Floating joints: joint_states cannot say where their child is, so they are left out.
  const std::vector<std::string>& floatingJoints() const { return floating_; }

 private:
  std::vector<JointFrame> fixed_;
  std::map<std::string, JointFrame> moving_;
  std::vector<MimicRule> mimics_;
  std::vector<std::string> floating_;
};

// tf's resolve(prefix, frame) as ROS 1's tf_prefix applies it: "prefix/frame", leading slashes
// dropped; a frame that starts with '/' is taken as it is (without the slash).
std::string prefixedFrame(const std::string& tf_prefix, const std::string& frame);

}  // namespace robot_state_publisher
