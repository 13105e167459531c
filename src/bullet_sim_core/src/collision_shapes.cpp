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

// Friction anchors on the points added while it lives: a new point near a sticking one (within
// the friction cone) leaves the old one in place, so the friction rows hold the bodies where they
// first touched instead of where the last step left them, which is what stops the creep. Bullet
// only offers them per collision object (CF_HAS_FRICTION_ANCHOR, read by
// btManifoldResult::addContactPoint), and on a rolling wheel they would keep contacts the wheel
// has rolled away from; so the flag is set on the two objects just while their cap contacts are
// added.
class FrictionAnchors {
 public:
  explicit FrictionAnchors(btPersistentManifold* manifold)
      : objects_{const_cast<btCollisionObject*>(manifold->getBody0()),
                 const_cast<btCollisionObject*>(manifold->getBody1())} {
    for (int i = 0; i < 2; ++i) {
      flags_[i] = objects_[i]->getCollisionFlags();
      objects_[i]->setCollisionFlags(flags_[i] | btCollisionObject::CF_HAS_FRICTION_ANCHOR);
    }
  }
  ~FrictionAnchors() {
    for (int i = 0; i < 2; ++i) objects_[i]->setCollisionFlags(flags_[i]);
  }
  FrictionAnchors(const FrictionAnchors&) = delete;
  FrictionAnchors& operator=(const FrictionAnchors&) = delete;

 private:
  btCollisionObject* objects_[2];
  int flags_[2];
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

// See makeCylinderCylinderAlgorithm in the header.
class CylinderCylinderAlgorithm : public btActivatingCollisionAlgorithm {
 public:
  CylinderCylinderAlgorithm(const btCollisionAlgorithmConstructionInfo& info, const btCollisionObjectWrapper* body0,
                            const btCollisionObjectWrapper* body1, btCollisionAlgorithmCreateFunc* general)
      : btActivatingCollisionAlgorithm(info, body0, body1) {
    const btCollisionObject* a = body0->getCollisionObject();
    const btCollisionObject* b = body1->getCollisionObject();
    if (m_dispatcher->needsCollision(a, b)) manifold_ = m_dispatcher->getNewManifold(a, b);
    // Bullet's own algorithm for every other way two cylinders touch, on this algorithm's manifold:
    // with a manifold of its own, made lazily, it crashed the simulator when a can was let go
    // onto a tower (reading a manifold that was no longer valid; katana layout seed 2).
    btCollisionAlgorithmConstructionInfo general_info(info.m_dispatcher1, 0);
    general_info.m_manifold = manifold_;
    general_ = general->CreateCollisionAlgorithm(general_info, body0, body1);
  }
  ~CylinderCylinderAlgorithm() override {
    if (general_) {
      general_->~btCollisionAlgorithm();
      m_dispatcher->freeCollisionAlgorithm(general_);
    }
    if (manifold_) m_dispatcher->releaseManifold(manifold_);
  }

  void processCollision(const btCollisionObjectWrapper* body0, const btCollisionObjectWrapper* body1,
                        const btDispatcherInfo& info, btManifoldResult* result) override {
    if (!manifold_) return;
    if (capOnCap(body0, body1, result)) {
      on_cap_ = true;
      return;
    }
    // The two ways keep their points apart: a switch starts the manifold afresh.
    if (on_cap_) manifold_->clearManifold();
    on_cap_ = false;
    general_->processCollision(body0, body1, info, result);
    // Bullet's algorithm drops stale points only from a manifold of its own: this one's, here.
    if (manifold_->getNumContacts()) result->refreshContactPoints();
  }

  btScalar calculateTimeOfImpact(btCollisionObject* body0, btCollisionObject* body1, const btDispatcherInfo& info,
                                 btManifoldResult* result) override {
    return general_->calculateTimeOfImpact(body0, body1, info, result);
  }

  void getAllContactManifolds(btManifoldArray& manifolds) override {
    if (manifold_) manifolds.push_back(manifold_);
  }

  struct CreateFunc : public btCollisionAlgorithmCreateFunc {
    explicit CreateFunc(btCollisionAlgorithmCreateFunc* general_func) : general(general_func) {}
    btCollisionAlgorithm* CreateCollisionAlgorithm(btCollisionAlgorithmConstructionInfo& info,
                                                   const btCollisionObjectWrapper* body0,
                                                   const btCollisionObjectWrapper* body1) override {
      void* memory = info.m_dispatcher1->allocateCollisionAlgorithm(sizeof(CylinderCylinderAlgorithm));
      return new (memory) CylinderCylinderAlgorithm(info, body0, body1, general);
    }
    btCollisionAlgorithmCreateFunc* general;
  };

 private:
  struct Cylinder {
    btVector3 centre, axis;
    btScalar half_length, radius;
  };
  static Cylinder describe(const btCollisionObjectWrapper* wrap) {
    const auto* shape = static_cast<const btCylinderShape*>(wrap->getCollisionShape());
    const btTransform& pose = wrap->getWorldTransform();
    const int up = shape->getUpAxis();
    return {pose.getOrigin(), pose.getBasis().getColumn(up), shape->getHalfExtentsWithMargin()[up],
            shape->getRadius()};
  }

