#include "bullet_sim/gazebo_ros_api.h"

#include <gazebo_msgs/LinkStates.h>
#include <gazebo_msgs/ModelStates.h>
#include <tinyxml2.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "bullet_sim/pose_info.h"
#include "bullet_sim_core/description_error.h"
#include "bullet_sim_core/sdf_parser.h"
#include "bullet_sim_core/urdf_parser.h"
#include "bullet_sim_plugins/ros_conversions.h"

namespace bullet_sim {
namespace {

// "model::link" -> ("model", "link"); no "::" -> (name, "").
std::pair<std::string, std::string> splitScoped(const std::string& name) {
  const auto pos = name.find("::");
  if (pos == std::string::npos) return {name, ""};
  return {name.substr(0, pos), name.substr(pos + 2)};
}

bool isWorld(const std::string& frame) { return frame.empty() || frame == "world" || frame == "map"; }

std::string rootElementName(const std::string& xml) {
  tinyxml2::XMLDocument doc;
  if (doc.Parse(xml.c_str(), xml.size()) != tinyxml2::XML_SUCCESS || !doc.RootElement()) return "";
  return doc.RootElement()->Name();
}

}  // namespace

GazeboRosApi::GazeboRosApi(Simulator& sim) : sim_(sim), node_("/gazebo"), reconfigure_(sim) {
  auto& n = node_;
  services_ = {
      n.advertiseService("spawn_urdf_model", &GazeboRosApi::spawnUrdf, this),
      n.advertiseService("spawn_sdf_model", &GazeboRosApi::spawnSdf, this),
      n.advertiseService("delete_model", &GazeboRosApi::deleteModel, this),
      n.advertiseService("get_model_state", &GazeboRosApi::getModelState, this),
      n.advertiseService("set_model_state", &GazeboRosApi::setModelState, this),
      n.advertiseService("get_link_state", &GazeboRosApi::getLinkState, this),
      n.advertiseService("set_link_state", &GazeboRosApi::setLinkState, this),
      n.advertiseService("get_model_properties", &GazeboRosApi::getModelProperties, this),
      n.advertiseService("get_joint_properties", &GazeboRosApi::getJointProperties, this),
      n.advertiseService("get_link_properties", &GazeboRosApi::getLinkProperties, this),
      n.advertiseService("get_world_properties", &GazeboRosApi::getWorldProperties, this),
      n.advertiseService("get_physics_properties", &GazeboRosApi::getPhysicsProperties, this),
      n.advertiseService("set_physics_properties", &GazeboRosApi::setPhysicsProperties, this),
      n.advertiseService("apply_joint_effort", &GazeboRosApi::applyJointEffort, this),
      n.advertiseService("apply_body_wrench", &GazeboRosApi::applyBodyWrench, this),
      n.advertiseService("clear_joint_forces", &GazeboRosApi::clearJointForces, this),
      n.advertiseService("clear_body_wrenches", &GazeboRosApi::clearBodyWrenches, this),
      n.advertiseService("set_model_configuration", &GazeboRosApi::setModelConfiguration, this),
      n.advertiseService("pause_physics", &GazeboRosApi::pausePhysics, this),
      n.advertiseService("unpause_physics", &GazeboRosApi::unpausePhysics, this),
      n.advertiseService("step_world", &GazeboRosApi::stepWorld, this),  // ours: gzclient's step button
      n.advertiseService("reset_simulation", &GazeboRosApi::resetSimulation, this),
      n.advertiseService("reset_world", &GazeboRosApi::resetWorld, this),
  };
  set_model_state_sub_ = n.subscribe("set_model_state", 10, &GazeboRosApi::setModelStateTopic, this);
  set_link_state_sub_ = n.subscribe("set_link_state", 10, &GazeboRosApi::setLinkStateTopic, this);
  model_states_pub_.advertise<gazebo_msgs::ModelStates>(n, "model_states", 1);
  link_states_pub_.advertise<gazebo_msgs::LinkStates>(n, "link_states", 1);
  sim_.before_step = [this](const ros::Time& now) { applyTimedForces(now); };
}

// --- timed efforts and wrenches -------------------------------------------------------------

void GazeboRosApi::applyTimedForces(const ros::Time& now) {
  auto expired = [&](const ros::Time& end) { return !end.isZero() && now >= end; };
  joint_efforts_.erase(std::remove_if(joint_efforts_.begin(), joint_efforts_.end(),
                                      [&](const TimedJointEffort& e) { return expired(e.end); }),
                       joint_efforts_.end());
  wrenches_.erase(std::remove_if(wrenches_.begin(), wrenches_.end(),
                                 [&](const TimedWrench& w) { return expired(w.end); }),
                  wrenches_.end());
  for (const auto& e : joint_efforts_) {
    if (now < e.start) continue;
    PhysicsModel* m = sim_.physics().findModel(e.model);
    m->addJointEffort(m->jointIndex(e.joint), e.effort);
  }
  for (const auto& w : wrenches_) {
    if (now < w.start) continue;
    PhysicsModel* m = sim_.physics().findModel(w.model);
    m->addLinkWrench(w.link, w.force, w.torque, m->linkPose(w.link) * w.point);
  }
}

// --- entities -------------------------------------------------------------------------------

bool GazeboRosApi::entityPose(const std::string& name, Eigen::Isometry3d& pose, Twist* twist) const {
  if (isWorld(name)) {
    pose.setIdentity();
    if (twist) *twist = Twist();
    return true;
  }
  const auto [model_name, link] = splitScoped(name);
  const PhysicsModel* model = sim_.physics().findModel(model_name);
  if (!model || (!link.empty() && !model->hasLink(link))) return false;
  pose = link.empty() ? model->pose() : model->linkPose(link);
  if (twist) *twist = link.empty() ? model->twist() : model->linkTwist(link);
  return true;
}

// --- spawn / delete -------------------------------------------------------------------------

bool GazeboRosApi::spawnUrdf(gazebo_msgs::SpawnModel::Request& req, gazebo_msgs::SpawnModel::Response& res) {
  return spawn(req, res, true);
}
bool GazeboRosApi::spawnSdf(gazebo_msgs::SpawnModel::Request& req, gazebo_msgs::SpawnModel::Response& res) {
  return spawn(req, res, false);
}

bool GazeboRosApi::spawn(gazebo_msgs::SpawnModel::Request& req, gazebo_msgs::SpawnModel::Response& res,
                         bool urdf_service) {
  const std::string service = urdf_service ? "SpawnModel (spawn_urdf_model)" : "SpawnModel (spawn_sdf_model)";
  const std::string source = "spawn request for model '" + req.model_name + "'";
  res.success = false;
  if (req.model_name.empty()) {
    res.status_message = service + ": model_name: expected a non-empty name";
    return true;
  }
  if (sim_.physics().findModel(req.model_name)) {
    res.status_message = service + ": model_name: a model named '" + req.model_name +
                         "' already exists; delete it first or choose another name";
    return true;
  }
  Eigen::Isometry3d initial, reference;
  std::string error;
  if (!toPose(req.initial_pose, service + ": initial_pose", initial, error)) {
    res.status_message = error;
    return true;
  }
  if (!entityPose(req.reference_frame, reference)) {
    res.status_message = service + ": reference_frame: entity '" + req.reference_frame +
                         "' does not exist (expected '', 'world', a model name or 'model::link')";
    return true;
  }
  try {
    const std::string root = rootElementName(req.model_xml);
    ModelDescription model;
    Eigen::Isometry3d model_pose = Eigen::Isometry3d::Identity();
    if (root == "robot") {
      model = parseUrdf(req.model_xml, source, sim_.resolver());
    } else if (root == "sdf" || root == "model") {
      model = parseSdfModel(req.model_xml, source, "", sim_.resolver(), &model_pose);
    } else if (req.model_xml.find_first_not_of(" \t\r\n") == std::string::npos) {
      throw DescriptionError(source + ": model_xml is empty; expected URDF (<robot>) or SDF (<sdf>) text");
    } else {
      // Let the parser of the service's own format say what is wrong with the XML.
      if (urdf_service) model = parseUrdf(req.model_xml, source, sim_.resolver());
      else model = parseSdfModel(req.model_xml, source, "", sim_.resolver(), &model_pose);
    }
    model.name = req.model_name;
    sim_.spawn(model, reference * initial * model_pose, req.robot_namespace);
  } catch (const DescriptionError& e) {
    res.status_message = service + ": " + e.what();
    ROS_ERROR_STREAM(res.status_message);
    return true;
  } catch (const std::exception& e) {
    res.status_message = service + ": " + source + ": " + e.what();
    ROS_ERROR_STREAM(res.status_message);
    return true;
  }
  res.success = true;
  res.status_message = "SpawnModel: Successfully spawned entity";  // upstream's words, which scripts look for
  ROS_INFO_STREAM(res.status_message << " '" << req.model_name << "'");
  return true;
}

bool GazeboRosApi::deleteModel(gazebo_msgs::DeleteModel::Request& req, gazebo_msgs::DeleteModel::Response& res) {
  res.success = sim_.remove(req.model_name);
  // Forces die with their body: a new model of the same name must not inherit them.
  joint_efforts_.erase(std::remove_if(joint_efforts_.begin(), joint_efforts_.end(),
                                      [&](const TimedJointEffort& e) { return e.model == req.model_name; }),
                       joint_efforts_.end());
  wrenches_.erase(std::remove_if(wrenches_.begin(), wrenches_.end(),
                                 [&](const TimedWrench& w) { return w.model == req.model_name; }),
                  wrenches_.end());
  res.status_message = res.success ? "DeleteModel: successfully deleted model"
                                   : "DeleteModel: model [" + req.model_name + "] does not exist";
  return true;
}

// --- model and link state -------------------------------------------------------------------

bool GazeboRosApi::getModelState(gazebo_msgs::GetModelState::Request& req, gazebo_msgs::GetModelState::Response& res) {
  res.header.stamp = sim_.now();
  res.header.frame_id = req.relative_entity_name;
  const PhysicsModel* model = sim_.physics().findModel(req.model_name);
  if (!model) {
    res.success = false;
    res.status_message = "GetModelState: model [" + req.model_name + "] does not exist";
    return true;
  }
  Eigen::Isometry3d reference;
  Twist reference_twist;
  if (!entityPose(req.relative_entity_name, reference, &reference_twist)) {
    res.success = false;
    res.status_message = "GetModelState: reference relative_entity_name [" + req.relative_entity_name +
                         "] not found, did you forget to scope the body by model name (model::link)?";
    return true;
  }
  const Eigen::Matrix3d to_reference = reference.linear().transpose();
  res.pose = toPoseMsg(reference.inverse() * model->pose());
  const Twist t = model->twist();
  res.twist.linear = toVector3Msg(to_reference * (t.linear - reference_twist.linear));
  res.twist.angular = toVector3Msg(to_reference * (t.angular - reference_twist.angular));
  res.success = true;
  res.status_message = "GetModelState: got properties";
  return true;
}

bool GazeboRosApi::applyModelState(const gazebo_msgs::ModelState& state, std::string& status) {
  PhysicsModel* model = sim_.physics().findModel(state.model_name);
  if (!model) {
    status = "SetModelState: model [" + state.model_name + "] does not exist";
    return false;
  }
  Eigen::Isometry3d pose;
  Twist twist;
  if (!worldState(state.pose, state.twist, state.reference_frame, "SetModelState: model_state", pose, twist, status))
    return false;
  model->setPose(pose);
  model->setTwist(twist);
  status = "SetModelState: set model state done";
  return true;
}

bool GazeboRosApi::worldState(const geometry_msgs::Pose& pose_msg, const geometry_msgs::Twist& twist_msg,
                              const std::string& reference_frame, const std::string& what, Eigen::Isometry3d& pose,
                              Twist& twist, std::string& status) const {
  Eigen::Isometry3d reference;
  if (!toPose(pose_msg, what + ".pose", pose, status)) return false;
  if (!isFinite(twist_msg)) {
    status = what + ".twist: expected finite numbers";
    return false;
  }
  if (!entityPose(reference_frame, reference)) {
    status = what + ": specified reference frame entity [" + reference_frame + "] does not exist";
    return false;
  }
  pose = reference * pose;
  twist = toTwist(twist_msg);
  twist.linear = reference.linear() * twist.linear;
  twist.angular = reference.linear() * twist.angular;
  return true;
}

bool GazeboRosApi::setModelState(gazebo_msgs::SetModelState::Request& req, gazebo_msgs::SetModelState::Response& res) {
  res.success = applyModelState(req.model_state, res.status_message);
  return true;
}

void GazeboRosApi::setModelStateTopic(const gazebo_msgs::ModelState::ConstPtr& msg) {
  std::string status;
  if (!applyModelState(*msg, status)) ROS_WARN_STREAM_THROTTLE(1.0, "/gazebo/set_model_state topic: " << status);
}

bool GazeboRosApi::getLinkState(gazebo_msgs::GetLinkState::Request& req, gazebo_msgs::GetLinkState::Response& res) {
  Eigen::Isometry3d pose, reference;
  Twist twist, reference_twist;
  if (splitScoped(req.link_name).second.empty() || !entityPose(req.link_name, pose, &twist)) {
    res.success = false;
    res.status_message = "GetLinkState: link [" + req.link_name + "] does not exist (expected 'model::link')";
    return true;
  }
  if (!entityPose(req.reference_frame, reference, &reference_twist)) {
    res.success = false;
    res.status_message = "GetLinkState: reference_frame [" + req.reference_frame + "] does not exist";
    return true;
  }
  const Eigen::Matrix3d to_reference = reference.linear().transpose();
  res.link_state.link_name = req.link_name;
  res.link_state.reference_frame = req.reference_frame;
  res.link_state.pose = toPoseMsg(reference.inverse() * pose);
  res.link_state.twist.linear = toVector3Msg(to_reference * (twist.linear - reference_twist.linear));
  res.link_state.twist.angular = toVector3Msg(to_reference * (twist.angular - reference_twist.angular));
  res.success = true;
  res.status_message = "GetLinkState: got state";
  return true;
}

// A model is one multibody (reduced coordinates): its root link can be placed anywhere, which
// moves the whole model, but the others follow from their joints, so placing one of them would
// break its joints. Gazebo (maximal coordinates) lets the joints pull such a link back; here it is
// refused with the way to move it.
bool GazeboRosApi::applyLinkState(const gazebo_msgs::LinkState& state, std::string& status) {
  const auto [model_name, link] = splitScoped(state.link_name);
  PhysicsModel* model = sim_.physics().findModel(model_name);
  if (link.empty() || !model || !model->hasLink(link)) {
    status = "SetLinkState: link [" + state.link_name + "] does not exist (expected 'model::link')";
    return false;
  }
  const std::string root = model->linkNames().front();
  if (link != root) {
    status = "SetLinkState: link [" + state.link_name + "] hangs on joints from its model's root link [" + root +
             "]: set the root link's state to move the model, or the joints with set_model_configuration";
    return false;
  }
  Eigen::Isometry3d link_pose;
  Twist twist;
  if (!worldState(state.pose, state.twist, state.reference_frame, "SetLinkState: link_state", link_pose, twist, status))
    return false;
  // The model's frame sits where it sits relative to its root link; the twist asked for is the
  // link origin's, the model's is its frame origin's.
  const Eigen::Isometry3d link_to_model = model->linkPose(link).inverse() * model->pose();
  model->setPose(link_pose * link_to_model);
  twist.linear += twist.angular.cross(model->pose().translation() - link_pose.translation());
  model->setTwist(twist);
  status = "SetLinkState: success";
  return true;
}

bool GazeboRosApi::setLinkState(gazebo_msgs::SetLinkState::Request& req, gazebo_msgs::SetLinkState::Response& res) {
  res.success = applyLinkState(req.link_state, res.status_message);
  return true;
}

void GazeboRosApi::setLinkStateTopic(const gazebo_msgs::LinkState::ConstPtr& msg) {
  std::string status;
  if (!applyLinkState(*msg, status)) ROS_WARN_STREAM_THROTTLE(1.0, "/gazebo/set_link_state topic: " << status);
}

bool GazeboRosApi::getModelProperties(gazebo_msgs::GetModelProperties::Request& req,
                                      gazebo_msgs::GetModelProperties::Response& res) {
  const PhysicsModel* model = sim_.physics().findModel(req.model_name);
  if (!model) {
    res.success = false;
    res.status_message = "GetModelProperties: model [" + req.model_name + "] does not exist";
    return true;
  }
  res.body_names = model->linkNames();
  res.canonical_body_name = res.body_names.front();
  for (const auto& link : model->description().links)
    for (const auto& c : link.collisions) res.geom_names.push_back(c.name.empty() ? link.name + "_collision" : c.name);
  for (const auto& j : model->joints()) res.joint_names.push_back(j.name);
  res.is_static = model->isStatic();
  res.success = true;
  res.status_message = "GetModelProperties: got properties";
  return true;
}

// The link's <inertial> as its description gives it (a moving link given none reports mass 0;
// the simulator moves it with a small substitute, and said so when it was spawned).
bool GazeboRosApi::getLinkProperties(gazebo_msgs::GetLinkProperties::Request& req,
                                     gazebo_msgs::GetLinkProperties::Response& res) {
  auto [model_name, link_name] = splitScoped(req.link_name);
  const PhysicsModel* model = sim_.physics().findModel(model_name);
  const LinkDescription* link = nullptr;
  if (model && !link_name.empty())
    for (const LinkDescription& l : model->description().links)
      if (l.name == link_name) link = &l;
  if (!link) {
    res.success = false;
    res.status_message = "GetLinkProperties: link [" + req.link_name + "] does not exist (expected 'model::link')";
    return true;
  }
  const Inertial& inertial = link->inertial;
  res.com = toPoseMsg(inertial.origin);
  res.gravity_mode = link->gravity;
  res.mass = inertial.mass;
  res.ixx = inertial.inertia(0, 0);
  res.ixy = inertial.inertia(0, 1);
  res.ixz = inertial.inertia(0, 2);
  res.iyy = inertial.inertia(1, 1);
  res.iyz = inertial.inertia(1, 2);
  res.izz = inertial.inertia(2, 2);
  res.success = true;
  res.status_message = "GetLinkProperties: got properties";
  return true;
}

bool GazeboRosApi::getJointProperties(gazebo_msgs::GetJointProperties::Request& req,
                                      gazebo_msgs::GetJointProperties::Response& res) {
  auto [model_name, joint_name] = splitScoped(req.joint_name);
  for (const std::string& name : sim_.physics().modelNames()) {
    const PhysicsModel* model = sim_.physics().findModel(name);
    if (!joint_name.empty() && name != model_name) continue;
    const int j = model->jointIndex(joint_name.empty() ? model_name : joint_name);
    if (j < 0) continue;
    const JointDescription& d = model->joints()[j];
    res.type = d.type == JointType::Prismatic    ? gazebo_msgs::GetJointProperties::Response::PRISMATIC
               : d.type == JointType::Continuous ? gazebo_msgs::GetJointProperties::Response::CONTINUOUS
                                                 : gazebo_msgs::GetJointProperties::Response::REVOLUTE;
    res.damping = {d.damping};
    res.position = {model->jointPosition(j)};
    res.rate = {model->jointVelocity(j)};
    res.success = true;
    res.status_message = "GetJointProperties: got properties";
    return true;
  }
  res.success = false;
  res.status_message = "GetJointProperties: joint [" + req.joint_name + "] does not exist";
  return true;
}

// --- world and physics ----------------------------------------------------------------------

bool GazeboRosApi::getWorldProperties(gazebo_msgs::GetWorldProperties::Request&,
                                      gazebo_msgs::GetWorldProperties::Response& res) {
  res.sim_time = sim_.physics().time();
  res.model_names = sim_.physics().modelNames();
  res.rendering_enabled = false;
  res.success = true;
  res.status_message = "GetWorldProperties: got properties";
  return true;
}

bool GazeboRosApi::getPhysicsProperties(gazebo_msgs::GetPhysicsProperties::Request&,
                                        gazebo_msgs::GetPhysicsProperties::Response& res) {
  const PhysicsSettings& s = sim_.physics().settings();
  res.time_step = s.max_step_size;
  res.pause = sim_.paused();
  res.max_update_rate = s.real_time_update_rate;
  res.gravity = toVector3Msg(s.gravity);
  // Bullet's sequential-impulse solver stands in for ODE's quick step; report its settings.
  const btContactSolverInfo& info = sim_.physics().bulletWorld().getSolverInfo();
  res.ode_config.auto_disable_bodies = false;
  res.ode_config.sor_pgs_precon_iters = 0;
  res.ode_config.sor_pgs_iters = s.solver_iterations;
  res.ode_config.sor_pgs_w = info.m_sor;
  res.ode_config.sor_pgs_rms_error_tol = s.solver_tolerance;  // m/s a sweep must change (contact_solver.h)
  res.ode_config.contact_surface_layer = s.contact_surface_layer;
  res.ode_config.contact_max_correcting_vel = s.contact_max_correcting_vel;
  res.ode_config.cfm = info.m_globalCfm;
  res.ode_config.erp = info.m_erp;
  res.ode_config.max_contacts = 20;
  res.success = true;
  res.status_message = "GetPhysicsProperties: got properties";
  return true;
}

bool GazeboRosApi::setPhysicsProperties(gazebo_msgs::SetPhysicsProperties::Request& req,
                                        gazebo_msgs::SetPhysicsProperties::Response& res) {
  PhysicsSettings s = sim_.physics().settings();
  s.max_step_size = req.time_step;
  s.real_time_update_rate = req.max_update_rate;
  s.gravity = toEigen(req.gravity);
  // 0 leaves these as they are, so that a request built from zeros only sets what it names.
  if (req.ode_config.sor_pgs_iters > 0) s.solver_iterations = static_cast<int>(req.ode_config.sor_pgs_iters);
  if (req.ode_config.sor_pgs_rms_error_tol > 0) s.solver_tolerance = req.ode_config.sor_pgs_rms_error_tol;
  if (req.ode_config.contact_surface_layer > 0) s.contact_surface_layer = req.ode_config.contact_surface_layer;
  if (req.ode_config.contact_max_correcting_vel > 0)
    s.contact_max_correcting_vel = req.ode_config.contact_max_correcting_vel;
  try {
    sim_.physics().setSettings(s);
  } catch (const DescriptionError& e) {
    res.success = false;
    res.status_message = std::string("SetPhysicsProperties: ") + e.what();
    return true;
  }
  sim_.setPaused(sim_.paused());  // restart real-time tracking at the new rate
  reconfigure_.publishUpdate();
  res.success = true;
  res.status_message = "SetPhysicsProperties: physics properties set";
  return true;
}

bool GazeboRosApi::pausePhysics(std_srvs::Empty::Request&, std_srvs::Empty::Response&) {
  sim_.setPaused(true);
  return true;
}
bool GazeboRosApi::unpausePhysics(std_srvs::Empty::Request&, std_srvs::Empty::Response&) {
  sim_.setPaused(false);
  return true;
}
// Called between steps (the loop runs callbacks there), so the steps run here, now, and the
// caller's reply carries the time after them.
bool GazeboRosApi::stepWorld(bullet_sim_msgs::StepWorld::Request& req, bullet_sim_msgs::StepWorld::Response& res) {
  sim_.setPaused(true);
  sim_.runSteps(static_cast<int>(std::min<uint32_t>(req.steps, std::numeric_limits<int>::max())));
  res.sim_time = sim_.now().toSec();
  res.success = true;
  res.status_message = "StepWorld: " + std::to_string(req.steps) + " step(s) run, paused";
  return true;
}
bool GazeboRosApi::resetSimulation(std_srvs::Empty::Request&, std_srvs::Empty::Response&) {
  joint_efforts_.clear();
  wrenches_.clear();
  sim_.resetSimulation();
  return true;
}
bool GazeboRosApi::resetWorld(std_srvs::Empty::Request&, std_srvs::Empty::Response&) {
  joint_efforts_.clear();
  wrenches_.clear();
  sim_.resetWorld();
  return true;
}

// --- forces -----------------------------------------------------------------------------------

bool GazeboRosApi::applyJointEffort(gazebo_msgs::ApplyJointEffort::Request& req,
                                    gazebo_msgs::ApplyJointEffort::Response& res) {
  res.success = false;
  if (!std::isfinite(req.effort)) {
    res.status_message = "ApplyJointEffort: effort: expected a finite number";
    return true;
  }
  auto [scope, joint_name] = splitScoped(req.joint_name);
  for (const std::string& name : sim_.physics().modelNames()) {
    if (!joint_name.empty() && name != scope) continue;
    const std::string joint = joint_name.empty() ? scope : joint_name;
    if (sim_.physics().findModel(name)->jointIndex(joint) < 0) continue;
    TimedJointEffort e{name, joint, req.effort, req.start_time, ros::Time()};
    if (e.start < sim_.now()) e.start = sim_.now();
    if (req.duration >= ros::Duration(0)) e.end = e.start + req.duration;
    joint_efforts_.push_back(e);
    res.success = true;
    res.status_message = "ApplyJointEffort: effort set";
    return true;
  }
  res.status_message = "ApplyJointEffort: joint [" + req.joint_name + "] not found";
  return true;
}

bool GazeboRosApi::applyBodyWrench(gazebo_msgs::ApplyBodyWrench::Request& req,
                                   gazebo_msgs::ApplyBodyWrench::Response& res) {
  res.success = false;
  const auto [model_name, link] = splitScoped(req.body_name);
  Eigen::Isometry3d body_pose, reference;
  if (link.empty() || !entityPose(req.body_name, body_pose)) {
    res.status_message = "ApplyBodyWrench: body [" + req.body_name + "] does not exist (expected 'model::link')";
    return true;
  }
  if (!entityPose(req.reference_frame, reference)) {
    res.status_message = "ApplyBodyWrench: reference_frame [" + req.reference_frame + "] does not exist";
    return true;
  }
  const Eigen::Vector3d point = toEigen(req.reference_point);
  if (!isFinite(req.wrench.force) || !isFinite(req.wrench.torque) || !point.allFinite()) {
    res.status_message = "ApplyBodyWrench: wrench and reference_point: expected finite numbers";
    return true;
  }
  TimedWrench w{model_name, link, reference.linear() * toEigen(req.wrench.force),
                reference.linear() * toEigen(req.wrench.torque), body_pose.inverse() * (reference * point),
                req.start_time, ros::Time()};
  if (w.start < sim_.now()) w.start = sim_.now();
  if (req.duration >= ros::Duration(0)) w.end = w.start + req.duration;
  wrenches_.push_back(w);
  res.success = true;
  res.status_message = "ApplyBodyWrench: wrench set";
  return true;
}

bool GazeboRosApi::clearJointForces(gazebo_msgs::JointRequest::Request& req, gazebo_msgs::JointRequest::Response&) {
  auto [scope, joint] = splitScoped(req.joint_name);
  joint_efforts_.erase(std::remove_if(joint_efforts_.begin(), joint_efforts_.end(),
                                      [&](const TimedJointEffort& e) {
                                        return joint.empty() ? e.joint == scope : (e.model == scope && e.joint == joint);
                                      }),
                       joint_efforts_.end());
  return true;
}

bool GazeboRosApi::clearBodyWrenches(gazebo_msgs::BodyRequest::Request& req, gazebo_msgs::BodyRequest::Response&) {
  auto [model, link] = splitScoped(req.body_name);
  wrenches_.erase(std::remove_if(wrenches_.begin(), wrenches_.end(),
                                 [&](const TimedWrench& w) { return w.model == model && (link.empty() || w.link == link); }),
                  wrenches_.end());
  return true;
}

bool GazeboRosApi::setModelConfiguration(gazebo_msgs::SetModelConfiguration::Request& req,
                                         gazebo_msgs::SetModelConfiguration::Response& res) {
  res.success = false;
  PhysicsModel* model = sim_.physics().findModel(req.model_name);
  if (!model) {
    res.status_message = "SetModelConfiguration: model [" + req.model_name + "] does not exist";
    return true;
  }
  if (req.joint_names.size() != req.joint_positions.size()) {
    res.status_message = "SetModelConfiguration: joint_names and joint_positions: expected the same length, got " +
                         std::to_string(req.joint_names.size()) + " and " + std::to_string(req.joint_positions.size());
    return true;
  }
  std::vector<int> indices;
  for (size_t i = 0; i < req.joint_names.size(); ++i) {
    const int j = model->jointIndex(req.joint_names[i]);
    if (j < 0) {
      res.status_message = "SetModelConfiguration: joint [" + req.joint_names[i] + "] is not a moving joint of model [" +
                           req.model_name + "]";
      return true;
    }
    if (!std::isfinite(req.joint_positions[i])) {
      res.status_message = "SetModelConfiguration: joint_positions[" + std::to_string(i) + "]: expected a finite number";
      return true;
    }
    indices.push_back(j);
  }
  for (size_t i = 0; i < indices.size(); ++i) model->setJointState(indices[i], req.joint_positions[i], 0.0);
  res.success = true;
  res.status_message = "SetModelConfiguration: success";
  return true;
}

// --- topics -----------------------------------------------------------------------------------

void GazeboRosApi::afterStep(const ros::Time&) { publishStates(false); }

void GazeboRosApi::publishStates(bool force) {
  const bool models = model_states_pub_.hasSubscribers();
  const bool links = link_states_pub_.hasSubscribers();
  if (!models && !links) return;
  // Gazebo publishes every step; far beyond real time that would only flood subscribers.
  const ros::WallTime wall = ros::WallTime::now();
  if (!force && wall - last_states_wall_ < ros::WallDuration(0.001)) return;
  last_states_wall_ = wall;
  if (models) {
    gazebo_msgs::ModelStates model_states;
    for (const std::string& name : sim_.physics().modelNames()) {
      const PhysicsModel* model = sim_.physics().findModel(name);
      model_states.name.push_back(name);
      model_states.pose.push_back(toPoseMsg(model->pose()));
      model_states.twist.push_back(toTwistMsg(model->twist()));
    }
    model_states_pub_.publish(std::move(model_states));
  }
  if (links) link_states_pub_.publish(linkStates(sim_.physics()));  // what /gazebo/pose_info carries too
}

}  // namespace bullet_sim
