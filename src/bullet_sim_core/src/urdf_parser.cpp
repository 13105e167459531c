#include "bullet_sim_core/urdf_parser.h"

#include <console_bridge/console.h>
#include <tinyxml2.h>
#include <urdf_parser/urdf_parser.h>

#include <cmath>
#include <mutex>
#include <sstream>

#include "bullet_sim_core/description_error.h"
#include "bullet_sim_core/gazebo_materials.h"

namespace bullet_sim {
namespace {

// urdfdom reports what is wrong only through console_bridge; collect it for the error text.
class CollectingOutputHandler : public console_bridge::OutputHandler {
 public:
  void log(const std::string& text, console_bridge::LogLevel level, const char*, int) override {
    if (level >= console_bridge::CONSOLE_BRIDGE_LOG_ERROR) errors += (errors.empty() ? "" : "; ") + text;
  }
  std::string errors;
};

Eigen::Isometry3d toIsometry(const urdf::Pose& p) {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.translation() = Eigen::Vector3d(p.position.x, p.position.y, p.position.z);
  t.linear() = Eigen::Quaterniond(p.rotation.w, p.rotation.x, p.rotation.y, p.rotation.z).normalized().toRotationMatrix();
  return t;
}

class Checker {
 public:
  explicit Checker(std::string source) : source_(std::move(source)) {}
  void finite(double v, const std::string& where) const {
    if (!std::isfinite(v)) fail(where, "expected a finite number, got " + std::to_string(v));
  }
  void pose(const urdf::Pose& p, const std::string& where) const {
    for (double v : {p.position.x, p.position.y, p.position.z, p.rotation.x, p.rotation.y, p.rotation.z, p.rotation.w})
      finite(v, where + "/<origin>");
  }
  [[noreturn]] void fail(const std::string& where, const std::string& what) const {
    throw DescriptionError(source_ + ": " + where + ": " + what);
  }