  // Whether `upper` rests on `lower`'s end cap: their axes within 30 degrees, and pushing upper
  // out along lower's axis is shorter than pushing it out sideways (the separating axis test
  // between the two directions). If so, the contacts between the facing caps go to the result.
  bool capOnCap(const btCollisionObjectWrapper* body0, const btCollisionObjectWrapper* body1,
                btManifoldResult* result) {
    const Cylinder c0 = describe(body0), c1 = describe(body1);
    if (std::abs(c0.axis.dot(c1.axis)) < btScalar(0.866)) return false;
    // Lower: whichever has the other's centre beyond its end cap.
    for (bool body1_lower : {true, false}) {
      const Cylinder& lower = body1_lower ? c1 : c0;
      const Cylinder& upper = body1_lower ? c0 : c1;
      const btVector3 offset = upper.centre - lower.centre;
      const btVector3 n = offset.dot(lower.axis) >= 0 ? lower.axis : -lower.axis;  // lower's cap, outwards
      const btVector3 cap = lower.centre + lower.half_length * n;
      if (n.dot(upper.centre - cap) <= 0) continue;
      // Upper's cap that faces lower, and its rim's deepest point below lower's cap plane.
      const btVector3 m = upper.axis.dot(n) > 0 ? upper.axis : -upper.axis;  // upper's axis, away from lower
      const btVector3 upper_cap = upper.centre - upper.half_length * m;
      btVector3 tilt = n - n.dot(m) * m;  // in upper's cap plane, along lower's normal
      const btScalar tilt_length = tilt.length();
      const btScalar depth_along_axis =
          -n.dot(upper_cap - cap) + (tilt_length > SIMD_EPSILON ? upper.radius * tilt_length : 0);
      const btVector3 to_axis = (upper.centre - lower.centre) - offset.dot(n) * n;
      const btScalar sideways = lower.radius + upper.radius - to_axis.length();
      if (sideways <= 0 || depth_along_axis >= sideways) return false;
      addCapContacts(lower, upper, n, cap, m, upper_cap, body1_lower, result);
      return true;
    }
    return false;
  }

  // Points of each cap's rim that lie over the other cap, paired with where they meet the other
  // cap's plane along lower's normal n. Manifold point reduction keeps four of them, deepest first.
  void addCapContacts(const Cylinder& lower, const Cylinder& upper, const btVector3& n, const btVector3& cap,
                      const btVector3& m, const btVector3& upper_cap, bool body1_lower, btManifoldResult* result) {
    if (!on_cap_) manifold_->clearManifold();
    result->setPersistentManifold(manifold_);
    const FrictionAnchors anchors(manifold_);
    const btScalar threshold = manifold_->getContactBreakingThreshold();
    constexpr btScalar kRimTolerance = 1e-4;  // m: equal coaxial rims count as over each other
    // Bullet's convention: the normal points from body1 to body0 and the point is on body1.
    auto add = [&](const btVector3& on_lower, const btVector3& on_upper, btScalar distance) {
      if (distance >= threshold) return;
      if (body1_lower) result->addContactPoint(n, on_lower, distance);
      else result->addContactPoint(-n, on_upper, distance);
    };
    constexpr int kRimPoints = 8;
    btVector3 u1, u2, l1, l2;
    btPlaneSpace1(m, u1, u2);
    btPlaneSpace1(n, l1, l2);
    for (int k = 0; k < kRimPoints; ++k) {
      const btScalar angle = SIMD_2_PI * k / kRimPoints, c = btCos(angle), s = btSin(angle);
      // Upper's rim onto lower's cap plane.
      const btVector3 on_upper = upper_cap + upper.radius * (c * u1 + s * u2);
      const btScalar distance = n.dot(on_upper - cap);
      const btVector3 below = on_upper - distance * n;
      if ((below - cap).length() <= lower.radius + kRimTolerance) add(below, on_upper, distance);
      // Lower's rim up to upper's cap plane.
      const btVector3 on_lower = cap + lower.radius * (c * l1 + s * l2);
      const btScalar up = m.dot(upper_cap - on_lower) / m.dot(n);
      const btVector3 above = on_lower + up * n;
      if ((above - upper_cap).length() <= upper.radius + kRimTolerance) add(on_lower, above, up);
    }
    if (manifold_->getNumContacts()) result->refreshContactPoints();
  }

  btPersistentManifold* manifold_ = nullptr;
  btCollisionAlgorithm* general_ = nullptr;
  bool on_cap_ = false;  // whether the last contacts were the caps'
};

}  // namespace

std::unique_ptr<btCollisionAlgorithmCreateFunc> makeCylinderPlaneAlgorithm(bool swapped) {
  auto f = std::make_unique<CylinderPlaneAlgorithm::CreateFunc>();
  f->m_swapped = swapped;
  return f;
}

std::unique_ptr<btCollisionAlgorithmCreateFunc> makeCylinderCylinderAlgorithm(
    btCollisionAlgorithmCreateFunc* general) {
  return std::make_unique<CylinderCylinderAlgorithm::CreateFunc>(general);
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
