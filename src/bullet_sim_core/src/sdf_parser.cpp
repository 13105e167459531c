// SDF (.world, model.sdf) -> WorldDescription / ModelDescription. See sdf_parser.h for the
// supported subset.
#include "bullet_sim_core/sdf_parser.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <sstream>

#include "bullet_sim_core/description_error.h"
#include "bullet_sim_core/gazebo_materials.h"

namespace fs = std::filesystem;

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

// SDF's "no limit": the model editor writes +-1.79769e+308, the spec's default is +-1e16.
constexpr double kNoLimit = 1e16;

// Where we are: relative URIs are resolved against base_dir; the SDF version decides the frame of
// a joint axis.
struct Ctx {
  std::string base_dir;
  const ResourceResolver& resolver;
  bool axis_in_model_frame_by_default = false;  // SDF 1.4
};

void allowOnly(const SdfElement& shape, std::initializer_list<std::string> names) {
  for (const SdfElement& e : shape.children()) {
    if (std::find(names.begin(), names.end(), e.tag()) != names.end()) continue;
    std::string list;
    for (const auto& n : names) list += (list.empty() ? "<" : ", <") + n + ">";
    e.fail("unexpected element in <" + shape.tag() + ">; expected " + list);
  }
}

Geometry parseGeometry(const Ctx& c, const SdfElement& g, const std::string& link) {
  const std::string expected = "expected one of box, cylinder, sphere, plane, mesh";
  const std::vector<SdfElement> shapes = g.children();
  if (shapes.empty()) g.fail(expected + ", found nothing");
  if (shapes.size() > 1) g.fail(expected + ", found more than one");
  const SdfElement& shape = shapes.front();
  const std::string kind = shape.tag();
  Geometry geo;
  if (kind == "box") {
    allowOnly(shape, {"size"});
    geo.type = GeometryType::Box;
    const SdfElement size = shape.requiredChild("size");
    geo.box_size = size.asVector3();
    if (geo.box_size.minCoeff() < 0) size.fail("expected sizes >= 0, got '" + size.text() + "'");
  } else if (kind == "cylinder") {
    allowOnly(shape, {"radius", "length"});
    geo.type = GeometryType::Cylinder;
    geo.radius = shape.requiredChild("radius").asNumber(nonNegative());
    geo.length = shape.requiredChild("length").asNumber(nonNegative());
  } else if (kind == "sphere") {
    allowOnly(shape, {"radius"});
    geo.type = GeometryType::Sphere;
    geo.radius = shape.requiredChild("radius").asNumber(nonNegative());
  } else if (kind == "plane") {
    // normal and size have obvious defaults (+z, the struct's extent), unlike a box's size.
    allowOnly(shape, {"normal", "size"});
    geo.type = GeometryType::Plane;
    if (const SdfElement n = shape.child("normal")) {
      geo.plane_normal = n.asVector3();
      if (geo.plane_normal.norm() < 1e-12) n.fail("expected a non-zero normal, got '" + n.text() + "'");
      geo.plane_normal.normalize();
    }
    if (const SdfElement s = shape.child("size")) {
      const auto v = s.asNumbers(2, 2);
      if (std::min(v[0], v[1]) < 0) s.fail("expected sizes >= 0, got '" + s.text() + "'");
      geo.plane_size = Eigen::Vector2d(v[0], v[1]);
    }
  } else if (kind == "mesh") {
    allowOnly(shape, {"uri", "scale", "submesh"});
    geo.type = GeometryType::Mesh;
    const SdfElement uri = shape.requiredChild("uri");
    try {
      geo.mesh_file = c.resolver.resolve(uri.text(), c.base_dir);
    } catch (const DescriptionError& e) {
      uri.fail("mesh of link '" + link + "' not found: " + e.what());
    }
    if (fs::is_directory(geo.mesh_file))
      uri.fail("mesh of link '" + link + "': " + geo.mesh_file + " is a folder, expected a mesh file");
    if (const SdfElement s = shape.child("scale")) {
      geo.mesh_scale = s.asVector3();
      if (geo.mesh_scale.minCoeff() <= 0) s.fail("expected a scale > 0 on every axis, got '" + s.text() + "'");
    }
  } else {
    g.fail(expected + ", found <" + kind + ">");
  }
  return geo;
}

