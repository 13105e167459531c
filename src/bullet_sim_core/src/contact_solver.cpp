#include "bullet_sim_core/contact_solver.h"

#include <algorithm>

#include <BulletCollision/NarrowPhaseCollision/btPersistentManifold.h>
#include <BulletDynamics/Featherstone/btMultiBodyConstraint.h>
#include <BulletDynamics/Featherstone/btMultiBodyLinkCollider.h>

namespace bullet_sim {
namespace {
// Below this slip speed a contact sticks and keeps Bullet's friction rows (see convertContacts).
constexpr btScalar kSlipSpeed = 1e-4;  // m/s
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
// After Bullet has set up the contacts, every contact that slides faster than kSlipSpeed gets
// its two friction rows rebuilt along the slip and across it (by Bullet's own row set-up), so
// the clamped force opposes the slip whatever the heading. Contacts that stick keep Bullet's
// rows: below the cone's limit any two directions hold the same.
void ContactSolver::convertContacts(btPersistentManifold** manifolds, int count, const btContactSolverInfo& info) {
  btMultiBodyConstraintSolver::convertContacts(manifolds, count, info);
  // Bullet lays out a normal row per touching point of each multibody manifold, in order, and
  // two friction rows per contact. Walk them, noting which contacts are their manifold's only one.
  lone_contact_.assign(m_multiBodyNormalContactConstraints.size(), false);
  const bool two_directions = (info.m_solverMode & SOLVER_USE_2_FRICTION_DIRECTIONS) &&
                              m_multiBodyFrictionContactConstraints.size() == 2 * m_multiBodyNormalContactConstraints.size();
  int contact = 0;
  bool bullets_layout = two_directions;
  for (int m = 0; m < count && bullets_layout; ++m) {
    btPersistentManifold* manifold = manifolds[m];
    if (!btMultiBodyLinkCollider::upcast(manifold->getBody0()) && !btMultiBodyLinkCollider::upcast(manifold->getBody1()))
      continue;  // a rigid-body pair: Bullet's rigid-body solver follows the slip and warm starts
    const int first = contact;
    for (int k = 0; k < manifold->getNumContacts(); ++k) {
      btManifoldPoint& point = manifold->getContactPoint(k);
      if (!(point.getDistance() <= manifold->getContactProcessingThreshold())) continue;
      if (contact >= m_multiBodyNormalContactConstraints.size() ||
          m_multiBodyNormalContactConstraints[contact].m_originalContactPoint != &point) {
        bullets_layout = false;  // not Bullet's layout: leave its rows, start them from zero
        break;
      }
      alongSlip(manifold, point, contact, m_multiBodyNormalContactConstraints[contact].m_frictionIndex, info);
      ++contact;
    }
    if (bullets_layout && contact == first + 1) lone_contact_[first] = true;
  }
  if (!bullets_layout) lone_contact_.assign(lone_contact_.size(), false);
  if (warm_start_) warmStart();
}

// Relative velocity (A minus B) along a row's direction, as the solver computes it.
btScalar ContactSolver::rowVelocity(const btMultiBodySolverConstraint& row) const {
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

void ContactSolver::alongSlip(btPersistentManifold* manifold, btManifoldPoint& point, int contact, int first_row,
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
        addMultiBodyFrictionConstraint(r == 0 ? point.m_lateralFrictionDir1 : point.m_lateralFrictionDir2, 0, manifold,
                                       contact, point, body0, body1, info.m_sor, info);
    m_multiBodyFrictionContactConstraints[first_row + r] = row;
    m_multiBodyFrictionContactConstraints.pop_back();
  }
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
  if (row.m_multiBodyA) {
    btScalar* unit = &m_data.m_deltaVelocitiesUnitImpulse[row.m_jacAindex];
    applyDeltaVee(unit, impulse, row.m_deltaVelAindex, row.m_multiBodyA->getNumDofs() + 6);
    row.m_multiBodyA->applyDeltaVeeMultiDof2(unit, impulse);
  } else if (row.m_solverBodyIdA >= 0) {
    btSolverBody& body = m_tmpSolverBodyPool[row.m_solverBodyIdA];
    body.internalApplyImpulse(row.m_contactNormal1 * body.internalGetInvMass(), row.m_angularComponentA, impulse);
  }
  if (row.m_multiBodyB) {
    btScalar* unit = &m_data.m_deltaVelocitiesUnitImpulse[row.m_jacBindex];
    applyDeltaVee(unit, impulse, row.m_deltaVelBindex, row.m_multiBodyB->getNumDofs() + 6);
    row.m_multiBodyB->applyDeltaVeeMultiDof2(unit, impulse);
  } else if (row.m_solverBodyIdB >= 0) {
    btSolverBody& body = m_tmpSolverBodyPool[row.m_solverBodyIdB];
    body.internalApplyImpulse(row.m_contactNormal2 * body.internalGetInvMass(), row.m_angularComponentB, impulse);
  }
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

}  // namespace bullet_sim
