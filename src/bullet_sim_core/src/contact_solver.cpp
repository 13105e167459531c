#include "bullet_sim_core/contact_solver.h"

#include <algorithm>

#include <BulletCollision/NarrowPhaseCollision/btPersistentManifold.h>
#include <BulletDynamics/Featherstone/btMultiBodyConstraint.h>
#include <BulletDynamics/Featherstone/btMultiBodyLinkCollider.h>

namespace bullet_sim {
namespace {
// Below this slip speed a contact sticks and keeps Bullet's friction rows (see convertContacts).
constexpr btScalar kSlipSpeed = 1e-4;  // m/s
// The position-only pass stops once a sweep changes no contact's separating speed by more than this:
// a micrometre per second, a thousandth of a millisecond's 1 nm (see pushApart).
constexpr btScalar kPushTolerance = 1e-6;  // m/s
// The overlap the position-only pass leaves beyond min_depth. Pushed to 0, a resting contact's points
// are touching in one step and apart in the next, and a can standing on another crept 0.25 mm in
// 30 s (test_physics_world's CanTower); 2 to 5 um keep them touching (0.01-0.13 mm, as before the
// pass). Too little to see: a box rests 3 um lower than its size says.
constexpr btScalar kPushSlop = 3e-6;  // m
}  // namespace

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
// Every contact that slides faster than kSlipSpeed gets its two friction rows along the slip
// and across it, so the clamped force opposes the slip whatever the heading. Contacts that stick
// keep Bullet's directions: below the cone's limit any two directions hold the same. The rows are
// set up once, here, in place of Bullet's convertMultiBodyContact (which picks btPlaneSpace1's
// directions without a way to choose others); setting up a row (its response, M^-1 J^T) is most of
// a wheeled robot's step, and rebuilding two rows per sliding contact after Bullet's cost it 8 %.
void ContactSolver::convertContacts(btPersistentManifold** manifolds, int count, const btContactSolverInfo& info) {
  lone_contact_.clear();
  corrections_.clear();
  const bool two_directions = info.m_solverMode & SOLVER_USE_2_FRICTION_DIRECTIONS;
  for (int m = 0; m < count; ++m) {
    btPersistentManifold* manifold = manifolds[m];
    if (!btMultiBodyLinkCollider::upcast(manifold->getBody0()) && !btMultiBodyLinkCollider::upcast(manifold->getBody1())) {
      convertContact(manifold, info);  // a rigid-body pair: Bullet's rigid-body solver follows the slip and warm starts
      continue;
    }
    const int first = m_multiBodyNormalContactConstraints.size();
    if (two_directions && slipFrictionApplies(manifold))
      convertManifold(manifold, info);
    else
      convertMultiBodyContact(manifold, info);
    const int made = m_multiBodyNormalContactConstraints.size() - first;
    lone_contact_.resize(m_multiBodyNormalContactConstraints.size(), false);
    // Warm started: a contact that is its manifold's one point (both conversions give it two friction rows).
    if (made == 1 && two_directions) lone_contact_[first] = true;
    // A velocity target without Bullet's push out of the overlap, which pushApart makes instead.
    for (int c = first; c < m_multiBodyNormalContactConstraints.size(); ++c) {
      btMultiBodySolverConstraint& normal = m_multiBodyNormalContactConstraints[c];
      const auto& point = *static_cast<const btManifoldPoint*>(normal.m_originalContactPoint);
      const btScalar gap = std::max<btScalar>(point.getDistance(), 0);  // may close within the step
      normal.m_rhs = -(normalVelocity(normal) + gap / info.m_timeStep) * normal.m_jacDiagABInv;
      corrections_.push_back(correctionOf(manifold, point));
    }
  }
  // Joint motors, limits and attachments: Bullet's rows.
  for (int i = 0; i < m_tmpNumMultiBodyConstraints; ++i) {
    m_data.m_solverBodyPool = &m_tmpSolverBodyPool;
    m_data.m_fixedBodyId = m_fixedBodyId;
    m_tmpMultiBodyConstraints[i]->createConstraintRows(m_multiBodyNonContactConstraints, m_data, info);
  }
  for (int r = 0; r < m_multiBodyNonContactConstraints.size(); ++r) m_multiBodyNonContactConstraints[r].m_appliedImpulse = 0;
  if (warm_start_) warmStart();
}

// Whether the manifold's contacts use only what convertManifold sets up: no rolling or spinning
// friction and no anisotropic friction (none of our models has them; Bullet's conversion, with
// its fixed directions, handles those).
bool ContactSolver::slipFrictionApplies(const btPersistentManifold* manifold) {
  const btCollisionObject* bodies[] = {manifold->getBody0(), manifold->getBody1()};
  for (const btCollisionObject* body : bodies)
    if (body->hasAnisotropicFriction(btCollisionObject::CF_ANISOTROPIC_FRICTION |
                                     btCollisionObject::CF_ANISOTROPIC_ROLLING_FRICTION))
      return false;
  for (int k = 0; k < manifold->getNumContacts(); ++k) {
    const btManifoldPoint& point = manifold->getContactPoint(k);
    if (point.m_combinedRollingFriction > 0 || point.m_combinedSpinningFriction > 0) return false;
  }
  return true;
}

// Bullet's conversion of a multibody manifold (a normal row per touching point and two friction
// rows) with the friction directions chosen first.
void ContactSolver::convertManifold(btPersistentManifold* manifold, const btContactSolverInfo& info) {
  auto* body0 = const_cast<btCollisionObject*>(manifold->getBody0());
  auto* body1 = const_cast<btCollisionObject*>(manifold->getBody1());
  const btMultiBodyLinkCollider* collider0 = btMultiBodyLinkCollider::upcast(body0);
  const btMultiBodyLinkCollider* collider1 = btMultiBodyLinkCollider::upcast(body1);
  btMultiBody* multibody0 = collider0 ? collider0->m_multiBody : nullptr;
  btMultiBody* multibody1 = collider1 ? collider1->m_multiBody : nullptr;
  const int solver_body0 = multibody0 ? -1 : getOrInitSolverBody(*body0, info.m_timeStep);
  const int solver_body1 = multibody1 ? -1 : getOrInitSolverBody(*body1, info.m_timeStep);
  for (int k = 0; k < manifold->getNumContacts(); ++k) {
    btManifoldPoint& point = manifold->getContactPoint(k);
    if (!(point.getDistance() <= manifold->getContactProcessingThreshold())) {
      point.m_appliedImpulse = 0;  // as Bullet: a point out of touch has nothing to start from
      point.m_prevRHS = 0;
      continue;
    }
    const int contact = m_multiBodyNormalContactConstraints.size();
    btMultiBodySolverConstraint& normal = m_multiBodyNormalContactConstraints.expandNonInitializing();
    normal.m_orgConstraint = nullptr;
    normal.m_orgDofIndex = -1;
    normal.m_solverBodyIdA = solver_body0;
    normal.m_solverBodyIdB = solver_body1;
    normal.m_multiBodyA = multibody0;
    if (multibody0) normal.m_linkA = collider0->m_link;
    normal.m_multiBodyB = multibody1;
    if (multibody1) normal.m_linkB = collider1->m_link;
    normal.m_originalContactPoint = &point;
    btScalar relaxation;
    setupMultiBodyContactConstraint(normal, point.m_normalWorldOnB, point.m_appliedImpulse, point, info, relaxation, false);
    normal.m_frictionIndex = m_multiBodyFrictionContactConstraints.size();

    btPlaneSpace1(point.m_normalWorldOnB, point.m_lateralFrictionDir1, point.m_lateralFrictionDir2);
    const btVector3 slip = velocityAlong(point.m_lateralFrictionDir1, point, body0, body1) * point.m_lateralFrictionDir1 +
                           velocityAlong(point.m_lateralFrictionDir2, point, body0, body1) * point.m_lateralFrictionDir2;
    const btScalar speed = slip.length();
    if (speed > kSlipSpeed) {
      point.m_lateralFrictionDir1 = slip / speed;
      point.m_lateralFrictionDir2 = point.m_lateralFrictionDir1.cross(point.m_normalWorldOnB);
    }
    addMultiBodyFrictionConstraint(point.m_lateralFrictionDir1, point.m_appliedImpulseLateral1, manifold, contact, point,
                                   body0, body1, relaxation, info);
    addMultiBodyFrictionConstraint(point.m_lateralFrictionDir2, point.m_appliedImpulseLateral2, manifold, contact, point,
                                   body0, body1, relaxation, info);
  }
}

// The velocity of body 0 relative to body 1 at the contact along `direction`, as a friction row
// along it measures it (its Jacobians times the bodies' velocities).
btScalar ContactSolver::velocityAlong(const btVector3& direction, const btManifoldPoint& point,
                                      const btCollisionObject* body0, const btCollisionObject* body1) {
  const auto along = [&](const btCollisionObject* body, const btVector3& where) -> btScalar {
    if (const btMultiBodyLinkCollider* collider = btMultiBodyLinkCollider::upcast(body)) {
      const btMultiBody* multibody = collider->m_multiBody;
      const int dofs = multibody->getNumDofs() + 6;
      jacobian_.resize(dofs);
      multibody->fillContactJacobianMultiDof(collider->m_link, where, direction, &jacobian_[0], m_data.scratch_r,
                                             m_data.scratch_v, m_data.scratch_m);
      const btScalar* velocity = multibody->getVelocityVector();
      btScalar v = 0;
      for (int i = 0; i < dofs; ++i) v += jacobian_[i] * velocity[i];
      return v;
    }
    if (const btRigidBody* rigid = btRigidBody::upcast(body))
      return rigid->getVelocityInLocalPoint(where - rigid->getCenterOfMassPosition()).dot(direction);
    return 0;  // a static object
  };
  return along(body0, point.getPositionWorldOnA()) - along(body1, point.getPositionWorldOnB());
}

// Warm starting.
//
// Projected Gauss-Seidel from zero needs its every sweep: a vehicle held still by its wheel
// motors crept 0.16 mm/s with Bullet's 10 sweeps a step and 10 um/s with 50, because the
// impulses that hold it build up from nothing each step. Between two 1 ms steps they barely
// change, so each row starts from the impulse it ended the last step with, as ODE's quickstep
// does, and the sweeps only correct it; the solver then stops as soon as a sweep changes no
// row's velocity by more than the world's tolerance (Bullet's m_leastSquaresResidualThreshold,
// the square of it), at most `iters` sweeps as before.
//
// Bullet keeps a contact's impulses in its manifold point across steps (btPersistentManifold
// carries them over when it matches the point again; a new point starts at 0): the normal one,
// and the two friction ones, which finish() stores along the fixed directions btPlaneSpace1
// gives for the normal, because the rows themselves turn with the slip. Joint motors, limits and
// attachments keep theirs in their btMultiBodyConstraint.
//
// Only a contact that is its manifold's one point starts warm: a wheel on the ground, a ball.
// Where two bodies touch at several points (a box's face, a can's end cap), the split of the
// load among them is not unique, and the manifold keeps four of the candidate points, choosing
// afresh each step, so a point's last impulse may have been carried by another feature: warm
// started, a can standing on its cap rocked at 2 mrad/s and a tower of cans crept 0.6 mm in
// 30 s (test_physics_world's StandingCylinderRestsOnItsEndCap and CanTower). Those start from
// zero, as before.
void ContactSolver::warmStart() {
  for (int c = 0; c < m_multiBodyNormalContactConstraints.size(); ++c) {
    if (!lone_contact_[c]) continue;
    btMultiBodySolverConstraint& normal = m_multiBodyNormalContactConstraints[c];
    const auto* point = static_cast<const btManifoldPoint*>(normal.m_originalContactPoint);
    const btScalar pushed = std::max<btScalar>(0, point->m_appliedImpulse);
    startRowAt(normal, pushed);
    if (pushed <= 0) continue;
    btVector3 e1, e2;
    btPlaneSpace1(point->m_normalWorldOnB, e1, e2);
    btVector3 friction = point->m_appliedImpulseLateral1 * e1 + point->m_appliedImpulseLateral2 * e2;
    btMultiBodySolverConstraint& row1 = m_multiBodyFrictionContactConstraints[normal.m_frictionIndex];
    btMultiBodySolverConstraint& row2 = m_multiBodyFrictionContactConstraints[normal.m_frictionIndex + 1];
    const btScalar limit = row1.m_friction * pushed, magnitude = friction.length();
    if (magnitude > limit) friction *= limit / magnitude;  // inside the cone it starts from
    startRowAt(row1, friction.dot(row1.m_contactNormal1));
    startRowAt(row2, friction.dot(row2.m_contactNormal1));
  }
  for (int r = 0; r < m_multiBodyNonContactConstraints.size(); ++r) {
    btMultiBodySolverConstraint& row = m_multiBodyNonContactConstraints[r];
    if (!row.m_orgConstraint || row.m_orgDofIndex < 0) continue;
    const btScalar last = row.m_orgConstraint->getAppliedImpulse(row.m_orgDofIndex);
    startRowAt(row, std::min(std::max(last, row.m_lowerLimit), row.m_upperLimit));
  }
}

// A row's impulse set to `impulse` from 0, and its effect added to the velocities the sweeps
// work on and to the bodies' velocities, as a sweep applies a change of impulse
// (resolveSingleConstraintRowGeneric; Bullet's DIRECTLY_UPDATE_VELOCITY_DURING_SOLVER_ITERATIONS).
void ContactSolver::startRowAt(btMultiBodySolverConstraint& row, btScalar impulse) {
  if (impulse == 0) return;
  row.m_appliedImpulse = impulse;
  const auto apply = [&](btMultiBody* multibody, int jacobian, int velocities, int solver_body, const btVector3& normal,
                         const btVector3& angular) {
    if (multibody) {
      btScalar* unit = &m_data.m_deltaVelocitiesUnitImpulse[jacobian];
      applyDeltaVee(unit, impulse, velocities, multibody->getNumDofs() + 6);
      multibody->applyDeltaVeeMultiDof2(unit, impulse);
    } else if (solver_body >= 0) {
      btSolverBody& body = m_tmpSolverBodyPool[solver_body];
      body.internalApplyImpulse(normal * body.internalGetInvMass(), angular, impulse);
    }
  };
  apply(row.m_multiBodyA, row.m_jacAindex, row.m_deltaVelAindex, row.m_solverBodyIdA, row.m_contactNormal1,
        row.m_angularComponentA);
  apply(row.m_multiBodyB, row.m_jacBindex, row.m_deltaVelBindex, row.m_solverBodyIdB, row.m_contactNormal2,
        row.m_angularComponentB);
}

// The early stop needs every row to start near its answer: with a contact that started from zero
// (several points in one manifold) in the solve, every sweep runs, as before. Stopped early, a
// box resting on the ground settled onto two of its corners.
btScalar ContactSolver::solveGroupCacheFriendlyIterations(btCollisionObject** bodies, int num_bodies,
                                                          btPersistentManifold** manifolds, int num_manifolds,
                                                          btTypedConstraint** constraints, int num_constraints,
                                                          const btContactSolverInfo& info, btIDebugDraw* debug) {
  const bool all_warm = warm_start_ && std::find(lone_contact_.begin(), lone_contact_.end(), false) == lone_contact_.end();
  if (all_warm || info.m_leastSquaresResidualThreshold <= 0)
    return btMultiBodyConstraintSolver::solveGroupCacheFriendlyIterations(bodies, num_bodies, manifolds, num_manifolds,
                                                                          constraints, num_constraints, info, debug);
  btContactSolverInfo every_sweep = info;
  every_sweep.m_leastSquaresResidualThreshold = 0;
  return btMultiBodyConstraintSolver::solveGroupCacheFriendlyIterations(bodies, num_bodies, manifolds, num_manifolds,
                                                                        constraints, num_constraints, every_sweep, debug);
}

btScalar ContactSolver::solveSingleIteration(int iteration, btCollisionObject** bodies, int num_bodies,
                                             btPersistentManifold** manifolds, int num_manifolds,
                                             btTypedConstraint** constraints, int num_constraints,
                                             const btContactSolverInfo& info, btIDebugDraw* debug) {
  ++sweeps_;
  return btMultiBodyConstraintSolver::solveSingleIteration(iteration, bodies, num_bodies, manifolds, num_manifolds,
                                                           constraints, num_constraints, info, debug);
}

btScalar ContactSolver::solveGroupCacheFriendlyFinish(btCollisionObject** bodies, int num_bodies,
                                                      const btContactSolverInfo& info) {
  ++solves_;
  const btScalar result = btMultiBodyConstraintSolver::solveGroupCacheFriendlyFinish(bodies, num_bodies, info);
  pushApart(info);
  // Each contact's friction impulse, which Bullet wrote back along its two rows, kept along
  // btPlaneSpace1's directions for the next step's warm start.
  if (m_multiBodyFrictionContactConstraints.size() != 2 * m_multiBodyNormalContactConstraints.size()) return result;
  for (int c = 0; c < m_multiBodyNormalContactConstraints.size(); ++c) {
    const btMultiBodySolverConstraint& normal = m_multiBodyNormalContactConstraints[c];
    auto* point = static_cast<btManifoldPoint*>(normal.m_originalContactPoint);
    if (!point) continue;
    const btMultiBodySolverConstraint& row1 = m_multiBodyFrictionContactConstraints[normal.m_frictionIndex];
    const btMultiBodySolverConstraint& row2 = m_multiBodyFrictionContactConstraints[normal.m_frictionIndex + 1];
    const btVector3 friction = btScalar(row1.m_appliedImpulse) * row1.m_contactNormal1 +
                               btScalar(row2.m_appliedImpulse) * row2.m_contactNormal1;
    btVector3 e1, e2;
    btPlaneSpace1(point->m_normalWorldOnB, e1, e2);
    point->m_appliedImpulseLateral1 = friction.dot(e1);
    point->m_appliedImpulseLateral2 = friction.dot(e2);
  }
  return result;
}

// Interpenetration.
//
// Bullet's contact row asks the bodies to separate at erp * depth / dt, as velocity, uncapped: with
// its wheels 0.1 m in the ground, m_robot left it at 20 m/s and flew 20 m up. Gazebo's
// ODE limits how fast a contact corrects an overlap by its max_vel (SDF <surface><contact><ode>
// <max_vel>, 0.01 m/s by default; the smaller of the two bodies' where both move, capped by the
// world's <contact_max_correcting_vel>) and leaves min_depth of it (0 by default) uncorrected.
//
// Here the correction moves positions only, as Bullet's split impulse does for rigid bodies: the
// velocity rows ask for no separation (convertContacts), so the bodies gain no kinetic energy from
// an overlap, and pushApart then solves the normal rows once more, on velocities of their own that
// move the positions in this step and are dropped after it (btMultiBody's split velocity, which
// btMultiBodyDynamicsWorld adds while it integrates positions and then removes). Each contact asks
// for erp * (depth - min_depth - kPushSlop) / dt of separation, capped by its max_vel: a box 0.1 m
// into the ground rises at 0.01 m/s for 10 s and stands on it at rest. Only contacts take part in
// this pass: joints keep their frames (it moves the multibody's own coordinates), and a joint limit
// it pushes a link into is corrected by the limit's own row in the next step.
//
// Where Gazebo differs (docs/SIMULATOR.md, "Interpenetration"): its quick step integrates the
// positions with the uncapped erp * depth / dt, and caps only the velocity kept after the step at
// max_vel; a body leaves an overlap within a step or a few, and keeps up to max_vel of speed.
ContactSolver::Correction ContactSolver::correctionOf(const btPersistentManifold* manifold,
                                                      const btManifoldPoint& point) const {
  // A collider's surfaces by the child shape of its compound that touches (the manifold's m_index).
  const auto surfaceOf = [](const btCollisionObject* object, int child) -> const ContactSurface* {
    const auto* surfaces = static_cast<const ColliderSurfaces*>(object->getUserPointer());
    if (!surfaces || surfaces->by_child.empty()) return nullptr;
    if (child < 0 || child >= static_cast<int>(surfaces->by_child.size())) child = 0;  // not expected
    return &surfaces->by_child[child];
  };
  const ContactSurface* a = surfaceOf(manifold->getBody0(), point.m_index0);
  const ContactSurface* b = surfaceOf(manifold->getBody1(), point.m_index1);
  Correction c;
  // As ODE's contact joint in Gazebo: both bodies' surfaces, the one body's, or the world's layer
  // (never, for our models: a static model has no surfaces, a moving one always has).
  c.min_depth = a && b ? std::min(a->min_depth, b->min_depth) : a ? a->min_depth : b ? b->min_depth : surface_layer_;
  c.max_vel = max_correcting_vel_;
  for (const ContactSurface* s : {a, b})
    if (s && s->max_vel >= 0) c.max_vel = std::min<btScalar>(c.max_vel, s->max_vel);
  return c;
}

// The bodies' velocity along the row (separating when positive), as Bullet computes it for the row.
btScalar ContactSolver::normalVelocity(const btMultiBodySolverConstraint& row) const {
  btScalar v = 0;
  const auto side = [&](const btMultiBody* multibody, int jacobian, int solver_body, const btVector3& normal,
                        const btVector3& arm) {
    if (multibody) {
      const btScalar* velocity = multibody->getVelocityVector();
      for (int i = 0; i < multibody->getNumDofs() + 6; ++i) v += m_data.m_jacobians[jacobian + i] * velocity[i];
    } else if (solver_body >= 0) {
      const btSolverBody& body = m_tmpSolverBodyPool[solver_body];
      v += normal.dot(body.m_linearVelocity + body.m_externalForceImpulse) +
           arm.dot(body.m_angularVelocity + body.m_externalTorqueImpulse);
    }
  };
  side(row.m_multiBodyA, row.m_jacAindex, row.m_solverBodyIdA, row.m_contactNormal1, row.m_relpos1CrossNormal);
  side(row.m_multiBodyB, row.m_jacBindex, row.m_solverBodyIdB, row.m_contactNormal2, row.m_relpos2CrossNormal);
  return v;
}

// Projected Gauss-Seidel over the contact rows (normal and friction) on velocities of their own, at
// most `iters` sweeps, only in a step where some contact overlaps by more than it may. A normal row
// pushes only (its impulse stays >= 0), so a contact inside its min_depth, or one still apart, keeps
// the others' pushes from closing it. Only multibodies move; a rigid body (none in our worlds) stays.
void ContactSolver::pushApart(const btContactSolverInfo& info) {
  const int rows = m_multiBodyNormalContactConstraints.size();
  if (rows == 0 || static_cast<int>(corrections_.size()) != rows) return;
  push_target_.resize(rows);
  bool any = false;
  for (int c = 0; c < rows; ++c) {
    const auto* point = static_cast<const btManifoldPoint*>(m_multiBodyNormalContactConstraints[c].m_originalContactPoint);
    const btScalar distance = point->getDistance(), excess = -distance - corrections_[c].min_depth - kPushSlop;
    push_target_[c] = excess > 0 ? std::min(info.m_erp2 * excess / info.m_timeStep, corrections_[c].max_vel)
                                 : -std::max<btScalar>(distance, 0) / info.m_timeStep;
    any = any || push_target_[c] > 0;
  }
  if (!any) return;
  push_velocity_.resize(m_data.m_deltaVelocities.size());
  for (int i = 0; i < push_velocity_.size(); ++i) push_velocity_[i] = 0;
  push_impulse_.assign(rows, 0);
  const auto along = [&](const btMultiBody* multibody, int jacobian, int velocities) {
    btScalar v = 0;
    if (multibody)
      for (int i = 0; i < multibody->getNumDofs() + 6; ++i) v += m_data.m_jacobians[jacobian + i] * push_velocity_[velocities + i];
    return v;
  };
  const auto apply = [&](const btMultiBody* multibody, int jacobian, int velocities, btScalar impulse) {
    if (multibody)
      for (int i = 0; i < multibody->getNumDofs() + 6; ++i)
        push_velocity_[velocities + i] += m_data.m_deltaVelocitiesUnitImpulse[jacobian + i] * impulse;
  };
  const int friction_rows = m_multiBodyFrictionContactConstraints.size();
  push_friction_.assign(friction_rows, 0);
  // One row towards `target`, its impulse kept within [lower, upper]; returns the change of its speed.
  const auto solve = [&](const btMultiBodySolverConstraint& row, btScalar target, btScalar& impulse, btScalar lower,
                         btScalar upper) -> btScalar {
    if (row.m_jacDiagABInv == 0) return 0;  // a row Bullet disabled (nothing can move along it)
    const btScalar speed = along(row.m_multiBodyA, row.m_jacAindex, row.m_deltaVelAindex) +
                           along(row.m_multiBodyB, row.m_jacBindex, row.m_deltaVelBindex);
    const btScalar next = std::min(upper, std::max(lower, impulse + (target - speed) * row.m_jacDiagABInv));
    const btScalar change = next - impulse;
    if (change == 0) return 0;
    impulse = next;
    apply(row.m_multiBodyA, row.m_jacAindex, row.m_deltaVelAindex, change);
    apply(row.m_multiBodyB, row.m_jacBindex, row.m_deltaVelBindex, change);
    return btFabs(change) / row.m_jacDiagABInv;
  };
  for (int sweep = 0; sweep < info.m_numIterations; ++sweep) {
    btScalar largest = 0;  // change of a row's speed in this sweep
    for (int c = 0; c < rows; ++c)
      largest = std::max(largest, solve(m_multiBodyNormalContactConstraints[c], push_target_[c], push_impulse_[c], 0,
                                        BT_LARGE_FLOAT));
    // Friction holds the contacts still while they are pushed, as in the velocity sweeps: pushed out
    // along its normals alone, a can standing on another tilts and slides off it a little each step.
    for (int f = 0; f < friction_rows; ++f) {
      const btMultiBodySolverConstraint& row = m_multiBodyFrictionContactConstraints[f];
      const btScalar limit = row.m_friction * push_impulse_[row.m_frictionIndex];
      largest = std::max(largest, solve(row, 0, push_friction_[f], -limit, limit));
    }
    if (largest <= kPushTolerance) break;
  }
  // Each moving body's share, once: btMultiBodyDynamicsWorld moves the positions with it this step.
  given_.assign(push_velocity_.size(), 0);
  const auto give = [&](btMultiBody* multibody, int velocities) {
    if (!multibody || given_[velocities]) return;
    given_[velocities] = 1;
    multibody->applyDeltaSplitVeeMultiDof(&push_velocity_[velocities], 1);
  };
  for (int c = 0; c < rows; ++c) {
    const btMultiBodySolverConstraint& row = m_multiBodyNormalContactConstraints[c];
    give(row.m_multiBodyA, row.m_deltaVelAindex);
    give(row.m_multiBodyB, row.m_deltaVelBindex);
  }
}

}  // namespace bullet_sim