std::array<float, 4> colour(const SdfElement& e) {
  const auto v = e.asNumbers(3, 4);  // alpha may be left out
  std::array<float, 4> rgba{{0, 0, 0, 1}};
  for (size_t i = 0; i < v.size(); ++i) rgba[i] = static_cast<float>(std::clamp(v[i], 0.0, 1.0));
  return rgba;
}

// As in Gazebo, explicit <diffuse> (else <ambient>) overrides the script's colour.
void parseMaterial(const SdfElement& m, VisualShape& v) {
  if (const SdfElement name = m.child("script").child("name")) {
    if (const auto rgba = gazeboMaterialColour(name.text())) v.rgba = *rgba;  // unknown scripts keep the grey
  }
  if (const SdfElement d = m.child("diffuse"))
    v.rgba = colour(d);
  else if (const SdfElement a = m.child("ambient"))
    v.rgba = colour(a);
}

std::vector<PluginDescription> parsePlugins(const SdfElement& parent) {
  std::vector<PluginDescription> out;
  for (const SdfElement& p : parent.children("plugin")) out.push_back({p.attribute("filename"), p.attribute("name"), p});
  return out;
}

// A collision's <surface><contact><ode>: how its contacts push out of an overlap. A negative max_vel
// is Gazebo's "no limit of this surface's own" (the world's contact_max_correcting_vel applies).
ContactSurface parseContactSurface(const SdfElement& ode) {
  ContactSurface out;
  out.max_vel = ode.number("max_vel", out.max_vel);
  out.min_depth = ode.number("min_depth", out.min_depth, nonNegative());
  return out;
}

// One <link>: its inertial, shapes and sensors, all in the link frame.
LinkDescription parseLink(const Ctx& c, const SdfElement& l, ModelDescription& model) {
  LinkDescription out;
  out.name = l.attribute("name");

  // SDF's defaults when <inertial> or one of its values is left out: 1 kg, unit inertia.
  Inertial& in = out.inertial;
  in.mass = 1.0;
  in.inertia.setIdentity();
  if (const SdfElement ie = l.child("inertial")) {
    in.mass = ie.number("mass", 1.0, nonNegative());
    in.origin = ie.pose();
    if (const SdfElement m = ie.child("inertia")) {
      const double ixx = m.number("ixx", 1), ixy = m.number("ixy", 0), ixz = m.number("ixz", 0),
                   iyy = m.number("iyy", 1), iyz = m.number("iyz", 0), izz = m.number("izz", 1);
      in.inertia << ixx, ixy, ixz, ixy, iyy, iyz, ixz, iyz, izz;
    }
  }

  bool friction_set = false;
  for (const SdfElement& e : l.children("collision")) {
    CollisionShape s;
    s.name = e.attribute("name");
    s.origin = e.pose();
    s.geometry = parseGeometry(c, e.requiredChild("geometry"), out.name);
    // One coefficient pair per link: the first collision that sets one wins.
    const SdfElement ode = e.child("surface").child("friction").child("ode");
    if (!friction_set && (ode.child("mu") || ode.child("mu2"))) {
      out.mu1 = ode.number("mu", 1.0, nonNegative());
      out.mu2 = ode.number("mu2", 1.0, nonNegative());
      friction_set = true;
    }
    s.surface = parseContactSurface(e.child("surface").child("contact").child("ode"));
    out.collisions.push_back(s);
  }
  for (const SdfElement& e : l.children("visual")) {
    VisualShape v;
    v.name = e.attribute("name");
    v.origin = e.pose();
    v.geometry = parseGeometry(c, e.requiredChild("geometry"), out.name);
    if (const SdfElement m = e.child("material")) parseMaterial(m, v);
    out.visuals.push_back(v);
  }
  for (const SdfElement& s : l.children("sensor"))
    model.sensors.push_back({s.attribute("name"), s.attribute("type"), out.name, s, parsePlugins(s)});
  out.gravity = l.boolean("gravity", true);
  // Other link elements (self_collide, velocity_decay, ...) do not apply here.
  return out;
}

