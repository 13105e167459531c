#include "bullet_sim_core/collision_shapes.h"

#include <BulletCollision/CollisionDispatch/btActivatingCollisionAlgorithm.h>
#include <BulletCollision/CollisionDispatch/btCollisionObjectWrapper.h>
#include <BulletCollision/CollisionDispatch/btManifoldResult.h>
#include <BulletCollision/CollisionShapes/btTriangleMesh.h>

#include <cmath>

#include "bullet_sim_core/description_error.h"
#include "bullet_sim_core/mesh_loader.h"

namespace bullet_sim {
namespace {
// Bullet's default 4 cm margin rounds box corners and inflates hulls; ranges and contacts
// should match the described geometry to the millimetre.
constexpr btScalar kMargin = 0.001;

// A plane whose bounding box is the half-space below it, where its normal is an axis (always, for
// a floor): Bullet's plane says it is everywhere, so every moving body, however far above the
// floor, is paired with it in the broadphase and tested every step. Bounded, only bodies that
// reach the floor's surface are.
class HalfSpaceShape : public btStaticPlaneShape {
 public:
  using btStaticPlaneShape::btStaticPlaneShape;
  void getAabb(const btTransform& t, btVector3& aabb_min, btVector3& aabb_max) const override {
    btStaticPlaneShape::getAabb(t, aabb_min, aabb_max);
    const btVector3 n = t.getBasis() * getPlaneNormal();
    const btScalar surface = getPlaneConstant() + n.dot(t.getOrigin());  // n . x on the plane
    for (int axis = 0; axis < 3; ++axis) {
      if (btFabs(btFabs(n[axis]) - 1) > 1e-9) continue;
      const btScalar level = n[axis] * surface + n[axis] * getMargin();
      if (n[axis] > 0) aabb_max[axis] = level;
      else aabb_min[axis] = level;
    }
  }
};

// See makeCylinderPlaneAlgorithm in the header.
class CylinderPlaneAlgorithm : public btActivatingCollisionAlgorithm {
 public:
  CylinderPlaneAlgorithm(const btCollisionAlgorithmConstructionInfo& info, const btCollisionObjectWrapper* body0,
                         const btCollisionObjectWrapper* body1, bool swapped)
      : btActivatingCollisionAlgorithm(info, body0, body1), swapped_(swapped) {
    // Like btConvexPlaneCollisionAlgorithm: its own manifold, cylinder first, also as a
    // compound's child (each child pair then has a manifold of its own).
    const btCollisionObject* cylinder = (swapped ? body1 : body0)->getCollisionObject();
    const btCollisionObject* plane = (swapped ? body0 : body1)->getCollisionObject();
    if (m_dispatcher->needsCollision(cylinder, plane)) manifold_ = m_dispatcher->getNewManifold(cylinder, plane);
  }
  ~CylinderPlaneAlgorithm() override {
    if (manifold_) m_dispatcher->releaseManifold(manifold_);
  }

