// SDF (.world, model.sdf) -> WorldDescription / ModelDescription. See sdf_world_parser.h for
// the supported subset and how SDF's links map onto our single-link models.
#include "bullet_sim/sdf_world_parser.h"

#include <tinyxml2.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <locale>
#include <map>
#include <optional>
#include <set>
#include <sstream>

#include "bullet_sim/description_error.h"

namespace fs = std::filesystem;
using tinyxml2::XMLElement;

namespace bullet_sim {
namespace {

// Gazebo's own ground_plane model (without its friction of mu 100 / mu2 50: Bullet combines
// the two bodies' coefficients differently from ODE, so the neutral default 1 is kept).
const char* const kGroundPlaneSdf = R"(<sdf version="1.6">
  <model name="ground_plane">
    <static>true</static>
    <link name="link">
      <collision name="collision">
        <geometry><plane><normal>0 0 1</normal><size>100 100</size></plane></geometry>
      </collision>
      <visual name="visual">
        <geometry><plane><normal>0 0 1</normal><size>100 100</size></plane></geometry>
        <material><script><name>Gazebo/Grey</name></script></material>
      </visual>
    </link>
  </model>
</sdf>)";

// Diffuse colours of the common materials of Gazebo's media/materials/scripts/gazebo.material.
const std::map<std::string, std::array<float, 4>>& gazeboMaterials() {
  static const std::map<std::string, std::array<float, 4>> table = {
      {"Gazebo/Grey", {0.7f, 0.7f, 0.7f, 1}},         {"Gazebo/Gray", {0.7f, 0.7f, 0.7f, 1}},
      {"Gazebo/DarkGrey", {0.35f, 0.35f, 0.35f, 1}},  {"Gazebo/LightGrey", {0.85f, 0.85f, 0.85f, 1}},
      {"Gazebo/White", {1, 1, 1, 1}},                 {"Gazebo/Black", {0, 0, 0, 1}},
      {"Gazebo/FlatBlack", {0.1f, 0.1f, 0.1f, 1}},    {"Gazebo/Red", {1, 0, 0, 1}},
      {"Gazebo/RedBright", {0.87f, 0.26f, 0.07f, 1}}, {"Gazebo/Green", {0, 1, 0, 1}},
      {"Gazebo/Blue", {0, 0, 1, 1}},                  {"Gazebo/SkyBlue", {0.53f, 0.81f, 0.92f, 1}},
      {"Gazebo/Yellow", {1, 1, 0, 1}},                {"Gazebo/ZincYellow", {0.97f, 0.95f, 0.21f, 1}},
      {"Gazebo/DarkYellow", {0.7f, 0.7f, 0, 1}},      {"Gazebo/Purple", {1, 0, 1, 1}},
      {"Gazebo/Turquoise", {0, 1, 1, 1}},             {"Gazebo/Orange", {1, 0.51f, 0.05f, 1}},
      {"Gazebo/Indigo", {0.33f, 0, 0.5f, 1}},         {"Gazebo/Gold", {0.8f, 0.65f, 0.2f, 1}},
      {"Gazebo/Wood", {0.6f, 0.4f, 0.2f, 1}},         {"Gazebo/WoodFloor", {0.65f, 0.5f, 0.35f, 1}},
      {"Gazebo/Bricks", {0.6f, 0.3f, 0.2f, 1}},       {"Gazebo/PaintedWall", {0.9f, 0.9f, 0.85f, 1}},
      {"Gazebo/BlueTransparent", {0, 0, 1, 0.5f}},    {"Gazebo/GreenTransparent", {0, 1, 0, 0.5f}},
      {"Gazebo/RedTransparent", {1, 0, 0, 0.5f}},     {"Gazebo/GreyTransparent", {0.5f, 0.5f, 0.5f, 0.5f}},
      {"Gazebo/BlackTransparent", {0, 0, 0, 0.5f}},   {"Gazebo/Residential", {0.8f, 0.8f, 0.75f, 1}},
  };
  return table;
}

// Where we are: errors name source (the file) and the element path inside it.
struct Ctx {
  std::string source;
  std::string base_dir;  // for relative URIs
  const ResourceResolver& resolver;
};

std::string describe(const XMLElement* e) {
  const char* name = e->Attribute("name");
  return std::string("<") + e->Name() + (name ? std::string(" name='") + name + "'" : "") + ">";
}

// "<world name='w'>/<model name='m'>/<link name='l'>"; the <sdf> root adds nothing useful.
std::string elementPath(const XMLElement* e) {
  std::string path;
  for (; e; e = e->Parent() ? e->Parent()->ToElement() : nullptr) {
    const bool is_root = !e->Parent() || !e->Parent()->ToElement();
    if (is_root && std::string(e->Name()) == "sdf") break;
    path = describe(e) + (path.empty() ? "" : "/") + path;
  }
  return path.empty() ? "<sdf>" : path;
}

[[noreturn]] void fail(const Ctx& c, const XMLElement* e, const std::string& what) {
  throw DescriptionError(c.source + ": " + elementPath(e) + ": " + what);
}

std::string text(const XMLElement* e) {
  std::string s = e->GetText() ? e->GetText() : "";
  s.erase(0, s.find_first_not_of(" \t\r\n"));
  s.erase(s.find_last_not_of(" \t\r\n") + 1);
  return s;
}

const XMLElement* required(const Ctx& c, const XMLElement* parent, const char* name) {
  const XMLElement* e = parent->FirstChildElement(name);
  if (!e) fail(c, parent, std::string("missing required element <") + name + ">");
  return e;
}

// Whitespace-separated finite numbers, between min_count and max_count of them. from_chars
// is used because it is strict and does not depend on the C locale.
std::vector<double> numbers(const Ctx& c, const XMLElement* e, size_t min_count, size_t max_count) {
  const std::string s = text(e);
  std::vector<double> out;
  bool ok = true;
  std::istringstream tokens(s);
  for (std::string tok; ok && tokens >> tok;) {
    const char* first = tok.c_str() + (tok[0] == '+' ? 1 : 0);
    double v = 0;
    auto [ptr, ec] = std::from_chars(first, tok.c_str() + tok.size(), v);
    ok = ec == std::errc() && ptr == tok.c_str() + tok.size() && std::isfinite(v);
    out.push_back(v);
  }
  if (!ok || out.size() < min_count || out.size() > max_count) {
    std::string expected = min_count == 1 && max_count == 1 ? "a finite number"
                           : std::to_string(min_count) +
                                 (max_count != min_count ? " or " + std::to_string(max_count) : "") +
                                 " finite numbers";
    fail(c, e, "expected " + expected + ", found '" + s + "'");
  }
  return out;
}

enum class Sign { Any, NonNegative, Positive };

void checkSign(const Ctx& c, const XMLElement* e, double v, Sign sign) {
  if (sign == Sign::NonNegative && v < 0) fail(c, e, "expected a non-negative value, found '" + text(e) + "'");
  if (sign == Sign::Positive && v <= 0) fail(c, e, "expected a positive value, found '" + text(e) + "'");
}

double number(const Ctx& c, const XMLElement* e, Sign sign = Sign::Any) {
  const double v = numbers(c, e, 1, 1)[0];
  checkSign(c, e, v, sign);
  return v;
}

Eigen::Vector3d vector3(const Ctx& c, const XMLElement* e, Sign sign = Sign::Any) {
  const auto v = numbers(c, e, 3, 3);
  for (double x : v) checkSign(c, e, x, sign);
  return {v[0], v[1], v[2]};
}

double childNumber(const Ctx& c, const XMLElement* parent, const char* name, double fallback,
                   Sign sign = Sign::Any) {
  const XMLElement* e = parent->FirstChildElement(name);
  return e ? number(c, e, sign) : fallback;
}

bool boolean(const Ctx& c, const XMLElement* e) {
  const std::string s = text(e);
  if (s == "true" || s == "1") return true;
  if (s == "false" || s == "0") return false;
  fail(c, e, "expected true, false, 1 or 0, found '" + s + "'");
}

// SDF's fixed-axis roll-pitch-yaw: R = Rz(yaw) * Ry(pitch) * Rx(roll).
Eigen::Isometry3d fromXyzRpy(double x, double y, double z, double roll, double pitch, double yaw) {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.translation() = Eigen::Vector3d(x, y, z);
  t.linear() = (Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()) *
                Eigen::AngleAxisd(pitch, Eigen::Vector3d::UnitY()) *
                Eigen::AngleAxisd(roll, Eigen::Vector3d::UnitX()))
                   .toRotationMatrix();
  return t;
}