JointType jointType(const SdfElement& j) {
  const std::string type = j.attribute("type");
  if (type == "revolute") return JointType::Revolute;
  if (type == "continuous") return JointType::Continuous;
  if (type == "prismatic") return JointType::Prismatic;
  if (type == "fixed") return JointType::Fixed;
  j.fail("type='" + type + "': expected revolute, continuous, prismatic or fixed" +
         (type.empty() ? "" : " (bullet_sim has no " + type + " joints)"));
}

// One <joint>, given the links' poses in the model frame ("world" is the model frame's origin).
JointDescription parseJoint(const Ctx& c, const SdfElement& j, const std::map<std::string, Eigen::Isometry3d>& links) {
  JointDescription out;
  out.name = j.attribute("name");
  if (out.name.empty()) j.fail("missing attribute name");
  out.type = jointType(j);
  const SdfElement parent = j.requiredChild("parent"), child = j.requiredChild("child");
  out.parent = parent.text();
  out.child = child.text();
  const auto named = [&](const SdfElement& e, const std::string& link, bool world_ok) {
    if (link == "world" && world_ok) return;
    if (!links.count(link)) {
      std::string known;
      for (const auto& [name, pose] : links) known += (known.empty() ? "" : ", ") + name;
      e.fail("expected the name of a link of this model (" + known + (world_ok ? ", or world" : "") + "), got '" +
             link + "'");
    }
  };
  named(parent, out.parent, true);
  named(child, out.child, false);
  if (out.parent == out.child) child.fail("expected a link other than the parent '" + out.parent + "'");

  const Eigen::Isometry3d parent_pose = out.parent == "world" ? Eigen::Isometry3d::Identity() : links.at(out.parent);
  const Eigen::Isometry3d child_pose = links.at(out.child);
  out.origin = parent_pose.inverse() * child_pose;
  const Eigen::Isometry3d joint_in_child = j.pose();
  out.pivot = joint_in_child.translation();
  if (out.type == JointType::Fixed) return out;

  const SdfElement axis = j.child("axis");
  const SdfElement xyz = axis.child("xyz");
  const Eigen::Vector3d direction = xyz ? xyz.asVector3() : Eigen::Vector3d::UnitZ();  // SDF's default
  if (direction.norm() < 1e-9) xyz.fail("expected a non-zero axis, got '" + xyz.text() + "'");
  const bool in_model_frame = axis.boolean("use_parent_model_frame", c.axis_in_model_frame_by_default);
  const Eigen::Vector3d axis_in_child = in_model_frame ? Eigen::Vector3d(child_pose.linear().transpose() * direction)
                                                      : Eigen::Vector3d(joint_in_child.linear() * direction);
  out.axis = axis_in_child.normalized();

  const SdfElement limit = axis.child("limit");
  const double lower = limit.number("lower", -kNoLimit), upper = limit.number("upper", kNoLimit);
  if (upper < lower) limit.child("upper").fail("expected a number >= <lower> (" + formatNumber(lower) + "), got '" +
                                               limit.child("upper").text() + "'");
  if (out.type != JointType::Continuous) {
    out.lower = lower > -kNoLimit ? lower : -std::numeric_limits<double>::infinity();
    out.upper = upper < kNoLimit ? upper : std::numeric_limits<double>::infinity();
  }
  // SDF: -1 (any negative value) means no limit.
  const double effort = limit.number("effort", -1), velocity = limit.number("velocity", -1);
  if (effort >= 0) out.effort_limit = effort;
  if (velocity >= 0) out.velocity_limit = velocity;
  const SdfElement dynamics = axis.child("dynamics");
  out.damping = dynamics.number("damping", 0.0, nonNegative());
  out.friction = dynamics.number("friction", 0.0, nonNegative());
  return out;
}

