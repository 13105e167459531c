#include "bullet_sim_core/laser_sensor.h"

#include <BulletCollision/NarrowPhaseCollision/btRaycastCallback.h>

#include <algorithm>
#include <array>
#include <climits>
#include <charconv>
#include <cmath>
#include <limits>
#include <sstream>

#include "bullet_sim_core/description_error.h"

namespace bullet_sim {

// ---------------------------------------------------------------------------------------------
// Parsing
// ---------------------------------------------------------------------------------------------
namespace {

// <horizontal> or <vertical>: samples, resolution, min_angle <= max_angle.
void readSweep(const SdfElement& e, int& samples, double& resolution, double& min_angle, double& max_angle) {
  samples = static_cast<int>(e.integer("samples", samples, 1, 1000000));
  resolution = e.number("resolution", resolution, positive());
  if (static_cast<int>(samples * resolution + 1e-9) < 1)
    e.child("resolution").fail("expected samples * resolution >= 1, got " + formatNumber(samples) + " * " +
                               formatNumber(resolution));
  min_angle = e.number("min_angle", min_angle);
  max_angle = e.number("max_angle", max_angle, atLeast(min_angle, "<min_angle>"));
}

}  // namespace

bool isLaserSensor(const SensorDescription& sensor) { return sensor.type == "ray" || sensor.type == "gpu_ray"; }

LaserConfig parseLaserSensor(const SensorDescription& sensor) {
  const SdfElement& e = sensor.element;
  LaserConfig c;
  c.name = sensor.name;
  c.type = sensor.type;
  c.link = sensor.link;
  c.pose = e.pose();
  c.update_rate = e.number("update_rate", c.update_rate, nonNegative());
  c.always_on = e.boolean("always_on", c.always_on);
  c.visualize = e.boolean("visualize", c.visualize);

  const SdfElement ray = e.child("ray");
  const SdfElement scan = ray.child("scan");
  readSweep(scan.child("horizontal"), c.samples, c.resolution, c.min_angle, c.max_angle);
  if (const SdfElement vertical = scan.child("vertical"))
    readSweep(vertical, c.vertical_samples, c.vertical_resolution, c.vertical_min_angle, c.vertical_max_angle);

  const SdfElement range = ray.child("range");
  c.range_min = range.number("min", c.range_min, nonNegative());
  c.range_max = range.number("max", c.range_max, greaterThan(c.range_min, "<min>"));
  c.range_resolution = range.number("resolution", c.range_resolution, nonNegative());

  if (const SdfElement noise = ray.child("noise")) {
    c.noise_type = noise.string("type", "gaussian");  // ray.sdf's default type once <noise> is given
    if (c.noise_type != "none" && c.noise_type != "gaussian" && c.noise_type != "gaussian_quantized")
      noise.child("type").fail("expected one of none, gaussian, gaussian_quantized, got '" + c.noise_type + "'");
    c.noise_mean = noise.number("mean", 0.0);
    c.noise_stddev = noise.number("stddev", 0.0, nonNegative());
  }
  return c;
}

// ---------------------------------------------------------------------------------------------
// Scanning
// ---------------------------------------------------------------------------------------------
namespace {

// The primitives URDF/SDF geometry becomes (box, cylinder, sphere, plane) get a closed-form ray
// test: exact, and tens of times cheaper than btCollisionWorld::rayTestSingle (1-5 us per call
// for a box or cylinder; a whole 720-beam scan here costs ~60 us), whose convex casts are
// approximate (in single precision the default sub-simplex cast even reports hits up to a metre
// short near the edges of 1 mm-margin boxes). Anything else (triangle meshes, convex hulls, ...)
// goes through rayTestSingle.
enum class Kind { Box, Sphere, Cylinder, Plane, Other };

// One leaf shape (compounds are flattened) that some beam of this scan may hit.
struct Candidate {
  const btCollisionObject* object;
  const btCollisionShape* shape;
  Kind kind;
  btTransform shape_in_world;
  btMatrix3x3 world_to_local;  // rotation only: directions into the shape frame
  btVector3 origin_local;      // the sensor origin in the shape frame
  btVector3 aabb_min, aabb_max;
  btScalar distance;           // sensor origin to the AABB: no beam hits this shape any closer
  btVector3 size{0, 0, 0};     // Box: half extents; Sphere: x = radius; Cylinder: x = radius, y = half height
  int axis = 2;                // Cylinder: its axis; Plane: unused
  btScalar plane_constant = 0; // Plane: n . x = c, with n in `size`; solid where n . x < c
  // The beams that can meet the AABB: [first, last] and [first2, last2] (a span across the scan's
  // ends has two parts); all of them unless the scan is flat.
  int first = 0, last = INT_MAX, first2 = 1, last2 = 0;
  bool mayHit(int beam) const { return (beam >= first && beam <= last) || (beam >= first2 && beam <= last2); }
};

// Slab test of the segment o + t d, t in [0, t_max], against an AABB (inv_d = 1 / d per axis).
bool segmentHitsBox(const btVector3& o, const btVector3& d, const btVector3& inv_d, const btVector3& lo,
                    const btVector3& hi, btScalar t_max, btScalar& t_enter) {
  btScalar t0 = 0, t1 = t_max;
  for (int k = 0; k < 3; ++k) {
    if (d[k] == 0) {
      if (o[k] < lo[k] || o[k] > hi[k]) return false;
      continue;
    }
    btScalar a = (lo[k] - o[k]) * inv_d[k], b = (hi[k] - o[k]) * inv_d[k];
    if (a > b) std::swap(a, b);
    t0 = std::max(t0, a);
    t1 = std::min(t1, b);
    if (t0 > t1) return false;
  }
  t_enter = t0;  // 0 when o is inside
  return true;
}

btVector3 inverse(const btVector3& d) {
  const btScalar inf = std::numeric_limits<btScalar>::infinity();
  return btVector3(d.x() != 0 ? 1 / d.x() : inf, d.y() != 0 ? 1 / d.y() : inf, d.z() != 0 ? 1 / d.z() : inf);
}

bool hitSphere(const btVector3& o, const btVector3& d, btScalar r, btScalar t_max, btScalar& t) {
  const btScalar b = o.dot(d), c = o.length2() - r * r;
  if (c <= 0) return t = 0, true;  // inside
  const btScalar disc = b * b - c;
  if (b >= 0 || disc < 0) return false;  // pointing away, or missing
  t = -b - std::sqrt(disc);
  return t <= t_max;
}

// Finite cylinder along local axis a (radius r, half height h); d is a unit vector.
bool hitCylinder(const btVector3& o, const btVector3& d, int a, btScalar r, btScalar h, btScalar t_max,
                 btScalar& t) {
  const int i = (a + 1) % 3, j = (a + 2) % 3;
  const btScalar radial2 = o[i] * o[i] + o[j] * o[j];
  if (radial2 <= r * r && std::abs(o[a]) <= h) return t = 0, true;  // inside
  btScalar best = std::numeric_limits<btScalar>::infinity();
  // Side: |(o + t d)_ij| = r, entering root.
  const btScalar A = d[i] * d[i] + d[j] * d[j], B = o[i] * d[i] + o[j] * d[j], C = radial2 - r * r;
  if (A > 0) {
    const btScalar disc = B * B - A * C;
    if (disc >= 0) {
      const btScalar ts = (-B - std::sqrt(disc)) / A;
      if (ts >= 0 && std::abs(o[a] + ts * d[a]) <= h) best = ts;
    }
  }
  // Caps: the face facing the origin.
  if (d[a] != 0) {
    const btScalar cap = o[a] > 0 ? h : -h;
    const btScalar tc = (cap - o[a]) / d[a];
    if (tc >= 0 && tc < best) {
      const btScalar pi = o[i] + tc * d[i], pj = o[j] + tc * d[j];
      if (pi * pi + pj * pj <= r * r) best = tc;
    }
  }
  if (best > t_max) return false;
  t = best;
  return true;
}

bool hitPlane(const btVector3& o, const btVector3& d, const btVector3& n, btScalar c, btScalar t_max, btScalar& t) {
  const btScalar s = n.dot(o) - c;
  if (s < 0) return t = 0, true;  // below the plane: inside the solid half-space
  const btScalar dn = n.dot(d);
  if (dn >= 0) return false;
  t = -s / dn;
  return t <= t_max;
}

// Distance from p to the box [lo, hi] (0 inside).
btScalar distanceToBox(const btVector3& p, const btVector3& lo, const btVector3& hi) {
  btVector3 gap(0, 0, 0);
  for (int k = 0; k < 3; ++k) gap[k] = std::max({lo[k] - p[k], btScalar(0), p[k] - hi[k]});
  return gap.length();
}

bool overlaps(const btVector3& a_lo, const btVector3& a_hi, const btVector3& b_lo, const btVector3& b_hi) {
  for (int k = 0; k < 3; ++k)
    if (a_lo[k] > b_hi[k] || b_lo[k] > a_hi[k]) return false;
  return true;
}

// Adds the leaves of `shape` (at `t` in the world) whose AABB meets the query box.
void addLeaves(const btCollisionObject* object, const btCollisionShape* shape, const btTransform& t,
               const btVector3& origin, const btVector3& q_lo, const btVector3& q_hi, std::vector<Candidate>& out) {
  if (shape->isCompound()) {
    const auto* compound = static_cast<const btCompoundShape*>(shape);
    for (int i = 0; i < compound->getNumChildShapes(); ++i)
      addLeaves(object, compound->getChildShape(i), t * compound->getChildTransform(i), origin, q_lo, q_hi, out);
    return;
  }
  if (shape->getShapeType() == EMPTY_SHAPE_PROXYTYPE) return;
  Candidate c;
  shape->getAabb(t, c.aabb_min, c.aabb_max);
  if (!overlaps(c.aabb_min, c.aabb_max, q_lo, q_hi)) return;
  c.object = object;
  c.shape = shape;
  c.kind = Kind::Other;
  c.shape_in_world = t;
  c.world_to_local = t.getBasis().transpose();
  c.origin_local = t.invXform(origin);
  c.distance = distanceToBox(origin, c.aabb_min, c.aabb_max);
  switch (shape->getShapeType()) {
    case BOX_SHAPE_PROXYTYPE:
      c.kind = Kind::Box;
      c.size = static_cast<const btBoxShape*>(shape)->getHalfExtentsWithMargin();
      break;
    case SPHERE_SHAPE_PROXYTYPE:
      c.kind = Kind::Sphere;
      c.size.setX(static_cast<const btSphereShape*>(shape)->getRadius());
      break;
    case CYLINDER_SHAPE_PROXYTYPE: {
      const auto* cyl = static_cast<const btCylinderShape*>(shape);
      const btVector3 half = cyl->getHalfExtentsWithMargin();
      c.kind = Kind::Cylinder;
      c.axis = cyl->getUpAxis();
      c.size = btVector3(half[c.axis == 0 ? 1 : 0], half[c.axis], 0);
      break;
    }
    case STATIC_PLANE_PROXYTYPE: {
      const auto* plane = static_cast<const btStaticPlaneShape*>(shape);
      c.kind = Kind::Plane;
      c.size = plane->getPlaneNormal();
      c.plane_constant = plane->getPlaneConstant();
      break;
    }
    default:
      break;
  }
  out.push_back(c);
}

// For a flat scan (beams at yaw min_angle + i * increment in the sensor's xy plane): which beams
// can meet the candidate's AABB. Seen from the sensor, the box's corners spread over an arc; if
// its widest gap exceeds half a turn the box lies to one side and only the beams in the rest of
// the circle (widened by a beam for rounding) can reach it. Otherwise the sensor is over or in
// the box's footprint, and every beam may.
void limitToBeamsFacing(Candidate& c, const btVector3& origin, const btMatrix3x3& basis, double min_angle,
                        double increment, int count) {
  if (count < 2 || increment <= 0) return;
  std::array<double, 8> angle;
  for (int k = 0; k < 8; ++k) {
    const btVector3 corner((k & 1) ? c.aabb_max.x() : c.aabb_min.x(), (k & 2) ? c.aabb_max.y() : c.aabb_min.y(),
                           (k & 4) ? c.aabb_max.z() : c.aabb_min.z());
    const btVector3 p = basis.transpose() * (corner - origin);
    if (!std::isfinite(p.x()) || !std::isfinite(p.y())) return;  // unbounded (a tilted plane)
    angle[k] = std::atan2(p.y(), p.x());
  }
  std::sort(angle.begin(), angle.end());
  double gap = angle[0] + 2 * M_PI - angle[7], gap_end = angle[0];  // the gap across +-pi
  for (int k = 1; k < 8; ++k)
    if (angle[k] - angle[k - 1] > gap) gap = angle[k] - angle[k - 1], gap_end = angle[k];
  if (gap <= M_PI) return;
  // The arc [from, from + width] holds every corner's direction.
  const double from = gap_end - increment, width = 2 * M_PI - gap + 2 * increment;
  // Beam i's yaw is min_angle + i * increment; the scan spans at most a turn, so the arc meets it
  // as shifted by 0 or +-2 pi, at most twice.
  int spans = 0;
  for (double shift : {-2 * M_PI, 0.0, 2 * M_PI}) {
    const double lo = (from + shift - min_angle) / increment, hi = (from + width + shift - min_angle) / increment;
    const int first = std::max(0, static_cast<int>(std::ceil(lo))), last = std::min(count - 1, static_cast<int>(hi));
    if (first > last) continue;
    if (spans++ == 0) c.first = first, c.last = last;
    else c.first2 = first, c.last2 = last;
  }
  if (spans == 0) c.first = 1, c.last = 0;  // the box is outside the scan's angles
}

// Closest hit of the beam o + t d (unit d), t in [0, t_max], with one candidate.
bool hitCandidate(const Candidate& c, const btVector3& o, const btVector3& d, btScalar t_max, btScalar& t) {
  const btVector3 dl = c.world_to_local * d;
  const btVector3& ol = c.origin_local;
  switch (c.kind) {
    case Kind::Box:
      return segmentHitsBox(ol, dl, inverse(dl), -c.size, c.size, t_max, t);
    case Kind::Sphere:
      return hitSphere(ol, dl, c.size.x(), t_max, t);
    case Kind::Cylinder:
      return hitCylinder(ol, dl, c.axis, c.size.x(), c.size.y(), t_max, t);
    case Kind::Plane:
      return hitPlane(ol, dl, c.size, c.plane_constant, t_max, t);
    case Kind::Other: {
      btTransform from, to;
      from.setIdentity();
      to.setIdentity();
      from.setOrigin(o);
      to.setOrigin(o + d * t_max);
      btCollisionWorld::ClosestRayResultCallback cb(from.getOrigin(), to.getOrigin());
#ifndef BT_USE_DOUBLE_PRECISION
      // In single precision the default sub-simplex cast misses by centimetres near edges and GJK
      // is within ~2 mm; in double precision the sub-simplex cast is the exact (and faster) one.
      cb.m_flags = btTriangleRaycastCallback::kF_UseGjkConvexCastRaytest;
#endif
      // rayTestSingle only reads the object (it hands it to the callback), but takes it non-const.
      btCollisionWorld::rayTestSingle(from, to, const_cast<btCollisionObject*>(c.object), c.shape,
                                      c.shape_in_world, cb);
      if (!cb.hasHit()) return false;
      t = cb.m_closestHitFraction * t_max;
      return true;
    }
  }
  return false;
}

struct ObjectCollector : btBroadphaseAabbCallback {
  std::vector<const btCollisionObject*> objects;
  bool process(const btBroadphaseProxy* proxy) override {
    objects.push_back(static_cast<const btCollisionObject*>(proxy->m_clientObject));
    return true;
  }
};

}  // namespace

LaserScanner::LaserScanner(LaserConfig config) : config_(std::move(config)) {
  // Gazebo's RaySensor publishes RangeCount() = int(samples * resolution) readings spread over
  // [min_angle, max_angle] (interpolating between its rays); we cast one ray per reading.
  const int count = std::max(1, static_cast<int>(config_.samples * config_.resolution + 1e-9));
  angle_increment_ = count > 1 ? (config_.max_angle - config_.min_angle) / (count - 1) : 0.0;
  // As Gazebo's MultiRayShape: a single beam looks along +x (yaw 0) whatever min_angle says, and
  // a single layer is at pitch 0; with several layers we scan layer 0, at the vertical min_angle.
  pitch_ = config_.vertical_samples > 1 ? btScalar(config_.vertical_min_angle) : btScalar(0);
  directions_.reserve(count);
  for (int i = 0; i < count; ++i) {
    const double yaw = count > 1 ? config_.min_angle + i * angle_increment_ : 0.0;
    directions_.emplace_back(std::cos(pitch_) * std::cos(yaw), std::cos(pitch_) * std::sin(yaw), std::sin(pitch_));
  }
}

void LaserScanner::scan(const btCollisionWorld& world, const btTransform& sensor_in_world,
                        const std::vector<const btCollisionObject*>& ignore, std::mt19937& rng,
                        std::vector<float>& ranges_out) const {
  const btScalar reach = btScalar(config_.range_max);
  const btVector3 origin = sensor_in_world.getOrigin();
  const btMatrix3x3& basis = sensor_in_world.getBasis();

  // 1. What the scan can reach: a disc in the sensor's xy plane for a flat scan (so a
  // horizontal scanner never even looks at the floor or ceiling), else a sphere.
  btVector3 extent(reach, reach, reach);
  if (pitch_ == 0) {
    const btVector3 normal = basis.getColumn(2);
    for (int k = 0; k < 3; ++k) extent[k] = reach * std::sqrt(std::max(btScalar(0), 1 - normal[k] * normal[k]));
  }
  extent += btVector3(1e-3, 1e-3, 1e-3);  // rounding margin for shapes the disc just touches
  const btVector3 q_lo = origin - extent, q_hi = origin + extent;

  // 2. The objects whose broadphase AABB overlaps that, minus the ignored ones, as leaf shapes
  // sorted by how close their AABB comes to the sensor. aabbTest is non-const in Bullet's
  // interface but only reads the broadphase tree.
  ObjectCollector collector;
  const_cast<btCollisionWorld&>(world).getBroadphase()->aabbTest(q_lo, q_hi, collector);
  std::vector<Candidate> candidates;
  candidates.reserve(collector.objects.size());
  for (const btCollisionObject* object : collector.objects) {
    if (!object->getCollisionShape() || std::find(ignore.begin(), ignore.end(), object) != ignore.end()) continue;
    addLeaves(object, object->getCollisionShape(), object->getWorldTransform(), origin, q_lo, q_hi, candidates);
  }
  std::sort(candidates.begin(), candidates.end(),
            [](const Candidate& a, const Candidate& b) { return a.distance < b.distance; });
  const int count = static_cast<int>(directions_.size());
  if (pitch_ == 0)
    for (Candidate& c : candidates) limitToBeamsFacing(c, origin, basis, config_.min_angle, angle_increment_, count);

  // 3. Each beam against the candidates, nearest AABB first; once a candidate's AABB is
  // farther than the best hit so far, none of the rest can do better.
  const float inf = std::numeric_limits<float>::infinity();
  const bool noisy = config_.noise_type != "none" && (config_.noise_stddev > 0 || config_.noise_mean != 0);
  std::normal_distribution<double> gauss(0.0, 1.0);
  ranges_out.resize(directions_.size());
  for (size_t i = 0; i < directions_.size(); ++i) {
    const btVector3 d = basis * directions_[i];
    const btVector3 inv_d = inverse(d);
    btScalar best = reach;
    bool hit = false;
    for (const Candidate& c : candidates) {
      if (c.distance >= best) break;
      if (!c.mayHit(static_cast<int>(i))) continue;
      btScalar t = 0;
      if (!segmentHitsBox(origin, d, inv_d, c.aabb_min, c.aabb_max, best, t)) continue;
      if (hitCandidate(c, origin, d, best, t) && t < best) {
        best = t;
        hit = true;
      }
    }
    // 4. REP 117 and Gazebo's RaySensor: >= max -> +inf, <= min -> -inf, else noise then clamp.
    // Gazebo starts its rays at range_min, so an object nearer than that is usually not seen at
    // all (the ray looks past or through it); we report it as -inf ("too close"), as REP 117
    // intends, rather than whatever lies behind it.
    double r = best;
    if (!hit || r >= config_.range_max) {
      ranges_out[i] = inf;
      continue;
    }
    if (r <= config_.range_min) {
      ranges_out[i] = -inf;
      continue;
    }
    if (noisy) r += config_.noise_mean + (config_.noise_stddev > 0 ? config_.noise_stddev * gauss(rng) : 0.0);
    if (config_.range_resolution > 0) r = std::round(r / config_.range_resolution) * config_.range_resolution;
    ranges_out[i] = static_cast<float>(std::clamp(r, config_.range_min, config_.range_max));
  }
}

}  // namespace bullet_sim