// Inverse of fromXyzRpy, written back into a sensor's <pose>.
std::string poseText(const Eigen::Isometry3d& t) {
  const Eigen::Matrix3d r = t.linear();
  const double pitch = std::asin(std::clamp(-r(2, 0), -1.0, 1.0));
  double roll = 0, yaw = 0;
  if (std::abs(r(2, 0)) < 1 - 1e-12) {
    roll = std::atan2(r(2, 1), r(2, 2));
    yaw = std::atan2(r(1, 0), r(0, 0));
  } else {
    yaw = std::atan2(-r(0, 1), r(1, 1));  // gimbal lock: only roll+yaw is defined, put it in yaw
  }
  std::ostringstream out;
  out.imbue(std::locale::classic());
  out.precision(15);
  const Eigen::Vector3d p = t.translation();
  out << p.x() << ' ' << p.y() << ' ' << p.z() << ' ' << roll << ' ' << pitch << ' ' << yaw;
  return out.str();
}

Eigen::Isometry3d parsePose(const Ctx& c, const XMLElement* e) {
  for (const char* attr : {"relative_to", "frame"}) {
    const char* v = e->Attribute(attr);
    if (v && *v) fail(c, e, std::string(attr) + "='" + v + "' is not supported; poses are relative to the parent element");
  }
  auto v = numbers(c, e, 6, 6);
  if (e->BoolAttribute("degrees", false))
    for (int i = 3; i < 6; ++i) v[i] *= EIGEN_PI / 180.0;
  return fromXyzRpy(v[0], v[1], v[2], v[3], v[4], v[5]);
}