// Links in tree order (every parent before its children), from `root`; fails on a link that the
// joints do not connect to the root.
void orderAsTree(ModelDescription& model, const SdfElement& m) {
  std::map<std::string, std::vector<const JointDescription*>> below;
  for (const JointDescription& j : model.joints) below[j.parent].push_back(&j);
  std::map<std::string, LinkDescription> by_name;
  for (LinkDescription& l : model.links) by_name[l.name] = std::move(l);
  std::vector<LinkDescription> ordered;
  std::vector<JointDescription> joints;
  std::vector<std::string> stack{model.root_link};
  std::set<std::string> reached;
  while (!stack.empty()) {
    const std::string name = stack.back();
    stack.pop_back();
    reached.insert(name);
    ordered.push_back(by_name.at(name));
    for (auto it = below[name].rbegin(); it != below[name].rend(); ++it) {
      joints.push_back(**it);
      stack.push_back((*it)->child);
    }
  }
  for (const auto& [name, link] : by_name) {
    if (!reached.count(name))
      m.fail("link '" + name + "' is not connected to link '" + model.root_link +
             "' by joints; a moving model must be one tree of links (is there a <joint> missing, or a loop?)");
  }
  model.links = std::move(ordered);
  model.joints = std::move(joints);
}

ModelDescription parseModel(const Ctx& c, const SdfElement& m, std::optional<bool> static_override,
                            Eigen::Isometry3d* model_pose) {
  ModelDescription model;
  model.name = m.attribute("name");
  if (model.name.empty()) m.fail("missing attribute name");
  model.source = m.source();
  const SdfElement st = m.child("static");
  model.is_static = static_override ? *static_override : (st && st.asBoolean());
  if (model_pose) *model_pose = m.pose();
  for (const std::string nested : {"model", "include"})
    if (const SdfElement e = m.child(nested.c_str()))
      e.fail("nested models are not supported; put the model directly in the world");

  std::map<std::string, Eigen::Isometry3d> link_poses;  // in the model frame
  for (const SdfElement& l : m.children("link")) {
    const std::string name = l.attribute("name");
    if (name.empty()) l.fail("missing attribute name");
    if (name == "world") l.fail("'world' names the world frame; give the link another name");
    if (!link_poses.emplace(name, l.pose()).second) l.fail("a link named '" + name + "' is already in this model");
    model.links.push_back(parseLink(c, l, model));
  }
  if (model.links.empty()) m.fail("expected at least one <link>");
  model.root_link = model.links.front().name;
  model.root_pose = link_poses.at(model.root_link);

  if (model.is_static) {
    // Nothing moves: every link is held where its pose puts it, joints or not.
    for (size_t i = 1; i < model.links.size(); ++i) {
      JointDescription fixed;
      fixed.name = model.links[i].name + "_static";
      fixed.parent = model.root_link;
      fixed.child = model.links[i].name;
      fixed.origin = model.root_pose.inverse() * link_poses.at(fixed.child);
      model.joints.push_back(fixed);
    }
  } else {
    std::map<std::string, std::string> parent_of;
    for (const SdfElement& j : m.children("joint")) {
      JointDescription joint = parseJoint(c, j, link_poses);
      if (parent_of.count(joint.child))
        j.child("child").fail("link '" + joint.child + "' already has a parent joint; a link has one parent");
      parent_of[joint.child] = joint.parent;
      model.joints.push_back(joint);
    }
    // The root is the link no joint moves; "world" fixes the model where it is placed.
    if (std::any_of(model.joints.begin(), model.joints.end(), [](const auto& j) { return j.parent == "world"; })) {
      LinkDescription world;
      world.name = "world";
      model.links.insert(model.links.begin(), world);
      model.root_link = "world";
      model.root_pose = Eigen::Isometry3d::Identity();
      model.fixed_base = true;
    } else {
      for (const LinkDescription& l : model.links)
        if (!parent_of.count(l.name)) {
          model.root_link = l.name;
          break;
        }
      model.root_pose = link_poses.at(model.root_link);
    }
    orderAsTree(model, m);
  }
  model.plugins = parsePlugins(m);
  return model;
}

