#pragma once
// Reads the subset of SDF used by the Gazebo tutorials' .world files and models into the
// plain descriptions of model_description.h. Everything that is wrong with the input is
// reported as a DescriptionError naming the file, the element path and what was expected.
//
// What is supported, and how SDF maps onto ModelDescription:
//  - <world>: name, <physics> (max_step_size, real_time_factor, real_time_update_rate,
//    gravity), <gravity>, <model>, <include> (uri, name, pose, static). Lights, scene, gui,
//    state and other world elements are ignored.
//  - model://ground_plane and model://sun are built in (sun is a light and yields no model).
//  - A static model may have several links; they become ONE LinkDescription named after
//    the first link, all shapes expressed in the model frame. A moving model must have
//    exactly one link and no <joint>; its link pose is folded into the shapes and inertial,
//    so the link frame is the model frame. Sensors' <pose> are re-expressed likewise.
//  - Without <inertial>, a link gets SDF's defaults: mass 1 kg, inertia identity.
#include <Eigen/Geometry>
#include <string>

#include "bullet_sim/model_description.h"
#include "bullet_sim/resource_resolver.h"

namespace bullet_sim {

// Reads and parses a .world file; relative URIs are taken relative to its folder.
WorldDescription parseWorldFile(const std::string& path, const ResourceResolver& resolver);

// Parses world XML text; source names it in error messages, base_dir resolves relative URIs.
WorldDescription parseWorldString(const std::string& xml, const std::string& source,
                                  const std::string& base_dir, const ResourceResolver& resolver);

// Parses one model, given as <sdf><model> or a bare <model> (spawn_sdf_model, model://
// includes). If model_pose is given, it receives the model's own <pose> (identity when
// absent): gazebo_ros places a spawned model at initial_pose * model_pose.
ModelDescription parseSdfModel(const std::string& xml, const std::string& source,
                               const std::string& base_dir, const ResourceResolver& resolver,
                               Eigen::Isometry3d* model_pose = nullptr);

}  // namespace bullet_sim