// The parent's <pose> child, or identity.
Eigen::Isometry3d childPose(const Ctx& c, const XMLElement* parent) {
  const XMLElement* e = parent->FirstChildElement("pose");
  return e ? parsePose(c, e) : Eigen::Isometry3d::Identity();
}

void allowOnly(const Ctx& c, const XMLElement* shape, std::initializer_list<std::string> names) {
  for (const XMLElement* e = shape->FirstChildElement(); e; e = e->NextSiblingElement()) {
    if (std::find(names.begin(), names.end(), e->Name()) != names.end()) continue;
    std::string list;
    for (const auto& n : names) list += (list.empty() ? "<" : ", <") + n + ">";
    fail(c, e, std::string("unexpected element in <") + shape->Name() + ">; expected " + list);
  }
}

Geometry parseGeometry(const Ctx& c, const XMLElement* g, const std::string& link) {
  const char* const expected = "expected one of box, cylinder, sphere, plane, mesh";
  const XMLElement* shape = g->FirstChildElement();
  if (!shape) fail(c, g, std::string(expected) + ", found nothing");
  if (shape->NextSiblingElement()) fail(c, g, std::string(expected) + ", found more than one");
  const std::string kind = shape->Name();
  Geometry geo;
  if (kind == "box") {
    allowOnly(c, shape, {"size"});
    geo.type = GeometryType::Box;
    geo.box_size = vector3(c, required(c, shape, "size"), Sign::NonNegative);
  } else if (kind == "cylinder") {
    allowOnly(c, shape, {"radius", "length"});
    geo.type = GeometryType::Cylinder;
    geo.radius = number(c, required(c, shape, "radius"), Sign::NonNegative);
    geo.length = number(c, required(c, shape, "length"), Sign::NonNegative);
  } else if (kind == "sphere") {
    allowOnly(c, shape, {"radius"});
    geo.type = GeometryType::Sphere;
    geo.radius = number(c, required(c, shape, "radius"), Sign::NonNegative);
  } else if (kind == "plane") {
    // normal and size have obvious defaults (+z, the struct's extent), unlike a box's size.
    allowOnly(c, shape, {"normal", "size"});
    geo.type = GeometryType::Plane;
    if (const XMLElement* n = shape->FirstChildElement("normal")) {
      geo.plane_normal = vector3(c, n);
      if (geo.plane_normal.norm() < 1e-12) fail(c, n, "expected a non-zero normal, found '" + text(n) + "'");
      geo.plane_normal.normalize();
    }
    if (const XMLElement* s = shape->FirstChildElement("size")) {
      const auto v = numbers(c, s, 2, 2);
      for (double x : v) checkSign(c, s, x, Sign::NonNegative);
      geo.plane_size = Eigen::Vector2d(v[0], v[1]);
    }
  } else if (kind == "mesh") {
    allowOnly(c, shape, {"uri", "scale"});
    geo.type = GeometryType::Mesh;
    const XMLElement* uri = required(c, shape, "uri");
    try {
      geo.mesh_file = c.resolver.resolve(text(uri), c.base_dir);
    } catch (const DescriptionError& e) {
      fail(c, uri, "mesh of link '" + link + "' not found: " + e.what());
    }
    if (fs::is_directory(geo.mesh_file))
      fail(c, uri, "mesh of link '" + link + "': " + geo.mesh_file + " is a folder, expected a mesh file");
    if (const XMLElement* s = shape->FirstChildElement("scale")) geo.mesh_scale = vector3(c, s, Sign::Positive);
  } else {
    fail(c, g, std::string(expected) + ", found <" + kind + ">");
  }
  return geo;
}