std::string readFile(const std::string& path, const std::string& context) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw DescriptionError(context + "cannot read " + path);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// SDF 1.4 gives joint axes in the model frame; later versions in the joint frame.
Ctx contextFor(const SdfElement& root, const std::string& base_dir, const ResourceResolver& resolver) {
  Ctx c{base_dir, resolver};
  c.axis_in_model_frame_by_default = root.tag() == "sdf" && root.attribute("version") == "1.4";
  return c;
}

// The <model> of an SDF document that must hold a model (model.sdf, spawn requests).
SdfElement modelElement(const SdfElement& root) {
  if (root.tag() == "model") return root;
  if (root.tag() != "sdf") root.fail("expected <sdf> or <model> as the root element, got <" + root.tag() + ">");
  if (const SdfElement w = root.child("world"))
    w.fail("expected a <model>, found a <world>; worlds are loaded from .world files, not spawned");
  const SdfElement m = root.child("model");
  if (!m) root.fail("expected a <model> element");
  return m;
}

std::vector<int> versionNumbers(const std::string& v) {
  std::vector<int> out;
  std::istringstream in(v);
  for (std::string part; std::getline(in, part, '.');) out.push_back(std::atoi(part.c_str()));
  return out;
}

// model.config names the SDF file (the newest version when there are several); model.sdf otherwise.
std::string modelFileInDir(const fs::path& dir) {
  try {
    const SdfElement config = SdfElement::parse(readFile((dir / "model.config").string(), ""), "model.config");
    SdfElement best;
    for (const SdfElement& s : config.children("sdf"))
      if (!s.text().empty() &&
          (!best || versionNumbers(s.attribute("version")) > versionNumbers(best.attribute("version"))))
        best = s;
    if (best) return (dir / best.text()).string();
  } catch (const DescriptionError&) {
    // No or unreadable model.config: Gazebo falls back to model.sdf too.
  }
  return (dir / "model.sdf").string();
}

// An <include>: the model it names placed in the world, or nothing for a light (sun).
std::optional<PlacedModel> parseInclude(const Ctx& c, const SdfElement& inc) {
  const SdfElement uri_e = inc.requiredChild("uri");
  std::string uri = uri_e.text();
  while (uri.size() > 8 && uri.back() == '/') uri.pop_back();  // "model://box/" names "box"
  if (uri == "model://sun") return std::nullopt;

  std::optional<bool> static_override;
  if (const SdfElement st = inc.child("static")) static_override = st.asBoolean();

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
      uri_e.fail(e.what());
    }
    source = path;
    base_dir = fs::path(path).parent_path().string();
  }

  PlacedModel placed;
  try {
    const SdfElement root = SdfElement::parse(xml, source);
    placed.model = parseModel(contextFor(root, base_dir, c.resolver), modelElement(root), static_override, &placed.pose);
  } catch (const DescriptionError& e) {
    inc.fail("in " + uri + ": " + e.what());  // name the world file too
  }
  if (const SdfElement n = inc.child("name")) {
    if (n.text().empty()) n.fail("expected a model name, got nothing");
    placed.model.name = n.text();
  }
  if (const SdfElement p = inc.child("pose")) placed.pose = p.asPose();  // replaces the model's
  return placed;
}

