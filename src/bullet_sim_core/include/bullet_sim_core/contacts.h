#pragma once
// The contacts of the last physics step, by model and link: what a bumper sensor or the grasp fix
// reads. Bullet keeps them in its collision dispatcher's manifolds; this names their bodies.
#include "bullet_sim_core/bullet_precision.h"
#include <Eigen/Geometry>

#include <string>
#include <vector>

class btCollisionObject;

namespace bullet_sim {

class PhysicsWorld;

struct Contact {
  const btCollisionObject* collider_a = nullptr;
  const btCollisionObject* collider_b = nullptr;
  std::string model_a, link_a, model_b, link_b;  // link: one of the links the collider carries
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  // world, midway between the two surfaces
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();   // world, unit, on b pointing towards a
  double depth = 0.0;  // penetration (m), > 0 when the surfaces overlap
  double force = 0.0;  // normal force the solver applied in the last step (N), >= 0
};

// Every touching point (penetration above -tolerance) of the last step between colliders of our
// models. Bullet also keeps points a little apart (its contact margin); those are left out.
std::vector<Contact> currentContacts(PhysicsWorld& world, double tolerance = 1e-3);

}  // namespace bullet_sim