std::array<float, 4> colour(const Ctx& c, const XMLElement* e) {
  const auto v = numbers(c, e, 3, 4);  // alpha may be left out
  std::array<float, 4> rgba{{0, 0, 0, 1}};
  for (size_t i = 0; i < v.size(); ++i) rgba[i] = static_cast<float>(std::clamp(v[i], 0.0, 1.0));
  return rgba;
}

// As in Gazebo, explicit <diffuse> (else <ambient>) overrides the script's colour.
void parseMaterial(const Ctx& c, const XMLElement* m, VisualShape& v) {
  if (const XMLElement* script = m->FirstChildElement("script"))
    if (const XMLElement* name = script->FirstChildElement("name")) {
      auto it = gazeboMaterials().find(text(name));
      if (it != gazeboMaterials().end()) v.rgba = it->second;  // unknown scripts keep the default grey
    }
  if (const XMLElement* d = m->FirstChildElement("diffuse")) v.rgba = colour(c, d);
  else if (const XMLElement* a = m->FirstChildElement("ambient")) v.rgba = colour(c, a);
}

// A <sensor> whose <pose> (relative to its SDF link) is re-expressed relative to our link
// frame, which is the model frame: link_pose * sensor_pose.
GazeboExtension sensorExtension(const Ctx& c, const XMLElement* sensor, const Eigen::Isometry3d& link_pose,
                                const std::string& reference) {
  tinyxml2::XMLDocument doc;
  XMLElement* copy = sensor->DeepClone(&doc)->ToElement();
  doc.InsertEndChild(copy);
  if (!link_pose.isApprox(Eigen::Isometry3d::Identity())) {
    XMLElement* pose = copy->FirstChildElement("pose");
    const Eigen::Isometry3d sensor_pose = childPose(c, sensor);
    if (!pose) pose = copy->InsertFirstChild(doc.NewElement("pose"))->ToElement();
    pose->SetText(poseText(link_pose * sensor_pose).c_str());
  }
  tinyxml2::XMLPrinter printer;
  copy->Accept(&printer);
  return {reference, printer.CStr()};
}