void parsePhysics(const SdfElement& p, PhysicsSettings& out) {
  out.max_step_size = p.number("max_step_size", out.max_step_size, positive());
  out.real_time_factor = p.number("real_time_factor", out.real_time_factor, nonNegative());
  out.real_time_update_rate = p.number("real_time_update_rate", out.real_time_update_rate, nonNegative());
  out.gravity = p.vector3("gravity", out.gravity);  // SDF <= 1.5
  // The solver's sweeps, from the engine's block Gazebo would use (ODE's unless type says bullet).
  const std::string engine = p.attribute("type") == "bullet" ? "bullet" : "ode";
  if (const SdfElement e = p.child(engine.c_str())) {
    if (const SdfElement solver = e.child("solver"))
      out.solver_iterations = static_cast<int>(solver.integer("iters", out.solver_iterations, 1, 100000));
    // How fast contacts push overlapping bodies apart (Bullet's block has the surface layer only).
    const SdfElement constraints = e.child("constraints");
    out.contact_max_correcting_vel =
        constraints.number("contact_max_correcting_vel", out.contact_max_correcting_vel, nonNegative());
    out.contact_surface_layer = constraints.number("contact_surface_layer", out.contact_surface_layer, nonNegative());
  }
}

// World plugins are not loaded; gazebo_ros's own (its API, paths, state) are built into the node.
void warnAboutWorldPlugin(const SdfElement& plugin, WorldDescription& world) {
  const std::string library = pluginLibraryName(plugin.attribute("filename"));
  for (const char* built_in : {"libgazebo_ros_api_plugin.so", "libgazebo_ros_paths_plugin.so", "libgazebo_ros_state.so"})
    if (library == built_in) return;
  world.warnings.push_back(plugin.source() + ": " + plugin.path() + ": world plugin '" + library +
                           "' is not simulated by bullet_sim; the world is loaded without it");
}

WorldDescription parseWorld(const Ctx& c, const SdfElement& root) {
  if (root.tag() != "sdf") root.fail("expected <sdf> as the root element");
  const SdfElement w = root.child("world");
  if (!w) root.fail("expected a <world> element");

  WorldDescription world;
  world.source = root.source();
  if (!w.attribute("name").empty()) world.name = w.attribute("name");

  // Several <physics> profiles are allowed; Gazebo uses the one marked default, else the first.
  const std::vector<SdfElement> profiles = w.children("physics");
  const auto chosen = std::find_if(profiles.begin(), profiles.end(), [](const SdfElement& p) {
    return p.hasAttribute("default") && p.attribute("default") != "false" && p.attribute("default") != "0";
  });
  if (chosen != profiles.end()) parsePhysics(*chosen, world.physics);
  else if (!profiles.empty()) parsePhysics(profiles.front(), world.physics);
  world.physics.gravity = w.vector3("gravity", world.physics.gravity);  // SDF >= 1.6

  std::set<std::string> names;
  for (const SdfElement& e : w.children()) {
    std::optional<PlacedModel> placed;
    if (e.tag() == "model") {
      placed.emplace();
      placed->model = parseModel(c, e, std::nullopt, &placed->pose);
    } else if (e.tag() == "include") {
      placed = parseInclude(c, e);
    }
    if (e.tag() == "plugin") warnAboutWorldPlugin(e, world);
    // Lights, scene, gui, state and the like have no counterpart here.
    if (!placed) continue;
    if (!names.insert(placed->model.name).second)
      e.fail("a model named '" + placed->model.name + "' is already in the world; give it another <name>");
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

WorldDescription parseWorldString(const std::string& xml, const std::string& source, const std::string& base_dir,
                                  const ResourceResolver& resolver) {
  const SdfElement root = SdfElement::parse(xml, source);
  return parseWorld(contextFor(root, base_dir, resolver), root);
}

ModelDescription parseSdfModel(const std::string& xml, const std::string& source, const std::string& base_dir,
                               const ResourceResolver& resolver, Eigen::Isometry3d* model_pose) {
  const SdfElement root = SdfElement::parse(xml, source);
  return parseModel(contextFor(root, base_dir, resolver), modelElement(root), std::nullopt, model_pose);
}

}  // namespace bullet_sim
