#pragma once
// Bullet collision shapes from descriptions. Bullet shapes do not own their children or
// triangle data, so a ShapeStore owns everything it makes for one model.
#include "bullet_sim_core/bullet_precision.h"
#include <btBulletDynamicsCommon.h>

#include <memory>
#include <vector>

#include "bullet_sim_core/model_description.h"

namespace bullet_sim {

class ShapeStore {
 public:
  // Meshes become convex hulls on moving bodies and exact triangle meshes on static ones,
  // as in Gazebo's Bullet engine. A plane is only allowed on static bodies.
  btCollisionShape* make(const Geometry& geometry, bool is_static, const std::string& where);
  btCompoundShape* makeCompound();

 private:
  std::vector<std::unique_ptr<btCollisionShape>> shapes_;
  std::vector<std::unique_ptr<btStridingMeshInterface>> meshes_;
};

btTransform toBullet(const Eigen::Isometry3d& t);
Eigen::Isometry3d fromBullet(const btTransform& t);
inline btVector3 toBullet(const Eigen::Vector3d& v) { return btVector3(v.x(), v.y(), v.z()); }
inline Eigen::Vector3d fromBullet(const btVector3& v) { return Eigen::Vector3d(v.x(), v.y(), v.z()); }

}  // namespace bullet_sim
