#pragma once
// The constraint solver of PhysicsWorld: Bullet's btMultiBody solver (projected Gauss-Seidel
// sweeps over the contact, friction and joint-motor rows) with two changes, each explained in
// contact_solver.cpp:
//
// - friction along the slip: a sliding contact's two friction rows lie along and across its
//   slip, so that Coulomb friction opposes the slip whatever the heading;
// - warm starting and an early stop: joint rows and contacts that are their manifold's only
//   point (a wheel, a ball) start from the impulse they ended the last step with, as ODE's
//   quickstep (Gazebo's default solver) does, and where every contact started so, the sweeps
//   stop once a whole sweep changes no row's velocity by more than the world's tolerance
//   (PhysicsSettings::solver_tolerance), at most `iters`.
#include "bullet_sim_core/bullet_precision.h"
#include <BulletDynamics/Featherstone/btMultiBodyConstraintSolver.h>

#include <vector>

namespace bullet_sim {

class ContactSolver : public btMultiBodyConstraintSolver {
 public:
  // Solves (one per island of touching bodies per step) and the sweeps they took, counted since
  // the last reset.
  long solves() const { return solves_; }
  long sweeps() const { return sweeps_; }
  void resetCounters() { solves_ = sweeps_ = 0; }
  // Off: every row starts from zero, as Bullet's solver does (benchmarks compare the two).
  void setWarmStart(bool on) { warm_start_ = on; }

 protected:
  void convertContacts(btPersistentManifold** manifolds, int count, const btContactSolverInfo& info) override;
  btScalar solveGroupCacheFriendlyIterations(btCollisionObject** bodies, int num_bodies,
                                             btPersistentManifold** manifolds, int num_manifolds,
                                             btTypedConstraint** constraints, int num_constraints,
                                             const btContactSolverInfo& info, btIDebugDraw* debug) override;
  btScalar solveSingleIteration(int iteration, btCollisionObject** bodies, int num_bodies,
                                btPersistentManifold** manifolds, int num_manifolds, btTypedConstraint** constraints,
                                int num_constraints, const btContactSolverInfo& info, btIDebugDraw* debug) override;
  btScalar solveGroupCacheFriendlyFinish(btCollisionObject** bodies, int num_bodies,
                                         const btContactSolverInfo& info) override;

 private:
  static bool slipFrictionApplies(const btPersistentManifold* manifold);
  void convertManifold(btPersistentManifold* manifold, const btContactSolverInfo& info);
  btScalar velocityAlong(const btVector3& direction, const btManifoldPoint& point, const btCollisionObject* body0,
                         const btCollisionObject* body1);
  void warmStart();
  void startRowAt(btMultiBodySolverConstraint& row, btScalar impulse);

  bool warm_start_ = true;
  std::vector<bool> lone_contact_;  // per normal row: its manifold's only touching point
  btAlignedObjectArray<btScalar> jacobian_;  // scratch for velocityAlong
  long solves_ = 0, sweeps_ = 0;
};

}  // namespace bullet_sim
