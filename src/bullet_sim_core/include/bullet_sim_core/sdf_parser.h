#pragma once
// Reads the SDF (1.4 to 1.6) of Gazebo's .world files and model.sdf files into the plain
// descriptions of model_description.h. Everything that is wrong with the input is reported as a
// DescriptionError naming the file, the element path and what was expected (see sdf_element.h).
//
// What is supported, and how SDF maps onto ModelDescription:
//  - <world>: name, <physics> (max_step_size, real_time_factor, real_time_update_rate,
//    gravity, the engine's <solver><iters> and <constraints> contact_max_correcting_vel and
//    contact_surface_layer), <gravity>, <model>, <include> (uri, name, pose, static). Lights,
//    scene, gui, state and other world elements are ignored.
//  - model://ground_plane and model://sun are built in (sun is a light and yields no model).
//  - <model>: <static>, <pose>, <link>s, <joint>s, <plugin>s. Each link keeps its own frame (its
//    <pose> in the model frame); collisions, visuals, the inertial and sensors are in the link
//    frame, as in SDF; a collision's <surface><contact><ode> max_vel and min_depth are kept with
//    it, its <surface><friction><ode> mu and mu2 with its link. Nested models are refused.
//  - <joint type="revolute|continuous|prismatic|fixed"> with <parent>, <child> (a link, or "world"
//    as parent, which fixes the model to the world), <pose> (the joint frame in the child link
//    frame: its origin is the point the joint turns about), <axis><xyz> (in the joint frame; in
//    the model frame for SDF 1.4 and with <use_parent_model_frame>), <axis><limit> (lower, upper,
//    effort, velocity; |limits| >= 1e16 mean none, negative effort or velocity mean unlimited) and
//    <axis><dynamics> (damping, friction). A moving model's links must form one tree.
//  - A static model never moves: its joints are not needed, and all its links are held where their
//    poses put them.
//  - Without <inertial>, a link gets SDF's defaults: mass 1 kg, inertia identity.
#include <Eigen/Geometry>
#include <string>

#include "bullet_sim_core/model_description.h"
#include "bullet_sim_core/resource_resolver.h"

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