// Adds one SDF link's content to `out`, every origin pre-multiplied by the link's pose in
// the model so that `out`'s frame is the model frame.
void parseLink(const Ctx& c, const XMLElement* l, bool first, LinkDescription& out, ModelDescription& model,
               bool& friction_set) {
  const Eigen::Isometry3d link_pose = childPose(c, l);
  const std::string link_name = l->Attribute("name") ? l->Attribute("name") : "";

  if (first) {
    // SDF's defaults when <inertial> or one of its values is left out: 1 kg, unit inertia.
    Inertial& in = out.inertial;
    in.mass = 1.0;
    in.inertia.setIdentity();
    Eigen::Isometry3d com = Eigen::Isometry3d::Identity();
    if (const XMLElement* ie = l->FirstChildElement("inertial")) {
      in.mass = childNumber(c, ie, "mass", 1.0, Sign::NonNegative);
      com = childPose(c, ie);
      if (const XMLElement* m = ie->FirstChildElement("inertia")) {
        const double ixx = childNumber(c, m, "ixx", 1), ixy = childNumber(c, m, "ixy", 0),
                     ixz = childNumber(c, m, "ixz", 0), iyy = childNumber(c, m, "iyy", 1),
                     iyz = childNumber(c, m, "iyz", 0), izz = childNumber(c, m, "izz", 1);
        in.inertia << ixx, ixy, ixz, ixy, iyy, iyz, ixz, iyz, izz;
      }
    }
    in.origin = link_pose * com;
  }

  for (const XMLElement* e = l->FirstChildElement(); e; e = e->NextSiblingElement()) {
    const std::string tag = e->Name();
    if (tag == "collision") {
      CollisionShape s;
      s.name = e->Attribute("name") ? e->Attribute("name") : "";
      s.origin = link_pose * childPose(c, e);
      s.geometry = parseGeometry(c, required(c, e, "geometry"), link_name);
      // One coefficient pair per LinkDescription: the first collision that sets one wins.
      const XMLElement* surface = e->FirstChildElement("surface");
      const XMLElement* friction = surface ? surface->FirstChildElement("friction") : nullptr;
      const XMLElement* ode = friction ? friction->FirstChildElement("ode") : nullptr;
      if (ode && !friction_set && (ode->FirstChildElement("mu") || ode->FirstChildElement("mu2"))) {
        out.mu1 = childNumber(c, ode, "mu", 1.0, Sign::NonNegative);
        out.mu2 = childNumber(c, ode, "mu2", 1.0, Sign::NonNegative);
        friction_set = true;
      }
      out.collisions.push_back(s);
    } else if (tag == "visual") {
      VisualShape v;
      v.name = e->Attribute("name") ? e->Attribute("name") : "";
      v.origin = link_pose * childPose(c, e);
      v.geometry = parseGeometry(c, required(c, e, "geometry"), link_name);
      if (const XMLElement* m = e->FirstChildElement("material")) parseMaterial(c, m, v);
      out.visuals.push_back(v);
    } else if (tag == "sensor") {
      model.extensions.push_back(sensorExtension(c, e, link_pose, out.name));
    }
    // Other link elements (gravity, self_collide, velocity_decay, ...) do not apply here.
  }
}

ModelDescription parseModel(const Ctx& c, const XMLElement* m, std::optional<bool> static_override,
                            Eigen::Isometry3d* model_pose) {
  ModelDescription model;
  if (!m->Attribute("name") || !*m->Attribute("name")) fail(c, m, "missing attribute name");
  model.name = m->Attribute("name");
  model.source = c.source;
  const XMLElement* st = m->FirstChildElement("static");
  model.is_static = static_override ? *static_override : (st && boolean(c, st));
  if (model_pose) *model_pose = childPose(c, m);

  std::vector<const XMLElement*> links;
  bool has_joint = false;
  for (const XMLElement* e = m->FirstChildElement(); e; e = e->NextSiblingElement()) {
    const std::string tag = e->Name();
    if (tag == "link") {
      if (!e->Attribute("name") || !*e->Attribute("name")) fail(c, e, "missing attribute name");
      links.push_back(e);
    } else if (tag == "joint") {
      has_joint = true;
    } else if (tag == "model" || tag == "include") {
      fail(c, e, "nested models are not supported; put the model directly in the world");
    }
  }
  if (links.empty()) fail(c, m, "expected at least one <link>");
  // A static model's links never move relative to each other, so they can share one
  // rigid body; a moving model's links would need joints, which only the URDF path has.
  if (!model.is_static && (links.size() > 1 || has_joint))
    fail(c, m, "SDF models with more than one link or with <joint> are not supported for moving models; "
               "describe it in URDF");

  LinkDescription link;
  link.name = links.front()->Attribute("name");
  bool friction_set = false;
  for (size_t i = 0; i < links.size(); ++i) parseLink(c, links[i], i == 0, link, model, friction_set);
  model.root_link = link.name;
  model.fixed_base = false;
  model.links.push_back(std::move(link));

  for (const XMLElement* p = m->FirstChildElement("plugin"); p; p = p->NextSiblingElement("plugin")) {
    tinyxml2::XMLPrinter printer;
    p->Accept(&printer);
    model.extensions.push_back({"", printer.CStr()});
  }
  return model;
}