  void processCollision(const btCollisionObjectWrapper* body0, const btCollisionObjectWrapper* body1,
                        const btDispatcherInfo&, btManifoldResult* result) override {
    if (!manifold_) return;
    const btCollisionObjectWrapper* cylinder_wrap = swapped_ ? body1 : body0;
    const btCollisionObjectWrapper* plane_wrap = swapped_ ? body0 : body1;
    const auto* cylinder = static_cast<const btCylinderShape*>(cylinder_wrap->getCollisionShape());
    const auto* plane = static_cast<const btStaticPlaneShape*>(plane_wrap->getCollisionShape());
    result->setPersistentManifold(manifold_);

    const btTransform& plane_pose = plane_wrap->getWorldTransform();
    const btVector3 n = plane_pose.getBasis() * plane->getPlaneNormal();
    const btScalar plane_offset = plane->getPlaneConstant() + n.dot(plane_pose.getOrigin());
    const btTransform& pose = cylinder_wrap->getWorldTransform();
    const int up = cylinder->getUpAxis();
    const btScalar half_length = cylinder->getHalfExtentsWithMargin()[up];  // the described size
    const btScalar radius = cylinder->getRadius();
    const btVector3 axis = pose.getBasis().getColumn(up);
    const btVector3 centre = pose.getOrigin();
    const btScalar threshold = manifold_->getContactBreakingThreshold();
    auto add = [&](const btVector3& point, btScalar distance) {
      // Bullet's convention: normal and point on the plane (B); distance < 0 is penetration.
      if (distance < threshold) result->addContactPoint(n, point - distance * n, distance);
    };
    auto distanceOf = [&](const btVector3& p) { return n.dot(p) - plane_offset; };

    const btScalar along = n.dot(axis);
    btVector3 across = n - along * axis;  // in the cross-section, towards the plane's normal
    if (std::abs(along) > SIMDSQRT12) {
      // Standing on an end cap: its rim's lowest point and the three at 90 degrees from it.
      btVector3 u, v;
      if (across.length2() > btScalar(1e-24)) {
        u = across.normalized();
        v = axis.cross(u);
      } else {
        btPlaneSpace1(axis, u, v);
      }
      const btVector3 cap = centre + (along > 0 ? -half_length : half_length) * axis;
      for (const btVector3& p : {cap - radius * u, cap + radius * v, cap - radius * v, cap + radius * u})
        add(p, distanceOf(p));
    } else {
      // Lying: the bottom line from one end cap's rim to the other's.
      across.normalize();
      const btVector3 p0 = centre - half_length * axis - radius * across;
      const btVector3 p1 = centre + half_length * axis - radius * across;
      const btScalar d0 = distanceOf(p0), d1 = distanceOf(p1);
      // Load per unit length ~ max(0, kContactPatchDepth - distance), linear along the line;
      // t is the fraction from p0 to p1 of its centroid.
      const btScalar w0 = kContactPatchDepth - d0, w1 = kContactPatchDepth - d1;
      btScalar t;
      if (w0 > 0 && w1 > 0) {
        t = (w0 + 2 * w1) / (3 * (w0 + w1));  // a trapezoid
      } else if (w1 > 0) {
        const btScalar start = w0 / (w0 - w1);  // a triangle from there to p1
        t = start + (1 - start) * btScalar(2) / 3;
      } else if (w0 > 0) {
        const btScalar end = w0 / (w0 - w1);  // a triangle from p0 to there
        t = end / 3;
      } else {
        t = d1 < d0 ? 1 : 0;  // clear of the band: the lower end, as Bullet would
      }
      add(p0 + t * (p1 - p0), d0 + t * (d1 - d0));
    }
    if (manifold_->getNumContacts()) result->refreshContactPoints();
  }

  btScalar calculateTimeOfImpact(btCollisionObject*, btCollisionObject*, const btDispatcherInfo&,
                                 btManifoldResult*) override {
    return 1;  // no continuous collision detection, as btConvexPlaneCollisionAlgorithm
  }

  void getAllContactManifolds(btManifoldArray& manifolds) override {
    if (manifold_) manifolds.push_back(manifold_);
  }

  struct CreateFunc : public btCollisionAlgorithmCreateFunc {
    btCollisionAlgorithm* CreateCollisionAlgorithm(btCollisionAlgorithmConstructionInfo& info,
                                                   const btCollisionObjectWrapper* body0,
                                                   const btCollisionObjectWrapper* body1) override {
      void* memory = info.m_dispatcher1->allocateCollisionAlgorithm(sizeof(CylinderPlaneAlgorithm));
      return new (memory) CylinderPlaneAlgorithm(info, body0, body1, m_swapped);
    }
  };

 private:
  btPersistentManifold* manifold_ = nullptr;
  bool swapped_;
};

}  // namespace

std::unique_ptr<btCollisionAlgorithmCreateFunc> makeCylinderPlaneAlgorithm(bool swapped) {
  auto f = std::make_unique<CylinderPlaneAlgorithm::CreateFunc>();
  f->m_swapped = swapped;
  return f;
}

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
      shape = std::make_unique<HalfSpaceShape>(toBullet(g.plane_normal.normalized()), 0);
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
