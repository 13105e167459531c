#include "bullet_sim_ros_control/ros_control_config.h"

namespace bullet_sim {

RosControlConfig parseRosControlConfig(const PluginDescription& plugin, const std::string& model_name) {
  const SdfElement& p = plugin.element;
  RosControlConfig c;
  c.robot_namespace = p.string("robotNamespace", "");
  if (c.robot_namespace.empty()) c.robot_namespace = model_name;
  c.control_period = p.number("controlPeriod", 0.0, {[](double v) { return v >= 0; }, ">= 0 (s)"});
  c.robot_param = p.string("robotParam", c.robot_param);
  return c;
}

std::vector<TransmissionJoint> transmissionJoints(const ModelDescription& model) {
  std::vector<TransmissionJoint> out;
  for (const TransmissionDescription& t : model.transmissions) {
    if (t.type.find("SimpleTransmission") == std::string::npos) {
      const SdfElement type = t.element.child("type");
      (type ? type : t.element).fail("expected transmission_interface/SimpleTransmission, got '" + t.type + "'");
    }
    for (const SdfElement& joint : t.element.children("joint")) {
      // The interface is on the joint (current format) or on the actuator (older tutorials).
      SdfElement interface = joint.child("hardwareInterface");
      if (!interface) interface = t.element.child("actuator").child("hardwareInterface");
      TransmissionJoint tj{joint.attribute("name")};
      if (!sim_control::parseInterfaceName(interface.text(), tj.interface))
        (interface ? interface : joint.child("hardwareInterface"))
            .fail("expected EffortJointInterface, PositionJointInterface or VelocityJointInterface (with or "
                  "without 'hardware_interface/'), got '" + interface.text() + "'");
      out.push_back(tj);
    }
  }
  return out;
}

}  // namespace bullet_sim
