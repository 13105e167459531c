#include "bullet_sim_plugins/katana_gripper_config.h"

#include <algorithm>
#include <cmath>

#include "bullet_sim_core/description_error.h"

namespace bullet_sim {
namespace {

// A finger: a moving joint of the model named by `tag` (`fallback` when the element is absent).
const JointDescription& fingerJoint(const SdfElement& plugin, const char* tag, const std::string& fallback,
                                    const ModelDescription& model) {
  const SdfElement e = plugin.child(tag);
  const std::string name = plugin.name(tag, fallback);
  for (const JointDescription& j : model.joints)
    if (j.name == name) {
      if (j.type != JointType::Fixed) return j;
      e.fail("expected a revolute, continuous or prismatic joint of model '" + model.name + "', got '" + name +
             "' (a fixed joint)");
    }
  e.fail("model '" + model.name + "' has no joint '" + name + "'" +
         (e ? std::string() : std::string(" (the default, as <") + tag + "> is missing)"));
}

}  // namespace

KatanaGripperConfig parseKatanaGripperConfig(const PluginDescription& plugin, const ModelDescription& model) {
  const SdfElement& p = plugin.element;
  KatanaGripperConfig c;
  const JointDescription& r = fingerJoint(p, "r_finger_joint", c.r_finger_joint, model);
  const JointDescription& l = fingerJoint(p, "l_finger_joint", c.l_finger_joint, model);
  c.r_finger_joint = r.name;
  c.l_finger_joint = l.name;
  if (c.l_finger_joint == c.r_finger_joint)
    p.child("l_finger_joint").fail("expected a joint other than <r_finger_joint> ('" + c.r_finger_joint + "')");
  // The setpoint moves at the slower finger's velocity limit; URDF's 0 (or none) means no limit.
  for (const JointDescription* j : {&r, &l})
    if (j->velocity_limit > 0 && std::isfinite(j->velocity_limit))
      c.options.max_velocity = std::min(c.options.max_velocity, j->velocity_limit);
  c.options.max_torque = p.number("max_torque", c.options.max_torque, positive());
  c.node_namespace = p.string("node_namespace", c.node_namespace);
  const std::string problems = validate(c.options);
  if (!problems.empty()) p.fail(problems);
  return c;
}

}  // namespace bullet_sim
