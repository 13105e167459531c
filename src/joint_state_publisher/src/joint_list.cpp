#include "joint_state_publisher/joint_list.h"

#include <tinyxml2.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace joint_state_publisher {
namespace {

// A number attribute, or `fallback` when it is absent; throws naming the joint when it is not a number.
double attribute(const tinyxml2::XMLElement* e, const char* name, double fallback, const std::string& joint) {
  const char* text = e->Attribute(name);
  if (!text) return fallback;
  char* end = nullptr;
  const double value = std::strtod(text, &end);
  if (end == text || *end != '\0' || !std::isfinite(value))
    throw JointListError("joint '" + joint + "': <" + e->Name() + " " + name + "=\"" + text +
                         "\">: expected a number");
  return value;
}

}  // namespace

JointList::JointList(const std::string& urdf, const Options& options) : dependent_(options.dependent_joints) {
  tinyxml2::XMLDocument doc;
  if (doc.Parse(urdf.c_str()) != tinyxml2::XML_SUCCESS)
    throw JointListError(std::string("robot_description is not XML: ") + doc.ErrorStr());
  const tinyxml2::XMLElement* robot = doc.FirstChildElement("robot");
  if (!robot) {
    if (doc.FirstChildElement("COLLADA"))
      throw JointListError("robot_description is a COLLADA document; only URDF is supported here");
    throw JointListError("robot_description has no <robot> element: expected a URDF");
  }
  for (const tinyxml2::XMLElement* j = robot->FirstChildElement("joint"); j; j = j->NextSiblingElement("joint")) {
    const char* type_text = j->Attribute("type");
    const std::string type = type_text ? type_text : "";
    if (type == "fixed" || type == "floating" || type == "planar") continue;
    const char* name_text = j->Attribute("name");
    if (!name_text) {
      warnings_.push_back("a <joint> without a name is left out");
      continue;
    }
    const std::string name = name_text;
    FreeJoint joint;
    if (type == "continuous") {
      joint.min = -M_PI;
      joint.max = M_PI;
      joint.continuous = true;
    } else {
      const tinyxml2::XMLElement* limit = j->FirstChildElement("limit");
      if (!limit) {  // upstream warns, then fails on its first message
        warnings_.push_back(name + " is not fixed, nor continuous, but limits are not specified! It is left out.");
        continue;
      }
      joint.min = attribute(limit, "lower", 0.0, name);  // URDF's defaults
      joint.max = attribute(limit, "upper", 0.0, name);
    }
    const tinyxml2::XMLElement* safety = j->FirstChildElement("safety_controller");
    if (options.use_smallest_joint_limits && safety && !safety->NextSiblingElement("safety_controller")) {
      joint.min = std::max(joint.min, attribute(safety, "soft_lower_limit", joint.min, name));
      joint.max = std::min(joint.max, attribute(safety, "soft_upper_limit", joint.max, name));
    }
    order_.push_back(name);
    const tinyxml2::XMLElement* mimic = j->FirstChildElement("mimic");
    if (options.use_mimic_tags && mimic && !mimic->NextSiblingElement("mimic")) {
      const char* parent = mimic->Attribute("joint");
      dependent_[name] = {parent ? parent : "", attribute(mimic, "multiplier", 1.0, name),
                          attribute(mimic, "offset", 0.0, name)};
      continue;
    }
    if (dependent_.count(name)) continue;
    // Upstream's rule: a zero of 0 (or none) becomes the middle of a range that excludes 0.
    const auto zero = options.zeros.find(name);
    joint.zero = zero != options.zeros.end() ? zero->second : 0.0;
    if (joint.zero == 0.0 && (joint.min > 0 || joint.max < 0)) joint.zero = (joint.min + joint.max) / 2;
    if (options.publish_default_positions) joint.position = joint.zero;
    if (options.publish_default_velocities) joint.velocity = 0.0;
    if (options.publish_default_efforts) joint.effort = 0.0;
    free_[name] = joint;
  }
  // Each dependent joint resolved down its chain to a free joint: factor and offset composed.
  std::map<std::string, Options::Dependent> resolved;
  for (const std::string& name : order_) {
    auto it = dependent_.find(name);
    if (it == dependent_.end()) continue;
    Options::Dependent d = it->second;
    std::vector<std::string> chain{name};
    while (dependent_.count(d.parent)) {
      if (std::find(chain.begin(), chain.end(), d.parent) != chain.end()) {
        std::string joints;
        for (const std::string& c : chain) joints += c + ", ";
        throw JointListError("Found an infinite recursive mimic chain: [" + joints + d.parent + "]");
      }
      chain.push_back(d.parent);
      const Options::Dependent& next = dependent_.at(d.parent);
      d.offset += d.factor * next.offset;
      d.factor *= next.factor;
      d.parent = next.parent;
    }
    if (!free_.count(d.parent)) {
      warnings_.push_back(name + " follows '" + d.parent + "', which is not a moving joint of the URDF; it is left out");
      continue;
    }
    resolved[name] = d;
  }
  dependent_ = resolved;
  std::vector<std::string> published;
  for (const std::string& name : order_)
    if (free_.count(name) || dependent_.count(name)) published.push_back(name);
  order_ = published;
}

void JointList::set(const std::string& name, std::optional<double> position, std::optional<double> velocity,
                    std::optional<double> effort) {
  auto it = free_.find(name);
  if (it == free_.end()) return;
  if (position) it->second.position = position;
  if (velocity) it->second.velocity = velocity;
  if (effort) it->second.effort = effort;
}

void JointList::sweep(double delta) {
  for (auto& [name, j] : free_) {
    if (!j.position) continue;
    double& p = *j.position;
    if (j.forward) {
      p += delta;
      if (p > j.max) {
        p = j.continuous ? j.min : j.max;
        if (!j.continuous) j.forward = false;
      }
    } else {
      p -= delta;
      if (p < j.min) {
        p = j.continuous ? j.max : j.min;
        if (!j.continuous) j.forward = true;
      }
    }
  }
}

JointStateArrays JointList::arrays() const {
  bool has_position = !dependent_.empty(), has_velocity = false, has_effort = false;
  for (const auto& [name, j] : free_) {
    has_position = has_position || j.position.has_value();
    has_velocity = has_velocity || j.velocity.has_value();
    has_effort = has_effort || j.effort.has_value();
  }
  JointStateArrays out;
  const size_t n = order_.size();
  if (has_position) out.position.assign(n, 0.0);
  if (has_velocity) out.velocity.assign(n, 0.0);
  if (has_effort) out.effort.assign(n, 0.0);
  for (size_t i = 0; i < n; ++i) {
    const std::string& name = order_[i];
    out.name.push_back(name);
    double factor = 1.0, offset = 0.0;
    const FreeJoint* joint;
    if (auto d = dependent_.find(name); d != dependent_.end()) {
      factor = d->second.factor;
      offset = d->second.offset;
      joint = &free_.at(d->second.parent);
    } else {
      joint = &free_.at(name);
    }
    if (has_position && joint->position) out.position[i] = *joint->position * factor + offset;
    if (has_velocity && joint->velocity) out.velocity[i] = *joint->velocity * factor;
    if (has_effort && joint->effort) out.effort[i] = *joint->effort;
  }
  return out;
}

}  // namespace joint_state_publisher
