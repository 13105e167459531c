#include "bullet_sim/laser_sensor.h"

#include <BulletCollision/NarrowPhaseCollision/btRaycastCallback.h>
#include <tinyxml2.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>
#include <sstream>

#include "bullet_sim/description_error.h"

namespace bullet_sim {

// ---------------------------------------------------------------------------------------------
// Parsing
// ---------------------------------------------------------------------------------------------
namespace {

using tinyxml2::XMLElement;

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r\n");
  if (b == std::string::npos) return "";
  return s.substr(b, s.find_last_not_of(" \t\r\n") - b + 1);
}

std::string fmt(double v) {
  std::ostringstream out;
  out << v;
  return out.str();
}

// "<sensor name='lidar'>", "<gazebo reference='ray'>", "<range>": one step of an element path.
std::string describe(const XMLElement* e) {
  std::string s = std::string("<") + e->Name();
  if (const char* n = e->Attribute("name")) s += std::string(" name='") + n + "'";
  if (const char* r = e->Attribute("reference")) s += std::string(" reference='") + r + "'";
  return s + ">";
}

// Locale-independent and strict: the whole text must be the number (a leading '+' is allowed).
bool toDouble(const std::string& text, double& out) {
  const char* b = text.data();
  const char* e = b + text.size();
  if (b != e && *b == '+') ++b;
  const auto r = std::from_chars(b, e, out);
  return b != e && r.ec == std::errc() && r.ptr == e && std::isfinite(out);
}

// A value and how it was written ("'abc'"), or a note that the default was used, for messages.
struct Number {
  double value;
  std::string shown;
};

// Reads the children of one <sensor>; every failure names source, element path and expectation.
class Reader {
 public:
  explicit Reader(std::string source) : source_(std::move(source)) {}

  [[noreturn]] void fail(const std::string& where, const std::string& what) const {
    throw DescriptionError(source_ + ": " + where + ": " + what);
  }

  // Trimmed text of child NAME into `out`; false (and `out` untouched) when there is no such child.
  bool text(const XMLElement* parent, const char* name, std::string& out) const {
    const XMLElement* e = parent ? parent->FirstChildElement(name) : nullptr;
    if (!e) return false;
    out = trim(e->GetText() ? e->GetText() : "");
    return true;
  }

  // Child NAME as a finite number (fallback when missing), else "expected a number[ expectation], got 'text'".
  Number number(const XMLElement* parent, const char* name, double fallback, const std::string& where,
                const std::string& expectation = "") const {
    std::string t;
    if (!text(parent, name, t)) return {fallback, "(missing, default " + fmt(fallback) + ")"};
    double v = 0;
    if (!toDouble(t, v)) fail(where + "/<" + name + ">", expected(expectation) + ", got '" + t + "'");
    return {v, "'" + t + "'"};
  }

  // A number that must also satisfy `ok`, e.g. expectation "> <min> (0.05)".
  template <class Pred>
  double checked(const XMLElement* parent, const char* name, double fallback, const std::string& where,
                 Pred ok, const std::string& expectation) const {
    const Number n = number(parent, name, fallback, where, expectation);
    if (!ok(n.value)) fail(where + "/<" + name + ">", expected(expectation) + ", got " + n.shown);
    return n.value;
  }

  int count(const XMLElement* parent, const char* name, int fallback, const std::string& where) const {
    std::string t;
    if (!text(parent, name, t)) return fallback;
    long v = 0;
    const auto r = std::from_chars(t.data(), t.data() + t.size(), v);
    if (t.empty() || r.ec != std::errc() || r.ptr != t.data() + t.size() || v < 1 || v > 1000000)
      fail(where + "/<" + name + ">", "expected an integer >= 1 (at most 1000000), got '" + t + "'");
    return static_cast<int>(v);
  }

  bool boolean(const XMLElement* parent, const char* name, bool fallback, const std::string& where) const {
    std::string t;
    if (!text(parent, name, t)) return fallback;
    if (t == "true" || t == "1") return true;
    if (t == "false" || t == "0") return false;
    fail(where + "/<" + name + ">", "expected true, false, 1 or 0, got '" + t + "'");
  }

