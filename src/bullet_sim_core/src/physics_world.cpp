#include "bullet_sim_core/physics_world.h"

#include <algorithm>
#include <cmath>

#include <BulletCollision/CollisionDispatch/btManifoldResult.h>
#include <BulletDynamics/Featherstone/btMultiBodyFixedConstraint.h>
#include <BulletDynamics/Featherstone/btMultiBodyLinkCollider.h>

#include "bullet_sim_core/description_error.h"

namespace bullet_sim {
namespace {
// Gazebo's ODE takes the smaller of two surfaces' friction coefficients; Bullet would
// multiply them, which makes Gazebo's ground_plane (mu 100) absurdly grippy.
btScalar minimumFriction(const btCollisionObject* a, const btCollisionObject* b) {
  return std::min(a->getFriction(), b->getFriction());
}

// Isotropic Coulomb friction for btMultiBody contacts.
//
// btMultiBodyConstraintSolver gives every contact two friction rows along fixed directions
// that depend only on the contact normal (btPlaneSpace1: world y and x on a flat floor; the
// velocity-dependent direction of Bullet's rigid-body solver is commented out there, and
// cached directions are overwritten), then scales the pair of impulses back onto the friction
// cone. Each row's impulse is the one that would stop the slip along it, i.e. weighted by that
// row's effective mass, so the clamped force only opposes the slip when both rows are alike.
// At a wheel they are not: along the wheel the contact is light (the wheel spins), across it
// heavy (the vehicle has to move). With the rows along a wheel's axes (a vehicle heading 0 or
// 90 degrees) nearly all of the friction goes sideways: spawned heading 0, m_robot, the RE510
// vehicle and skid4 turned on the spot at 35, 17 and 14 % of the rate Coulomb friction gives
// (which they reach at 45 degrees), and the rate rose and fell with the heading every 90
// degrees. PyBullet, on the same solver, does the same (scripts/bench_skid_steer.py).
//
// After Bullet has set up the contacts, every contact that slides faster than kSlipSpeed gets
// its two friction rows rebuilt along the slip and across it (by Bullet's own row set-up), so
// the clamped force opposes the slip whatever the heading. Contacts that stick keep Bullet's
// rows: below the cone's limit any two directions hold the same.
class IsotropicFrictionSolver : public btMultiBodyConstraintSolver {
 public:
  static constexpr btScalar kSlipSpeed = 1e-4;  // m/s

 protected:
  void convertContacts(btPersistentManifold** manifolds, int count, const btContactSolverInfo& info) override {
    btMultiBodyConstraintSolver::convertContacts(manifolds, count, info);
    // Bullet lays out two friction rows per contact, in the contacts' order.
    if (!(info.m_solverMode & SOLVER_USE_2_FRICTION_DIRECTIONS) ||
        m_multiBodyFrictionContactConstraints.size() != 2 * m_multiBodyNormalContactConstraints.size())
      return;
    int contact = 0;
    for (int m = 0; m < count; ++m) {
      btPersistentManifold* manifold = manifolds[m];
      if (!btMultiBodyLinkCollider::upcast(manifold->getBody0()) &&
          !btMultiBodyLinkCollider::upcast(manifold->getBody1()))
        continue;  // a rigid-body pair: Bullet's rigid-body solver already follows the slip
      for (int k = 0; k < manifold->getNumContacts(); ++k) {
        btManifoldPoint& point = manifold->getContactPoint(k);
        if (!(point.getDistance() <= manifold->getContactProcessingThreshold())) continue;
        if (contact >= m_multiBodyNormalContactConstraints.size()) return;
        const btMultiBodySolverConstraint& normal = m_multiBodyNormalContactConstraints[contact++];
        if (normal.m_originalContactPoint != &point) return;  // not Bullet's layout: leave its rows
        alongSlip(manifold, point, contact - 1, normal.m_frictionIndex, info);
      }
    }
  }

 private:
  // Relative velocity (A minus B) along a row's direction, as the solver computes it.
  btScalar rowVelocity(const btMultiBodySolverConstraint& row) const {
    btScalar v = 0;
    if (row.m_multiBodyA) {
      const btScalar* jacobian = &m_data.m_jacobians[row.m_jacAindex];
      const btScalar* velocity = row.m_multiBodyA->getVelocityVector();
      for (int i = 0; i < row.m_multiBodyA->getNumDofs() + 6; ++i) v += jacobian[i] * velocity[i];
    } else if (row.m_solverBodyIdA >= 0) {
      if (const btRigidBody* body = m_tmpSolverBodyPool[row.m_solverBodyIdA].m_originalBody)
        v += row.m_contactNormal1.dot(body->getLinearVelocity()) +
             row.m_relpos1CrossNormal.dot(body->getAngularVelocity());
    }
    if (row.m_multiBodyB) {
      const btScalar* jacobian = &m_data.m_jacobians[row.m_jacBindex];
      const btScalar* velocity = row.m_multiBodyB->getVelocityVector();
      for (int i = 0; i < row.m_multiBodyB->getNumDofs() + 6; ++i) v += jacobian[i] * velocity[i];
    } else if (row.m_solverBodyIdB >= 0) {
      if (const btRigidBody* body = m_tmpSolverBodyPool[row.m_solverBodyIdB].m_originalBody)
        v += row.m_contactNormal2.dot(body->getLinearVelocity()) +
             row.m_relpos2CrossNormal.dot(body->getAngularVelocity());
    }
    return v;
  }

  void alongSlip(btPersistentManifold* manifold, btManifoldPoint& point, int contact, int first_row,
                 const btContactSolverInfo& info) {
    const btMultiBodySolverConstraint& row1 = m_multiBodyFrictionContactConstraints[first_row];
    const btMultiBodySolverConstraint& row2 = m_multiBodyFrictionContactConstraints[first_row + 1];
    const btVector3 slip = rowVelocity(row1) * row1.m_contactNormal1 + rowVelocity(row2) * row2.m_contactNormal1;
    const btScalar speed = slip.length();
    if (!(speed > kSlipSpeed)) return;
    point.m_lateralFrictionDir1 = slip / speed;
    point.m_lateralFrictionDir2 = point.m_lateralFrictionDir1.cross(point.m_normalWorldOnB);
    auto* body0 = const_cast<btCollisionObject*>(manifold->getBody0());
    auto* body1 = const_cast<btCollisionObject*>(manifold->getBody1());
    for (int r = 0; r < 2; ++r) {
      // Appended by Bullet's set-up, then moved into the old row's place.
      const btMultiBodySolverConstraint& row =
          addMultiBodyFrictionConstraint(r == 0 ? point.m_lateralFrictionDir1 : point.m_lateralFrictionDir2, 0,
                                         manifold, contact, point, body0, body1, info.m_sor, info);
      m_multiBodyFrictionContactConstraints[first_row + r] = row;
      m_multiBodyFrictionContactConstraints.pop_back();
    }
  }
};
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
      solver_(std::make_unique<IsotropicFrictionSolver>()),
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
  settings_ = s;
  world_->setGravity(toBullet(s.gravity));
  world_->getSolverInfo().m_numIterations = s.solver_iterations;
  // Every sweep runs (Bullet's residual threshold stays 0): PyBullet's early stop at 1e-7 saves
  // a wheeled robot's step 30 % but lets held wheels creep again (25 um/s where 50 full sweeps
  // leave under 20, WheelsHeldStillHoldTheVehicleStill); 1e-9 stops no earlier than 50.
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
