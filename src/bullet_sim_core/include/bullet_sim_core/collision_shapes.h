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

// How a cylinder (btCylinderShape, any axis) touches a static plane; PhysicsWorld registers it
// with the collision dispatcher in place of Bullet's convex-plane algorithm, which reports the
// single deepest point of the shape's support function: for a cylinder lying on its side, a
// point on one rim edge, picked by the rounding of a ~1e-17 component. A full-width wheel then
// stands on one edge, a width/2 lever off its mid-plane, and a skid steer's wheels push the
// vehicle sideways while it turns. This algorithm follows the geometry instead:
// - lying (axis within 45 degrees of the plane): the bottom line of the cylinder touches. It
//   gives one contact at the line's centre of pressure, the load taken to grow linearly with
//   the depth below a band kContactPatchDepth above the plane: the mid-plane while the line is
//   level to within that band, sliding towards the lower rim as the cylinder tips, the lowest
//   rim point once only that end is near the plane. One point per step, so no solver has to
//   share a line's load between its ends (it would put it on whichever end it solves first);
// - standing: the lower end cap's face touches. Its rim's four points at 90 degrees (the
//   lowest first) are contacts, like a box's face.
// Points are added only within the manifold's contact breaking threshold, as Bullet does.
std::unique_ptr<btCollisionAlgorithmCreateFunc> makeCylinderPlaneAlgorithm(bool swapped);
constexpr btScalar kContactPatchDepth = 0.001;  // m

// How two cylinders touch when one stands on the other's end cap (a tower of cans): Bullet's
// convex-convex algorithm finds one point per step by GJK/EPA, and its manifold of points from
// successive steps lets the upper one creep over the lower one, about 0.1 mm/s for the Katana
// tutorial's cans. Here the points of each cap's rim that lie over the other cap are contacts
// at once, like a box's face on a box. It applies when the axes are within 30 degrees and the
// shorter way out is along the lower one's axis; otherwise `general` (Bullet's algorithm for
// the pair, from the collision configuration) handles the pair.
std::unique_ptr<btCollisionAlgorithmCreateFunc> makeCylinderCylinderAlgorithm(btCollisionAlgorithmCreateFunc* general);

}  // namespace bullet_sim
