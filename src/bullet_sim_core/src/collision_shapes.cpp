#include "bullet_sim_core/collision_shapes.h"

#include <BulletCollision/CollisionShapes/btTriangleMesh.h>

#include "bullet_sim_core/description_error.h"
#include "bullet_sim_core/mesh_loader.h"

namespace bullet_sim {
namespace {
// Bullet's default 4 cm margin rounds box corners and inflates hulls; ranges and contacts
// should match the described geometry to the millimetre.
constexpr btScalar kMargin = 0.001;
}  // namespace

btTransform toBullet(const Eigen::Isometry3d& t) {
  const Eigen::Quaterniond q(t.linear());
  return btTransform(btQuaternion(q.x(), q.y(), q.z(), q.w()), toBullet(Eigen::Vector3d(t.translation())));
}

Eigen::Isometry3d fromBullet(const btTransform& t) {
  const btQuaternion q = t.getRotation();
  Eigen::Isometry3d out = Eigen::Isometry3d::Identity();
  out.linear() = Eigen::Quaterniond(q.w(), q.x(), q.y(), q.z()).toRotationMatrix();
  out.translation() = fromBullet(t.getOrigin());
  return out;
}

btCompoundShape* ShapeStore::makeCompound() {
  shapes_.push_back(std::make_unique<btCompoundShape>());
  return static_cast<btCompoundShape*>(shapes_.back().get());
}

btCollisionShape* ShapeStore::make(const Geometry& g, bool is_static, const std::string& where) {
  std::unique_ptr<btCollisionShape> shape;
  switch (g.type) {
    case GeometryType::Box:
      shape = std::make_unique<btBoxShape>(toBullet(Eigen::Vector3d(g.box_size * 0.5)));
      break;
    case GeometryType::Cylinder:
      shape = std::make_unique<btCylinderShapeZ>(btVector3(g.radius, g.radius, g.length * 0.5));
      break;
    case GeometryType::Sphere:
      shape = std::make_unique<btSphereShape>(g.radius);
      break;
    case GeometryType::Plane:
      if (!is_static) throw DescriptionError(where + ": a plane is only allowed on a static model");
      shape = std::make_unique<btStaticPlaneShape>(toBullet(g.plane_normal.normalized()), 0);
      break;
    case GeometryType::Mesh: {
      const TriangleMesh& mesh = loadMesh(g.mesh_file);
      const Eigen::Vector3d s = g.mesh_scale;
      if (is_static) {
        auto triangles = std::make_unique<btTriangleMesh>(true, false);
        for (const auto& t : mesh.triangles) {
          btVector3 v[3];
          for (int k = 0; k < 3; ++k) v[k] = toBullet(Eigen::Vector3d(mesh.vertices[t[k]].cwiseProduct(s)));
          triangles->addTriangle(v[0], v[1], v[2], true);
        }
        shape = std::make_unique<btBvhTriangleMeshShape>(triangles.get(), true);
        meshes_.push_back(std::move(triangles));
      } else {
        auto hull = std::make_unique<btConvexHullShape>();
        for (const auto& v : mesh.vertices) hull->addPoint(toBullet(Eigen::Vector3d(v.cwiseProduct(s))), false);
        hull->recalcLocalAabb();
        hull->optimizeConvexHull();
        shape = std::move(hull);
      }
      break;
    }
  }
  shape->setMargin(kMargin);
  shapes_.push_back(std::move(shape));
  return shapes_.back().get();
}

}  // namespace bullet_sim
