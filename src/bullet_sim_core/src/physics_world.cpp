#include "bullet_sim_core/physics_world.h"

#include <algorithm>
#include <cmath>

#include <BulletDynamics/Featherstone/btMultiBodyFixedConstraint.h>

#include "bullet_sim_core/description_error.h"
#include "bullet_sim_core/contact_solver.h"

namespace bullet_sim {
namespace {
// Gazebo's ODE takes the smaller of two surfaces' friction coefficients; Bullet would
// multiply them, which makes Gazebo's ground_plane (mu 100) absurdly grippy.
btScalar minimumFriction(const btCollisionObject* a, const btCollisionObject* b) {
  return std::min(a->getFriction(), b->getFriction());
}

// Bullet predicts every link's pose at the end of the step for continuous collision detection,
// which the simulator does not use (multibody links are not swept): a pass of forward kinematics
// per step for nothing.
class DiscreteMultiBodyWorld : public btMultiBodyDynamicsWorld {
 public:
  using btMultiBodyDynamicsWorld::btMultiBodyDynamicsWorld;
  void predictUnconstraintMotion(btScalar time_step) override {
    btDiscreteDynamicsWorld::predictUnconstraintMotion(time_step);
  }
};

}  // namespace

PhysicsWorld::PhysicsWorld(const PhysicsSettings& settings)
    : collision_config_(std::make_unique<btDefaultCollisionConfiguration>()),
      cylinder_plane_(makeCylinderPlaneAlgorithm(false)),
      plane_cylinder_(makeCylinderPlaneAlgorithm(true)),
      dispatcher_(std::make_unique<btCollisionDispatcher>(collision_config_.get())),
      broadphase_(std::make_unique<btDbvtBroadphase>()),
      solver_(std::make_unique<ContactSolver>()),
      world_(std::make_unique<DiscreteMultiBodyWorld>(dispatcher_.get(), broadphase_.get(), solver_.get(),
                                                         collision_config_.get())) {
  gCalculateCombinedFrictionCallback = &minimumFriction;
  dispatcher_->registerCollisionCreateFunc(CYLINDER_SHAPE_PROXYTYPE, STATIC_PLANE_PROXYTYPE, cylinder_plane_.get());
  dispatcher_->registerCollisionCreateFunc(STATIC_PLANE_PROXYTYPE, CYLINDER_SHAPE_PROXYTYPE, plane_cylinder_.get());
  cylinder_cylinder_ = makeCylinderCylinderAlgorithm(
      collision_config_->getCollisionAlgorithmCreateFunc(CYLINDER_SHAPE_PROXYTYPE, CYLINDER_SHAPE_PROXYTYPE));
  dispatcher_->registerCollisionCreateFunc(CYLINDER_SHAPE_PROXYTYPE, CYLINDER_SHAPE_PROXYTYPE,
                                           cylinder_cylinder_.get());
  setSettings(settings);
}

PhysicsWorld::~PhysicsWorld() {
  while (!attachments_.empty()) detach(attachments_.back().id);
  models_.clear();
}

void PhysicsWorld::setSettings(const PhysicsSettings& s) {
  if (!std::isfinite(s.max_step_size) || s.max_step_size <= 0 || s.max_step_size > 0.1)
    throw DescriptionError("physics: max_step_size: expected a step in (0, 0.1] s, got " + std::to_string(s.max_step_size));
  if (!std::isfinite(s.real_time_factor) || s.real_time_factor < 0)
    throw DescriptionError("physics: real_time_factor: expected a number >= 0 (0 runs as fast as possible), got " +
                           std::to_string(s.real_time_factor));
  if (!std::isfinite(s.real_time_update_rate) || s.real_time_update_rate < 0)
    throw DescriptionError("physics: real_time_update_rate: expected a rate >= 0 Hz, got " +
                           std::to_string(s.real_time_update_rate));
  if (!s.gravity.allFinite()) throw DescriptionError("physics: gravity: expected three finite numbers");
  if (s.solver_iterations < 1)
    throw DescriptionError("physics: solver iters: expected at least 1, got " + std::to_string(s.solver_iterations));
  if (!std::isfinite(s.solver_tolerance) || s.solver_tolerance < 0)
    throw DescriptionError("physics: solver tolerance: expected a velocity >= 0 m/s, got " +
                           std::to_string(s.solver_tolerance));
  if (!std::isfinite(s.contact_max_correcting_vel) || s.contact_max_correcting_vel < 0)
    throw DescriptionError("physics: contact_max_correcting_vel: expected a velocity >= 0 m/s, got " +
                           std::to_string(s.contact_max_correcting_vel));
  if (!std::isfinite(s.contact_surface_layer) || s.contact_surface_layer < 0)
    throw DescriptionError("physics: contact_surface_layer: expected a depth >= 0 m, got " +
                           std::to_string(s.contact_surface_layer));
  settings_ = s;
  world_->setGravity(toBullet(s.gravity));
  solver_->setContactCorrection(s.contact_max_correcting_vel, s.contact_surface_layer);
  world_->getSolverInfo().m_numIterations = s.solver_iterations;
  // Bullet's residual is the largest squared change of a row's velocity in a sweep.
  world_->getSolverInfo().m_leastSquaresResidualThreshold = s.solver_tolerance * s.solver_tolerance;
}

PhysicsModel& PhysicsWorld::addModel(const ModelDescription& description, const Eigen::Isometry3d& pose) {
  if (description.name.empty()) throw DescriptionError(description.source + ": the model has no name");
  if (findModel(description.name))
    throw DescriptionError(description.source + ": a model named '" + description.name +
                           "' already exists; model names must be unique");
  if (!pose.matrix().allFinite())
    throw DescriptionError(description.source + ": initial pose of '" + description.name + "': expected finite numbers");
  warnings_.clear();
  models_.push_back(std::make_unique<PhysicsModel>(description, pose, *world_, settings_.max_step_size, warnings_));
  return *models_.back();
}

bool PhysicsWorld::removeModel(const std::string& name) {
  auto it = std::find_if(models_.begin(), models_.end(), [&](const auto& m) { return m->name() == name; });
  if (it == models_.end()) return false;
  std::vector<int> joined;
  for (const auto& a : attachments_)
    if (a.model_a == name || a.model_b == name) joined.push_back(a.id);
  for (int id : joined) detach(id);
  models_.erase(std::find_if(models_.begin(), models_.end(), [&](const auto& m) { return m->name() == name; }));
  return true;
}

int PhysicsWorld::attach(const std::string& model_a, const std::string& link_a, const std::string& model_b,
                         const std::string& link_b) {
  const auto body = [&](const std::string& model, const std::string& link) {
    const PhysicsModel* m = findModel(model);
    if (!m) throw DescriptionError("attach: no model named '" + model + "'");
    if (!m->hasLink(link)) throw DescriptionError("attach: model '" + model + "' has no link '" + link + "'");
    const PhysicsModel::BodyOfLink b = m->bodyOfLink(link);
    if (!b.multibody) throw DescriptionError("attach: model '" + model + "' is static; nothing to hold");
    return b;
  };
  const PhysicsModel::BodyOfLink a = body(model_a, link_a), b = body(model_b, link_b);
  if (a.multibody == b.multibody && a.body == b.body)
    throw DescriptionError("attach: '" + link_a + "' and '" + link_b + "' already move as one body");
  // The constraint holds b's COM frame where it is now in a's COM frame.
  const Eigen::Isometry3d b_in_a = a.com.inverse() * b.com;
  const Eigen::Matrix3d frame_in_a = b_in_a.linear();
  btMatrix3x3 frame(frame_in_a(0, 0), frame_in_a(0, 1), frame_in_a(0, 2), frame_in_a(1, 0), frame_in_a(1, 1),
                    frame_in_a(1, 2), frame_in_a(2, 0), frame_in_a(2, 1), frame_in_a(2, 2));
  const Eigen::Vector3d pivot = b_in_a.translation();
  auto constraint = std::make_unique<btMultiBodyFixedConstraint>(
      a.multibody, a.body, b.multibody, b.body, btVector3(pivot.x(), pivot.y(), pivot.z()), btVector3(0, 0, 0), frame,
      btMatrix3x3::getIdentity());
  world_->addMultiBodyConstraint(constraint.get());
  attachments_.push_back({next_attachment_id_, model_a, model_b, std::move(constraint)});
  return next_attachment_id_++;
}

bool PhysicsWorld::detach(int id) {
  auto it = std::find_if(attachments_.begin(), attachments_.end(), [&](const auto& a) { return a.id == id; });
  if (it == attachments_.end()) return false;
  world_->removeMultiBodyConstraint(it->constraint.get());
  attachments_.erase(it);
  return true;
}

PhysicsModel* PhysicsWorld::findModel(const std::string& name) {
  for (auto& m : models_)
    if (m->name() == name) return m.get();
  return nullptr;
}

const PhysicsModel* PhysicsWorld::findModel(const std::string& name) const {
  for (const auto& m : models_)
    if (m->name() == name) return m.get();
  return nullptr;
}

std::vector<std::string> PhysicsWorld::modelNames() const {
  std::vector<std::string> names;
  for (const auto& m : models_) names.push_back(m->name());
  return names;
}

void PhysicsWorld::step() {
  for (auto& m : models_) m->beforeStep();
  // maxSubSteps 0: exactly one step of the given size, no interpolation.
  world_->stepSimulation(settings_.max_step_size, 0, settings_.max_step_size);
  for (auto& m : models_) m->afterStep();
  time_ += settings_.max_step_size;
}

void PhysicsWorld::resetModels() {
  for (auto& m : models_) m->resetToInitial();
}

}  // namespace bullet_sim
