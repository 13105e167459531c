#pragma once
// The parameters of libgazebo_ros_katana_gripper.so (katana_gazebo_plugins' names and defaults),
// read from its <plugin> element:
//
//   <plugin name="gazebo_ros_katana_gripper" filename="libgazebo_ros_katana_gripper.so">
//     <r_finger_joint>katana_r_finger_joint</r_finger_joint>
//     <l_finger_joint>katana_l_finger_joint</l_finger_joint>
//     <max_torque>0.5</max_torque> <node_namespace>katana</node_namespace>
//   </plugin>
//
// Upstream's l_finger_joint falls back to the r finger's name when absent (a bug: both PIDs would
// drive one finger); here it falls back to katana_l_finger_joint.
#include <string>

#include "bullet_sim_core/model_description.h"
#include "bullet_sim_plugins/katana_gripper_controller.h"

namespace bullet_sim {

struct KatanaGripperConfig {
  std::string r_finger_joint = "katana_r_finger_joint";
  std::string l_finger_joint = "katana_l_finger_joint";
  // Upstream publishes katana_msgs/GripperControllerState on <node_namespace>/gripper_controller_state;
  // katana_msgs is not in this workspace, so it is read and not used.
  std::string node_namespace = "katana";
  // max_torque from <max_torque>, max_velocity the finger joints' (slower) velocity limit; the
  // rest are upstream's constants.
  KatanaGripperOptions options;
};

// Throws DescriptionError naming the element: a finger that is not a revolute, continuous or
// prismatic joint of `model`, both fingers on one joint, a max_torque that is not > 0.
KatanaGripperConfig parseKatanaGripperConfig(const PluginDescription& plugin, const ModelDescription& model);

}  // namespace bullet_sim