 private:
  std::string source_;
};

Geometry convertGeometry(const urdf::GeometrySharedPtr& g, const std::string& where, const Checker& check,
                         const ResourceResolver& resolver, const std::string& base_dir) {
  if (!g) check.fail(where, "expected a <geometry> with box, cylinder, sphere or mesh");
  Geometry out;
  switch (g->type) {
    case urdf::Geometry::BOX: {
      auto b = std::static_pointer_cast<urdf::Box>(g);
      out.type = GeometryType::Box;
      out.box_size = Eigen::Vector3d(b->dim.x, b->dim.y, b->dim.z);
      for (int i = 0; i < 3; ++i) {
        check.finite(out.box_size[i], where + "/<box size>");
        if (out.box_size[i] < 0) check.fail(where + "/<box size>", "expected sizes >= 0");
      }
      break;
    }
    case urdf::Geometry::CYLINDER: {
      auto c = std::static_pointer_cast<urdf::Cylinder>(g);
      out.type = GeometryType::Cylinder;
      out.radius = c->radius;
      out.length = c->length;
      check.finite(out.radius, where + "/<cylinder radius>");
      check.finite(out.length, where + "/<cylinder length>");
      if (out.radius < 0 || out.length < 0) check.fail(where + "/<cylinder>", "expected radius and length >= 0");
      break;
    }
    case urdf::Geometry::SPHERE: {
      auto s = std::static_pointer_cast<urdf::Sphere>(g);
      out.type = GeometryType::Sphere;
      out.radius = s->radius;
      check.finite(out.radius, where + "/<sphere radius>");
      if (out.radius < 0) check.fail(where + "/<sphere radius>", "expected radius >= 0");
      break;
    }
    case urdf::Geometry::MESH: {
      auto m = std::static_pointer_cast<urdf::Mesh>(g);
      out.type = GeometryType::Mesh;
      out.mesh_scale = Eigen::Vector3d(m->scale.x, m->scale.y, m->scale.z);
      const std::string mesh_where = where + "/<mesh filename='" + m->filename + "'>";
      try {
        out.mesh_file = resolver.resolve(m->filename, base_dir);
      } catch (const DescriptionError& e) {
        check.fail(mesh_where, e.what());
      }
      break;
    }
  }
  return out;
}

Inertial convertInertial(const urdf::InertialSharedPtr& in, const std::string& where, const Checker& check) {
  Inertial out;
  if (!in) return out;
  check.pose(in->origin, where + "/<inertial>");
  out.origin = toIsometry(in->origin);
  out.mass = in->mass;
  check.finite(out.mass, where + "/<inertial>/<mass>");
  if (out.mass < 0) check.fail(where + "/<inertial>/<mass>", "expected a mass >= 0");
  out.inertia << in->ixx, in->ixy, in->ixz, in->ixy, in->iyy, in->iyz, in->ixz, in->iyz, in->izz;
  for (int i = 0; i < 9; ++i) check.finite(out.inertia(i), where + "/<inertial>/<inertia>");
  return out;
}

std::string linkWhere(const std::string& name) { return "<link name='" + name + "'>"; }
std::string jointWhere(const std::string& name) { return "<joint name='" + name + "'>"; }

LinkDescription convertLink(const urdf::Link& link, const urdf::ModelInterface& model, const Checker& check,
                            const ResourceResolver& resolver, const std::string& base_dir) {
  LinkDescription out;
  out.name = link.name;
  const std::string where = linkWhere(link.name);
  out.inertial = convertInertial(link.inertial, where, check);
  for (const auto& c : link.collision_array) {
    CollisionShape shape;
    shape.name = c->name;
    check.pose(c->origin, where + "/<collision>");
    shape.origin = toIsometry(c->origin);
    shape.geometry = convertGeometry(c->geometry, where + "/<collision>/<geometry>", check, resolver, base_dir);
    out.collisions.push_back(shape);
  }
  for (const auto& v : link.visual_array) {
    VisualShape shape;
    shape.name = v->name;
    check.pose(v->origin, where + "/<visual>");
    shape.origin = toIsometry(v->origin);
    shape.geometry = convertGeometry(v->geometry, where + "/<visual>/<geometry>", check, resolver, base_dir);
    urdf::MaterialSharedPtr material = v->material;
    if (material && !v->material_name.empty() && model.getMaterial(v->material_name))
      material = model.getMaterial(v->material_name);
    if (material) {
      shape.rgba = {static_cast<float>(material->color.r), static_cast<float>(material->color.g),
                    static_cast<float>(material->color.b), static_cast<float>(material->color.a)};
      if (!material->texture_filename.empty()) {
        try {
          shape.texture_file = resolver.resolve(material->texture_filename, base_dir);
        } catch (const DescriptionError&) {
          // A missing texture only changes how the link looks; keep the colour.
        }
      }
    }
    out.visuals.push_back(shape);
  }
  return out;
}

JointDescription convertJoint(const urdf::Joint& joint, const Checker& check) {
  JointDescription out;
  out.name = joint.name;
  out.parent = joint.parent_link_name;
  out.child = joint.child_link_name;
  const std::string where = jointWhere(joint.name);
  switch (joint.type) {
    case urdf::Joint::FIXED: out.type = JointType::Fixed; break;
    case urdf::Joint::REVOLUTE: out.type = JointType::Revolute; break;
    case urdf::Joint::CONTINUOUS: out.type = JointType::Continuous; break;
    case urdf::Joint::PRISMATIC: out.type = JointType::Prismatic; break;
    default:
      check.fail(where, "joint type not supported; expected fixed, revolute, continuous or prismatic");
  }
  check.pose(joint.parent_to_joint_origin_transform, where);
  out.origin = toIsometry(joint.parent_to_joint_origin_transform);
  out.axis = Eigen::Vector3d(joint.axis.x, joint.axis.y, joint.axis.z);
  for (int i = 0; i < 3; ++i) check.finite(out.axis[i], where + "/<axis>");
  if (out.type != JointType::Fixed) {
    if (out.axis.norm() < 1e-9) check.fail(where + "/<axis>", "expected a non-zero axis");
    out.axis.normalize();
  }
  if (joint.limits) {
    const auto& l = *joint.limits;
    for (double v : {l.effort, l.velocity}) check.finite(v, where + "/<limit>");
    if (out.type == JointType::Revolute || out.type == JointType::Prismatic) {
      check.finite(l.lower, where + "/<limit lower>");
      check.finite(l.upper, where + "/<limit upper>");
      if (l.upper < l.lower) check.fail(where + "/<limit>", "expected lower <= upper");
      out.lower = l.lower;
      out.upper = l.upper;
    }
    // URDF's effort/velocity 0 means "not given"; treat it as unlimited.
    if (l.effort > 0) out.effort_limit = l.effort;
    if (l.velocity > 0) out.velocity_limit = l.velocity;
  }
  if (joint.dynamics) {
    check.finite(joint.dynamics->damping, where + "/<dynamics damping>");
    check.finite(joint.dynamics->friction, where + "/<dynamics friction>");
    if (joint.dynamics->damping < 0 || joint.dynamics->friction < 0)
      check.fail(where + "/<dynamics>", "expected damping and friction >= 0");
    out.damping = joint.dynamics->damping;
    out.friction = joint.dynamics->friction;
  }
  return out;
}

std::vector<PluginDescription> readPlugins(const SdfElement& parent) {
  std::vector<PluginDescription> out;
  for (const SdfElement& p : parent.children("plugin"))
    out.push_back({p.attribute("filename"), p.attribute("name"), p});
  return out;
}

// A <gazebo reference="link"> block: friction, contact correction, material and sensors of that link.
void readLinkBlock(const SdfElement& block, LinkDescription& link, ModelDescription& model) {
  link.mu1 = block.number("mu1", link.mu1, nonNegative());
  link.mu2 = block.number("mu2", link.mu2, nonNegative());
  // Gazebo's URDF importer turns <turnGravityOff> into SDF's <gravity>; either is accepted.
  link.gravity = !block.boolean("turnGravityOff", !link.gravity);
  link.gravity = block.boolean("gravity", link.gravity);
  // Gazebo's URDF importer writes these into every collision of the link as <surface><contact><ode>
  // max_vel and min_depth (a negative maxVel: only the world's limit, as there).
  if (const SdfElement max_vel = block.child("maxVel")) {
    const double v = max_vel.asNumber();
    for (CollisionShape& c : link.collisions) c.surface.max_vel = v;
  }
  if (const SdfElement min_depth = block.child("minDepth")) {
    const double d = min_depth.asNumber(nonNegative());
    for (CollisionShape& c : link.collisions) c.surface.min_depth = d;
  }
  if (const SdfElement material = block.child("material")) {
    // Gazebo paints every visual of the link with it, whatever the URDF's own <material> says.
    const auto colour = gazeboMaterialColour(material.text());
    if (colour) {
      for (VisualShape& v : link.visuals) v.rgba = *colour;
    } else {
      model.warnings.push_back(model.source + ": " + material.path() + ": unknown material '" + material.text() +
                               "' (the Gazebo/* colours are known); link '" + link.name + "' keeps its URDF colour");
    }
  }
  for (const SdfElement& sensor : block.children("sensor"))
    model.sensors.push_back({sensor.attribute("name"), sensor.attribute("type"), link.name, sensor, readPlugins(sensor)});
}

// Every <gazebo> block: SDF carried inside the URDF, as Gazebo's URDF importer reads it.
void readGazeboBlocks(const SdfElement& robot, ModelDescription& model) {
  for (const SdfElement& block : robot.children("gazebo")) {
    const std::string reference = block.attribute("reference");
    std::vector<PluginDescription> plugins = readPlugins(block);
    model.plugins.insert(model.plugins.end(), plugins.begin(), plugins.end());
    if (reference.empty()) {
      if (const SdfElement sensor = block.child("sensor"))
        sensor.fail("expected the sensor's <gazebo> block to name its link with reference='LINK'");
      continue;
    }
    LinkDescription* link = nullptr;
    for (auto& l : model.links)
      if (l.name == reference) link = &l;
    if (link) {
      readLinkBlock(block, *link, model);
      continue;
    }
    bool is_joint = false;
    for (const auto& j : model.joints) is_joint = is_joint || j.name == reference;
    if (!is_joint) {
      model.warnings.push_back(model.source + ": " + block.path() + ": no link or joint is named '" + reference +
                               "'; the block is ignored");
    } else if (block.child("sensor")) {
      block.child("sensor").fail("expected a link in reference='...', got the joint '" + reference + "'");
    }
  }
}

// Every <transmission>; ros_control decides what the interfaces mean.
void readTransmissions(const SdfElement& robot, ModelDescription& model) {
  for (const SdfElement& t : robot.children("transmission")) {
    TransmissionDescription out;
    out.name = t.attribute("name");
    out.type = t.child("type") ? t.child("type").text() : t.attribute("type");  // the old URDF spelling
    out.element = t;
    for (const SdfElement& j : t.children("joint")) {
      TransmissionDescription::Joint joint{j.attribute("name"), {}};
      for (const SdfElement& i : j.children("hardwareInterface")) joint.hardware_interfaces.push_back(i.text());
      out.joints.push_back(joint);
    }
    for (const SdfElement& a : t.children("actuator")) {
      TransmissionDescription::Actuator actuator;
      actuator.name = a.attribute("name");
      actuator.mechanical_reduction = a.number("mechanicalReduction", 1.0);
      for (const SdfElement& i : a.children("hardwareInterface")) actuator.hardware_interfaces.push_back(i.text());
      out.actuators.push_back(actuator);
    }
    model.transmissions.push_back(out);
  }
}

}  // namespace

ModelDescription parseUrdf(const std::string& xml, const std::string& source, const ResourceResolver& resolver,
                           const std::string& base_dir) {
  const Checker check(source);
  const SdfElement robot = SdfElement::parse(xml, source);
  if (robot.tag() != "robot") throw DescriptionError(source + ": expected a <robot> root element (is this URDF?)");

  urdf::ModelInterfaceSharedPtr urdf_model;
  {
    // console_bridge's handler is process-global; parse one URDF at a time.
    static std::mutex mutex;
    std::lock_guard<std::mutex> lock(mutex);
    CollectingOutputHandler handler;
    console_bridge::useOutputHandler(&handler);
    urdf_model = urdf::parseURDF(xml);
    console_bridge::restorePreviousOutputHandler();
    if (!urdf_model)
      throw DescriptionError(source + ": invalid URDF: " +
                             (handler.errors.empty() ? std::string("urdfdom rejected it") : handler.errors));
  }

  ModelDescription model;
  model.name = urdf_model->getName();
  model.source = source;
  const urdf::LinkConstSharedPtr root = urdf_model->getRoot();
  if (!root) throw DescriptionError(source + ": expected a tree of links with one root");
  model.root_link = root->name;
  model.fixed_base = root->name == "world";

  // Depth-first from the root so that every parent comes before its children.
  std::vector<urdf::LinkConstSharedPtr> stack{root};
  while (!stack.empty()) {
    urdf::LinkConstSharedPtr link = stack.back();
    stack.pop_back();
    model.links.push_back(convertLink(*link, *urdf_model, check, resolver, base_dir));
    if (link->parent_joint) model.joints.push_back(convertJoint(*link->parent_joint, check));
    for (auto it = link->child_links.rbegin(); it != link->child_links.rend(); ++it) stack.push_back(*it);
  }
  readGazeboBlocks(robot, model);
  readTransmissions(robot, model);
  return model;
}

}  // namespace bullet_sim
