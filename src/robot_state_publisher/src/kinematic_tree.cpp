#include "robot_state_publisher/kinematic_tree.h"

#include <stdexcept>

#include <kdl/tree.hpp>
#include <kdl_parser/kdl_parser.hpp>

namespace robot_state_publisher {

KinematicTree::KinematicTree(const urdf::ModelInterface& model) {
  KDL::Tree tree;
  if (!kdl_parser::treeFromUrdfModel(model, tree))
    throw std::invalid_argument("Failed to extract kdl tree from xml robot description");
  const std::string root = tree.getRootSegment()->first;
  for (const auto& [name, element] : tree.getSegments()) {
    if (name == root) continue;  // the root link: no joint above it
    const KDL::Segment& segment = GetTreeElementSegment(element);
    const std::string parent = GetTreeElementSegment(GetTreeElementParent(element)->second).getName();
    JointFrame frame{segment.getJoint().getName(), parent, segment.getName(), segment};
    if (segment.getJoint().getType() != KDL::Joint::None) {
      moving_.emplace(frame.joint, std::move(frame));
      continue;
    }
    const urdf::JointConstSharedPtr joint = model.getJoint(frame.joint);
    if (joint && joint->type == urdf::Joint::FLOATING)
      floating_.push_back(frame.joint);
    else
      fixed_.push_back(std::move(frame));
  }
  for (const auto& [name, joint] : model.joints_)
    if (joint->mimic) mimics_.push_back({name, joint->mimic->joint_name, joint->mimic->multiplier, joint->mimic->offset});
}

const JointFrame* KinematicTree::movingJoint(const std::string& name) const {
  const auto found = moving_.find(name);
  return found == moving_.end() ? nullptr : &found->second;
}

std::string prefixedFrame(const std::string& tf_prefix, const std::string& frame) {
  const auto withoutSlash = [](const std::string& s) {
    const std::size_t start = s.find_first_not_of('/');
    return start == std::string::npos ? std::string() : s.substr(start);
  };
  if (!frame.empty() && frame[0] == '/') return withoutSlash(frame);
  const std::string prefix = withoutSlash(tf_prefix);
  return prefix.empty() ? frame : prefix + "/" + frame;
}

}  // namespace robot_state_publisher
