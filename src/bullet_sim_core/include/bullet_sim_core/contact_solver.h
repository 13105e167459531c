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
//   (PhysicsSettings::solver_tolerance), at most `iters`;
// - overlaps corrected as Gazebo limits it, and in positions only: the contacts' velocity rows ask
//   for no separation, and a second, position-only pass moves overlapping bodies apart no faster
//   than the contact's max_vel (its surfaces', capped by the world's contact_max_correcting_vel),
//   leaving min_depth of the overlap; so a body spawned into another rises out of it slowly and
//   gains no kinetic energy from it.
#include "bullet_sim_core/bullet_precision.h"
#include <BulletDynamics/Featherstone/btMultiBodyConstraintSolver.h>

#include <vector>

#include "bullet_sim_core/model_description.h"

namespace bullet_sim {

// A moving body's surfaces as its collider tells the solver: one per child of the collider's
// compound shape, in order. PhysicsModel sets it as the collider's user pointer; a collider
// without one (a static model's) has no surface of its own, like a static geom in ODE.
struct ColliderSurfaces {
  std::vector<ContactSurface> by_child;
};

class ContactSolver : public btMultiBodyConstraintSolver {
 public:
  // Solves (one per island of touching bodies per step) and the sweeps they took, counted since
  // the last reset.
  long solves() const { return solves_; }
  long sweeps() const { return sweeps_; }
  void resetCounters() { solves_ = sweeps_ = 0; }
  // Off: every row starts from zero, as Bullet's solver does (benchmarks compare the two).
  void setWarmStart(bool on) { warm_start_ = on; }
  // The world's contact_max_correcting_vel (m/s) and contact_surface_layer (m): PhysicsSettings.
  void setContactCorrection(btScalar max_correcting_vel, btScalar surface_layer) {
    max_correcting_vel_ = max_correcting_vel;
    surface_layer_ = surface_layer;
  }

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
  // Overlaps (see contact_solver.cpp, "Interpenetration").
  struct Correction {
    btScalar max_vel = 0;    // m/s, the fastest this contact moves its bodies apart
    btScalar min_depth = 0;  // m, the overlap it leaves
  };
  Correction correctionOf(const btPersistentManifold* manifold, const btManifoldPoint& point) const;
  btScalar normalVelocity(const btMultiBodySolverConstraint& row) const;
  void pushApart(const btContactSolverInfo& info);

  bool warm_start_ = true;
  std::vector<bool> lone_contact_;  // per normal row: its manifold's only touching point
  btAlignedObjectArray<btScalar> jacobian_;  // scratch for velocityAlong
  long solves_ = 0, sweeps_ = 0;
  btScalar max_correcting_vel_ = 100, surface_layer_ = 0.001;
  std::vector<Correction> corrections_;                // per normal row
  std::vector<btScalar> push_target_, push_impulse_;   // per normal row
  std::vector<btScalar> push_friction_;                // per friction row
  btAlignedObjectArray<btScalar> push_velocity_;       // laid out as m_data.m_deltaVelocities
  std::vector<char> given_;                            // pushApart's scratch, laid out the same
};

}  // namespace bullet_sim