  // <pose>x y z roll pitch yaw</pose>, fixed-axis RPY: R = Rz(yaw) * Ry(pitch) * Rx(roll).
  Eigen::Isometry3d pose(const XMLElement* parent, const std::string& where) const {
    Eigen::Isometry3d out = Eigen::Isometry3d::Identity();
    std::string t;
    if (!text(parent, "pose", t)) return out;
    std::istringstream in(t);
    std::vector<double> v;
    bool numbers = true;
    for (std::string word; in >> word;) {
      double d = 0;
      numbers = numbers && toDouble(word, d);
      v.push_back(d);
    }
    if (!numbers || v.size() != 6) fail(where + "/<pose>", "expected 6 numbers 'x y z roll pitch yaw', got '" + t + "'");
    out.translation() = Eigen::Vector3d(v[0], v[1], v[2]);
    out.linear() = (Eigen::AngleAxisd(v[5], Eigen::Vector3d::UnitZ()) *
                    Eigen::AngleAxisd(v[4], Eigen::Vector3d::UnitY()) *
                    Eigen::AngleAxisd(v[3], Eigen::Vector3d::UnitX())).toRotationMatrix();
    return out;
  }

 private:
  static std::string expected(const std::string& expectation) {
    return expectation.empty() ? "expected a number" : "expected a number " + expectation;
  }
  std::string source_;
};

const auto kNonNegative = [](double v) { return v >= 0; };

bool isLaserPlugin(const std::string& filename) {
  const std::string base = filename.substr(filename.find_last_of('/') + 1);  // npos + 1 == 0
  return base == "libgazebo_ros_laser.so" || base == "libgazebo_ros_gpu_laser.so";
}

// <horizontal> or <vertical>: samples, resolution, min_angle <= max_angle.
void readSweep(const Reader& r, const XMLElement* e, const std::string& where, int& samples, double& resolution,
               double& min_angle, double& max_angle) {
  samples = r.count(e, "samples", samples, where);
  resolution = r.checked(e, "resolution", resolution, where, [](double v) { return v > 0; }, "> 0");
  if (static_cast<int>(samples * resolution + 1e-9) < 1)
    r.fail(where + "/<resolution>", "expected samples * resolution >= 1, got " + fmt(samples) + " * " + fmt(resolution));
  min_angle = r.number(e, "min_angle", min_angle, where).value;
  const double lo = min_angle;
  max_angle = r.checked(e, "max_angle", max_angle, where, [lo](double v) { return v >= lo; },
                        ">= <min_angle> (" + fmt(lo) + ")");
}

LaserConfig readSensor(const Reader& r, const XMLElement* sensor, const std::string& where, const std::string& link) {
  LaserConfig c;
  c.name = sensor->Attribute("name") ? sensor->Attribute("name") : "";
  c.type = sensor->Attribute("type");
  c.link = link;
  c.pose = r.pose(sensor, where);
  c.update_rate = r.checked(sensor, "update_rate", c.update_rate, where, kNonNegative, ">= 0");
  c.always_on = r.boolean(sensor, "always_on", c.always_on, where);
  c.visualize = r.boolean(sensor, "visualize", c.visualize, where);

  const XMLElement* ray = sensor->FirstChildElement("ray");
  const std::string ray_where = where + "/<ray>";
  const XMLElement* scan = ray ? ray->FirstChildElement("scan") : nullptr;
  const XMLElement* horizontal = scan ? scan->FirstChildElement("horizontal") : nullptr;
  readSweep(r, horizontal, ray_where + "/<scan>/<horizontal>", c.samples, c.resolution, c.min_angle, c.max_angle);
  if (const XMLElement* vertical = scan ? scan->FirstChildElement("vertical") : nullptr)
    readSweep(r, vertical, ray_where + "/<scan>/<vertical>", c.vertical_samples, c.vertical_resolution,
              c.vertical_min_angle, c.vertical_max_angle);

  const XMLElement* range = ray ? ray->FirstChildElement("range") : nullptr;
  const std::string range_where = ray_where + "/<range>";
  c.range_min = r.checked(range, "min", c.range_min, range_where, kNonNegative, ">= 0");
  const double lo = c.range_min;
  c.range_max = r.checked(range, "max", c.range_max, range_where, [lo](double v) { return v > lo; },
                          "> <min> (" + fmt(lo) + ")");
  c.range_resolution = r.checked(range, "resolution", c.range_resolution, range_where, kNonNegative, ">= 0");

  if (const XMLElement* noise = ray ? ray->FirstChildElement("noise") : nullptr) {
    const std::string noise_where = ray_where + "/<noise>";
    c.noise_type = "gaussian";  // ray.sdf's default type once <noise> is given
    r.text(noise, "type", c.noise_type);
    if (c.noise_type != "none" && c.noise_type != "gaussian" && c.noise_type != "gaussian_quantized")
      r.fail(noise_where + "/<type>", "expected one of none, gaussian, gaussian_quantized, got '" + c.noise_type + "'");
    c.noise_mean = r.number(noise, "mean", 0.0, noise_where).value;
    c.noise_stddev = r.checked(noise, "stddev", 0.0, noise_where, kNonNegative, ">= 0");
  }

  for (const XMLElement* p = sensor->FirstChildElement("plugin"); p; p = p->NextSiblingElement("plugin")) {
    const char* filename = p->Attribute("filename");
    if (!filename || !isLaserPlugin(filename)) continue;
    const std::string plugin_where = where + "/" + describe(p);
    c.plugin_filename = filename;
    c.plugin_name = p->Attribute("name") ? p->Attribute("name") : "";
    r.text(p, "topicName", c.topic_name);
    r.text(p, "frameName", c.frame_name);
    c.robot_namespace_given = r.text(p, "robotNamespace", c.robot_namespace);
    c.gaussian_noise = r.checked(p, "gaussianNoise", 0.0, plugin_where, kNonNegative, ">= 0");
    break;  // <hokuyoMinIntensity> and anything else is ignored, as by gazebo_ros_laser
  }
  return c;
}

bool isRaySensor(const XMLElement* e) {
  const char* type = e->Attribute("type");
  return type && (std::string(type) == "ray" || std::string(type) == "gpu_ray");
}

}  // namespace