void loadXml(tinyxml2::XMLDocument& doc, const std::string& xml, const std::string& source) {
  if (doc.Parse(xml.c_str(), xml.size()) != tinyxml2::XML_SUCCESS)
    throw DescriptionError(source + ": line " + std::to_string(doc.ErrorLineNum()) +
                           ": malformed XML: " + doc.ErrorStr());
  if (!doc.RootElement()) throw DescriptionError(source + ": no XML element found");
}

std::string readFile(const std::string& path, const std::string& context) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw DescriptionError(context + "cannot read " + path);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// The <model> of an SDF document that must hold a model (model.sdf, spawn requests).
const XMLElement* modelElement(const Ctx& c, const XMLElement* root) {
  const std::string tag = root->Name();
  if (tag == "model") return root;
  if (tag != "sdf") fail(c, root, "expected <sdf> or <model> as the root element");
  if (const XMLElement* w = root->FirstChildElement("world"))
    fail(c, w, "expected a <model>, found a <world>; worlds are loaded from .world files, not spawned");
  const XMLElement* m = root->FirstChildElement("model");
  if (!m) fail(c, root, "expected a <model> element");
  return m;
}

std::vector<int> versionNumbers(const char* v) {
  std::vector<int> out;
  std::istringstream in(v ? v : "");
  for (std::string part; std::getline(in, part, '.');) out.push_back(std::atoi(part.c_str()));
  return out;
}

// model.config names the SDF file (the newest version when there are several); model.sdf otherwise.
std::string modelFileInDir(const fs::path& dir) {
  tinyxml2::XMLDocument config;
  if (config.LoadFile((dir / "model.config").c_str()) == tinyxml2::XML_SUCCESS && config.RootElement()) {
    const XMLElement* best = nullptr;
    for (const XMLElement* s = config.RootElement()->FirstChildElement("sdf"); s; s = s->NextSiblingElement("sdf"))
      if (!text(s).empty() && (!best || versionNumbers(s->Attribute("version")) > versionNumbers(best->Attribute("version"))))
        best = s;
    if (best) return (dir / text(best)).string();
  }
  return (dir / "model.sdf").string();
}

// An <include>: the model it names placed in the world, or nothing for a light (sun).
std::optional<PlacedModel> parseInclude(const Ctx& c, const XMLElement* inc) {
  const XMLElement* uri_e = required(c, inc, "uri");
  std::string uri = text(uri_e);
  while (uri.size() > 8 && uri.back() == '/') uri.pop_back();  // "model://box/" names "box"
  if (uri == "model://sun") return std::nullopt;

  std::optional<bool> static_override;
  if (const XMLElement* st = inc->FirstChildElement("static")) static_override = boolean(c, st);

  std::string xml, source, base_dir;
  if (uri == "model://ground_plane") {
    xml = kGroundPlaneSdf;
    source = "built-in model://ground_plane";
  } else {
    std::string path;
    try {
      const bool model_name_only = uri.rfind("model://", 0) == 0 && uri.find('/', 8) == std::string::npos;
      path = model_name_only ? c.resolver.findModelDir(uri.substr(8)) : c.resolver.resolve(uri, c.base_dir);
      if (fs::is_directory(path)) path = modelFileInDir(path);
      xml = readFile(path, "");
    } catch (const DescriptionError& e) {
      fail(c, uri_e, e.what());
    }
    source = path;
    base_dir = fs::path(path).parent_path().string();
  }

  PlacedModel placed;
  try {
    const Ctx inner{source, base_dir, c.resolver};
    tinyxml2::XMLDocument doc;
    loadXml(doc, xml, source);
    placed.model = parseModel(inner, modelElement(inner, doc.RootElement()), static_override, &placed.pose);
  } catch (const DescriptionError& e) {
    fail(c, inc, std::string("in ") + uri + ": " + e.what());  // name the world file too
  }
  if (const XMLElement* n = inc->FirstChildElement("name")) {
    if (text(n).empty()) fail(c, n, "expected a model name, found nothing");
    placed.model.name = text(n);
  }
  if (const XMLElement* p = inc->FirstChildElement("pose")) placed.pose = parsePose(c, p);  // replaces the model's
  return placed;
}

