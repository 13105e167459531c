#include "bullet_sim/ros_control_plugin.h"

#include <tinyxml2.h>

#include <algorithm>
#include <cmath>

#include "bullet_sim/description_error.h"

namespace bullet_sim {
namespace {

const char* kPluginFile = "libgazebo_ros_control.so";
// A motor needs a finite force bound; joints without an effort limit get a generous one.
constexpr double kUnlimitedMotorForce = 1e4;
// PyBullet's POSITION_CONTROL default: close 10 % of the position error per step.
constexpr double kMotorPositionGain = 0.1;

std::string text(const tinyxml2::XMLElement* parent, const char* child) {
  const tinyxml2::XMLElement* e = parent ? parent->FirstChildElement(child) : nullptr;
  return e && e->GetText() ? e->GetText() : "";
}

std::string trim(std::string s) {
  const auto b = s.find_first_not_of(" \t\r\n");
  const auto e = s.find_last_not_of(" \t\r\n");
  return b == std::string::npos ? "" : s.substr(b, e - b + 1);
}

double wrapAngle(double a) { return std::remainder(a, 2.0 * M_PI); }

}  // namespace

bool findRosControlPlugin(const ModelDescription& model, RosControlConfig& config) {
  for (const GazeboExtension& ext : model.extensions) {
    tinyxml2::XMLDocument doc;
    if (doc.Parse(ext.xml.c_str()) != tinyxml2::XML_SUCCESS) continue;
    for (auto* plugin = doc.RootElement()->FirstChildElement("plugin"); plugin;
         plugin = plugin->NextSiblingElement("plugin")) {
      const char* file = plugin->Attribute("filename");
      if (!file || std::string(file) != kPluginFile) continue;
      config.robot_namespace = trim(text(plugin, "robotNamespace"));
      if (config.robot_namespace.empty()) config.robot_namespace = model.name;
      const std::string period = trim(text(plugin, "controlPeriod"));
      if (!period.empty()) {
        char* end = nullptr;
        config.control_period = std::strtod(period.c_str(), &end);
        if (*end != '\0' || !std::isfinite(config.control_period) || config.control_period < 0)
          throw DescriptionError(model.source + ": <gazebo>/<plugin filename='" + kPluginFile +
                                 "'>/<controlPeriod>: expected a period in seconds, got '" + period + "'");
      }
      const std::string param = trim(text(plugin, "robotParam"));
      if (!param.empty()) config.robot_param = param;
      return true;
    }
  }
  return false;
}

std::vector<TransmissionJoint> parseTransmissions(const ModelDescription& model) {
  std::vector<TransmissionJoint> out;
  tinyxml2::XMLDocument doc;
  if (doc.Parse(model.robot_xml.c_str()) != tinyxml2::XML_SUCCESS || !doc.FirstChildElement("robot")) return out;
  for (auto* t = doc.FirstChildElement("robot")->FirstChildElement("transmission"); t;
       t = t->NextSiblingElement("transmission")) {
    const std::string name = t->Attribute("name") ? t->Attribute("name") : "";
    const std::string where = model.source + ": <transmission name='" + name + "'>";
    std::string type = trim(text(t, "type"));
    if (type.empty() && t->Attribute("type")) type = t->Attribute("type");  // the old URDF spelling
    if (type.find("SimpleTransmission") == std::string::npos) {
      throw DescriptionError(where + "/<type>: expected transmission_interface/SimpleTransmission, got '" + type +
                             "'");
    }
    const tinyxml2::XMLElement* actuator = t->FirstChildElement("actuator");
    for (auto* j = t->FirstChildElement("joint"); j; j = j->NextSiblingElement("joint")) {
      TransmissionJoint tj;
      tj.joint = j->Attribute("name") ? j->Attribute("name") : "";
      // The interface is on the joint (current format) or on the actuator (older tutorials).
      std::string interface = trim(text(j, "hardwareInterface"));
      if (interface.empty()) interface = trim(text(actuator, "hardwareInterface"));
      if (!sim_control::parseInterfaceName(interface, tj.interface))
        throw DescriptionError(where + "/<joint name='" + tj.joint + "'>/<hardwareInterface>: expected "
                               "EffortJointInterface, PositionJointInterface or VelocityJointInterface (with or "
                               "without 'hardware_interface/'), got '" + interface + "'");
      const std::string reduction = trim(text(actuator, "mechanicalReduction"));
      if (!reduction.empty()) tj.mechanical_reduction = std::atof(reduction.c_str());
      out.push_back(tj);
    }
  }
  return out;
}

RosControlPlugin::RosControlPlugin(PhysicsModel& model, const RosControlConfig& config, double step_size)
    : model_(model), control_period_(std::max(config.control_period, step_size)) {
  const std::vector<TransmissionJoint> transmissions = parseTransmissions(model.description());
  hw_.joints().reserve(transmissions.size());  // JointData pointers must stay valid
  ros::NodeHandle robot_nh(config.robot_namespace);
  for (const TransmissionJoint& t : transmissions) {
    const int j = model.jointIndex(t.joint);
    if (j < 0) {
      throw DescriptionError(model.description().source + ": <transmission> joint '" + t.joint +
                             "': expected a revolute, continuous or prismatic joint of model '" + model.name() + "'");
    }
    const JointDescription& d = model.joints()[j];
    sim_control::JointLimits limits;
    limits.continuous = d.type == JointType::Continuous;
    limits.has_position_limits = d.type == JointType::Revolute || d.type == JointType::Prismatic;
    limits.lower = d.lower;
    limits.upper = d.upper;
    limits.effort = d.effort_limit;
    limits.velocity = d.velocity_limit;
    Actuated a{j, &hw_.addJoint(t.joint, t.interface, limits)};
    if (t.interface == sim_control::InterfaceType::Position) a.data->command = model.jointPosition(j);
    // gazebo_ros_control's optional PID for position/velocity joints.
    ros::NodeHandle gains(robot_nh, "gazebo_ros_control/pid_gains/" + t.joint);
    if (t.interface != sim_control::InterfaceType::Effort && gains.hasParam("p")) {
      std::string error;
      if (!a.pid.init(gains, error)) throw DescriptionError(error);
      a.has_pid = true;
    }
    actuated_.push_back(a);
  }
  if (actuated_.empty())
    ROS_WARN_STREAM("model '" << model.name() << "': " << kPluginFile
                              << " found no <transmission>; its controllers will have no joints to command");
  readState();
  manager_ = std::make_unique<sim_control::ControllerManager>(hw_, robot_nh);
  ROS_INFO_STREAM("model '" << model.name() << "': controller manager at " << robot_nh.resolveName("controller_manager")
                            << " for " << actuated_.size() << " joints, control period " << control_period_.toSec()
                            << " s");
}

void RosControlPlugin::readState() {
  for (Actuated& a : actuated_) {
    a.data->position = model_.jointPosition(a.physics_joint);
    a.data->velocity = model_.jointVelocity(a.physics_joint);
    a.data->effort = model_.jointEffort(a.physics_joint) + model_.jointMotorForce(a.physics_joint);
  }
}

void RosControlPlugin::beforeStep(const ros::Time& now, double dt) {
  readState();
  if (last_update_.isZero() || now - last_update_ >= control_period_ - ros::Duration(1e-9)) {
    const ros::Duration period = last_update_.isZero() ? control_period_ : now - last_update_;
    manager_->update(now, period);
    last_update_ = now;
  }
  applyCommands(dt);
}

void RosControlPlugin::applyCommands(double dt) {
  for (Actuated& a : actuated_) {
    const sim_control::JointData& d = *a.data;
    if (!manager_->isDriven(d.name)) {
      // No running controller: the joint is free (upstream would keep applying the last command).
      model_.clearJointMotor(a.physics_joint);
      continue;
    }
    const double limit = d.limits.effort;
    const double command = std::isfinite(d.command) ? d.command : 0.0;
    double effort = 0.0;
    switch (d.interface) {
      case sim_control::InterfaceType::Effort:
        effort = command;
        break;
      case sim_control::InterfaceType::Position:
        if (!a.has_pid) {
          const double target = d.limits.has_position_limits ? std::clamp(command, d.limits.lower, d.limits.upper)
                                                             : command;
          // Continuous joints go the short way round.
          const double goal = d.limits.continuous ? d.position + wrapAngle(target - d.position) : target;
          model_.setJointMotor(a.physics_joint, goal, 0.0, kMotorPositionGain,
                               std::isfinite(limit) ? limit : kUnlimitedMotorForce);
          continue;
        }
        effort = a.pid.compute(d.limits.continuous ? wrapAngle(command - d.position) : command - d.position, dt);
        break;
      case sim_control::InterfaceType::Velocity:
        if (!a.has_pid) {
          model_.setJointMotor(a.physics_joint, 0.0, command, 0.0, std::isfinite(limit) ? limit : kUnlimitedMotorForce);
          continue;
        }
        effort = a.pid.compute(command - d.velocity, dt);
        break;
    }
    model_.addJointEffort(a.physics_joint, std::clamp(effort, -limit, limit));
  }
}

void RosControlPlugin::reset() {
  last_update_ = ros::Time();
  for (Actuated& a : actuated_) {
    a.pid.reset();
    if (a.data->interface == sim_control::InterfaceType::Position) a.data->command = model_.jointPosition(a.physics_joint);
  }
}

}  // namespace bullet_sim