std::vector<LaserConfig> parseLaserSensors(const std::vector<GazeboExtension>& blocks, const std::string& source) {
  const Reader reader(source);
  std::vector<LaserConfig> out;
  for (const GazeboExtension& block : blocks) {
    const std::string block_where =
        block.reference.empty() ? "<gazebo>" : "<gazebo reference='" + block.reference + "'>";
    if (trim(block.xml).empty()) continue;
    tinyxml2::XMLDocument doc;
    if (doc.Parse(block.xml.c_str(), block.xml.size()) != tinyxml2::XML_SUCCESS)
      reader.fail(block_where, "malformed XML at line " + std::to_string(doc.ErrorLineNum()) + ": " + doc.ErrorStr());

    for (const XMLElement* root = doc.FirstChildElement(); root; root = root->NextSiblingElement()) {
      // URDF: <gazebo reference="link"><sensor .../></gazebo>; SDF: the <sensor> itself.
      std::vector<std::pair<const XMLElement*, std::string>> sensors;
      if (std::string(root->Name()) == "sensor") {
        sensors.emplace_back(root, block.reference.empty() ? "" : "<link name='" + block.reference + "'>/");
      } else if (std::string(root->Name()) == "gazebo") {
        for (const XMLElement* s = root->FirstChildElement("sensor"); s; s = s->NextSiblingElement("sensor"))
          sensors.emplace_back(s, describe(root) + "/");
      }
      for (const auto& [sensor, prefix] : sensors) {
        if (!isRaySensor(sensor)) continue;
        const std::string where = prefix + describe(sensor);
        if (block.reference.empty())
          reader.fail(where, "expected the sensor's <gazebo> block to name its link with reference='LINK'");
        out.push_back(readSensor(reader, sensor, where, block.reference));
      }
    }
  }
  return out;
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
