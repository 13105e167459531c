#include "bullet_sim_core/physics_world.h"

#include <algorithm>
#include <cmath>

#include <BulletCollision/CollisionDispatch/btManifoldResult.h>

#include "bullet_sim_core/description_error.h"

namespace bullet_sim {
namespace {
// Gazebo's ODE takes the smaller of two surfaces' friction coefficients; Bullet would
// multiply them, which makes Gazebo's ground_plane (mu 100) absurdly grippy.
btScalar minimumFriction(const btCollisionObject* a, const btCollisionObject* b) {
  return std::min(a->getFriction(), b->getFriction());
}
}  // namespace

PhysicsWorld::PhysicsWorld(const PhysicsSettings& settings)
    : collision_config_(std::make_unique<btDefaultCollisionConfiguration>()),
      dispatcher_(std::make_unique<btCollisionDispatcher>(collision_config_.get())),
      broadphase_(std::make_unique<btDbvtBroadphase>()),
      solver_(std::make_unique<btMultiBodyConstraintSolver>()),
      world_(std::make_unique<btMultiBodyDynamicsWorld>(dispatcher_.get(), broadphase_.get(), solver_.get(),
                                                         collision_config_.get())) {
  gCalculateCombinedFrictionCallback = &minimumFriction;
  setSettings(settings);
}

PhysicsWorld::~PhysicsWorld() { models_.clear(); }

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
  settings_ = s;
  world_->setGravity(toBullet(s.gravity));
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
  models_.erase(it);
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
  world_->forwardKinematics();  // refresh every link's cached world transform
  for (auto& m : models_) m->afterStep();
  time_ += settings_.max_step_size;
}

void PhysicsWorld::resetModels() {
  for (auto& m : models_) m->resetToInitial();
}

}  // namespace bullet_sim