void parsePhysics(const Ctx& c, const XMLElement* p, PhysicsSettings& out) {
  out.max_step_size = childNumber(c, p, "max_step_size", out.max_step_size, Sign::Positive);
  out.real_time_factor = childNumber(c, p, "real_time_factor", out.real_time_factor, Sign::NonNegative);
  out.real_time_update_rate =
      childNumber(c, p, "real_time_update_rate", out.real_time_update_rate, Sign::NonNegative);
  if (const XMLElement* g = p->FirstChildElement("gravity")) out.gravity = vector3(c, g);  // SDF <= 1.5
}

WorldDescription parseWorld(const Ctx& c, const XMLElement* root) {
  if (std::string(root->Name()) != "sdf") fail(c, root, "expected <sdf> as the root element");
  const XMLElement* w = root->FirstChildElement("world");
  if (!w) fail(c, root, "expected a <world> element");

  WorldDescription world;
  world.source = c.source;
  if (w->Attribute("name") && *w->Attribute("name")) world.name = w->Attribute("name");

  // Several <physics> profiles are allowed; Gazebo uses the one marked default, else the first.
  const XMLElement* physics = w->FirstChildElement("physics");
  for (const XMLElement* p = physics; p; p = p->NextSiblingElement("physics"))
    if (p->BoolAttribute("default", false)) { physics = p; break; }
  if (physics) parsePhysics(c, physics, world.physics);
  if (const XMLElement* g = w->FirstChildElement("gravity")) world.physics.gravity = vector3(c, g);  // SDF >= 1.6

  std::set<std::string> names;
  for (const XMLElement* e = w->FirstChildElement(); e; e = e->NextSiblingElement()) {
    const std::string tag = e->Name();
    std::optional<PlacedModel> placed;
    if (tag == "model") {
      placed.emplace();
      placed->model = parseModel(c, e, std::nullopt, &placed->pose);
    } else if (tag == "include") {
      placed = parseInclude(c, e);
    }
    // Lights, scene, gui, state, plugins and the like have no counterpart here.
    if (!placed) continue;
    if (!names.insert(placed->model.name).second)
      fail(c, e, "a model named '" + placed->model.name + "' is already in the world; give it another <name>");
    world.models.push_back(std::move(*placed));
  }
  return world;
}

}  // namespace

WorldDescription parseWorldFile(const std::string& path, const ResourceResolver& resolver) {
  const std::string xml = readFile(path, "world file: ");
  const std::string base_dir = fs::absolute(path).parent_path().string();
  return parseWorldString(xml, path, base_dir, resolver);
}

WorldDescription parseWorldString(const std::string& xml, const std::string& source,
                                  const std::string& base_dir, const ResourceResolver& resolver) {
  tinyxml2::XMLDocument doc;
  loadXml(doc, xml, source);
  return parseWorld(Ctx{source, base_dir, resolver}, doc.RootElement());
}

ModelDescription parseSdfModel(const std::string& xml, const std::string& source, const std::string& base_dir,
                               const ResourceResolver& resolver, Eigen::Isometry3d* model_pose) {
  tinyxml2::XMLDocument doc;
  loadXml(doc, xml, source);
  const Ctx c{source, base_dir, resolver};
  return parseModel(c, modelElement(c, doc.RootElement()), std::nullopt, model_pose);
}

}  // namespace bullet_sim
