#include "bullet_sim/drive_odometry.h"

#include <tinyxml2.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

#include "bullet_sim/description_error.h"

namespace bullet_sim {

// ---------------------------------------------------------------------------------------------
// Configuration
// ---------------------------------------------------------------------------------------------
namespace {

using tinyxml2::XMLElement;

const char* kDiffDriveFile = "libgazebo_ros_diff_drive.so";
const char* kSkidSteerFile = "libgazebo_ros_skid_steer_drive.so";

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r\n");
  if (b == std::string::npos) return "";
  return s.substr(b, s.find_last_not_of(" \t\r\n") - b + 1);
}

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

// Locale-independent and strict: the whole text must be a finite number (a leading '+' is allowed).
bool toDouble(const std::string& text, double& out) {
  const char* b = text.data();
  const char* e = b + text.size();
  if (b != e && *b == '+') ++b;
  const auto r = std::from_chars(b, e, out);
  return b != e && r.ec == std::errc() && r.ptr == e && std::isfinite(out);
}

// "<gazebo>", "<gazebo reference='x'>", "<plugin name='d' filename='libgazebo_ros_diff_drive.so'>".
std::string describe(const XMLElement* e) {
  std::string s = std::string("<") + e->Name();
  if (const char* n = e->Attribute("name")) s += std::string(" name='") + n + "'";
  if (const char* r = e->Attribute("reference")) s += std::string(" reference='") + r + "'";
  if (const char* f = e->Attribute("filename")) s += std::string(" filename='") + f + "'";
  return s + ">";
}

// Gazebo finds the library by file name; a path in front of it is allowed.
bool isPluginFile(const char* filename, const char* wanted) {
  if (!filename) return false;
  const std::string f(filename);
  return f.substr(f.find_last_of('/') + 1) == wanted;  // npos + 1 == 0
}

const char* jointTypeName(JointType t) {
  switch (t) {
    case JointType::Fixed: return "fixed";
    case JointType::Revolute: return "revolute";
    case JointType::Continuous: return "continuous";
    case JointType::Prismatic: return "prismatic";
  }
  return "unknown";
}

const auto kPositive = [](double v) { return v > 0; };
const auto kNonNegative = [](double v) { return v >= 0; };

// Reads the children of one <plugin>; every failure names the source, the element path and what
// was expected.
class PluginReader {
 public:
  PluginReader(const ModelDescription& model, const XMLElement* plugin, std::string where)
      : model_(model), plugin_(plugin), where_(std::move(where)) {}

  const std::string& where() const { return where_; }
  const char* name() const { return plugin_->Attribute("name") ? plugin_->Attribute("name") : ""; }

  [[noreturn]] void fail(const char* element, const std::string& what) const {
    throw DescriptionError(where_ + "/<" + element + ">: " + what);
  }

  // Trimmed text of child `element`; false (and `out` untouched) when there is none.
  bool text(const char* element, std::string& out) const {
    const XMLElement* e = plugin_->FirstChildElement(element);
    if (!e) return false;
    out = trim(e->GetText() ? e->GetText() : "");
    return true;
  }
  bool has(const char* element) const { return plugin_->FirstChildElement(element) != nullptr; }

  std::string string(const char* element, const std::string& fallback) const {
    std::string s = fallback;
    text(element, s);
    return s;
  }

  template <class Pred>
  double number(const char* element, double fallback, Pred ok, const std::string& expectation) const {
    std::string t;
    if (!text(element, t)) return fallback;
    double v = 0;
    if (!toDouble(t, v) || !ok(v)) fail(element, "expected a number " + expectation + ", got '" + t + "'");
    return v;
  }

  // gazebo_ros_utils takes true/false (any case); SDF's bool also takes 1/0.
  bool boolean(const char* element, bool fallback) const {
    std::string t;
    if (!text(element, t)) return fallback;
    const std::string l = lower(t);
    if (l == "true" || l == "1") return true;
    if (l == "false" || l == "0") return false;
    fail(element, "expected true or false (or 1 or 0), got '" + t + "'");
  }

  // A wheel: the name of a revolute or continuous joint of the model (`fallback` when missing, as upstream).
  std::string joint(const char* element, const std::string& fallback) const {
    std::string name = fallback;
    const bool given = text(element, name);
    const JointDescription* found = nullptr;
    for (const JointDescription& j : model_.joints)
      if (j.name == name) found = &j;
    if (found && (found->type == JointType::Revolute || found->type == JointType::Continuous)) return name;
    std::string got = "'" + name + "'";
    if (!given)
      got += std::string(" (the default, as <") + element + "> is missing)";
    else if (found)
      got += std::string(" (a ") + jointTypeName(found->type) + " joint)";
    fail(element, "expected a revolute or continuous joint of model '" + model_.name + "', got " + got);
  }

 private:
  const ModelDescription& model_;
  const XMLElement* plugin_;
  std::string where_;
};

// Finds the one <plugin> with `file` among the model's blocks (URDF: <gazebo><plugin>; SDF: the
// model's <plugin> itself) and reads it with `read(PluginReader&)`.
template <class Config, class Read>
std::optional<Config> parsePlugin(const ModelDescription& model, const char* file, Read read) {
  std::optional<Config> out;
  for (const GazeboExtension& block : model.extensions) {
    if (trim(block.xml).empty()) continue;
    tinyxml2::XMLDocument doc;
    if (doc.Parse(block.xml.c_str(), block.xml.size()) != tinyxml2::XML_SUCCESS) {
      const std::string block_where =
          block.reference.empty() ? "<gazebo>" : "<gazebo reference='" + block.reference + "'>";
      throw DescriptionError(model.source + ": " + block_where + ": malformed XML at line " +
                             std::to_string(doc.ErrorLineNum()) + ": " + doc.ErrorStr());
    }
    for (const XMLElement* root = doc.FirstChildElement(); root; root = root->NextSiblingElement()) {
      std::vector<std::pair<const XMLElement*, std::string>> plugins;
      if (std::string(root->Name()) == "plugin") {
        plugins.emplace_back(root, "");
      } else if (std::string(root->Name()) == "gazebo") {
        for (const XMLElement* p = root->FirstChildElement("plugin"); p; p = p->NextSiblingElement("plugin"))
          plugins.emplace_back(p, describe(root) + "/");
      }
      for (const auto& [plugin, prefix] : plugins) {
        if (!isPluginFile(plugin->Attribute("filename"), file)) continue;
        const std::string where = model.source + ": " + prefix + describe(plugin);
        if (out)
          throw DescriptionError(where + ": expected at most one " + file + " plugin in model '" + model.name +
                                 "', but " + out->where + " is one already");
        out = read(PluginReader(model, plugin, where));
      }
    }
  }
  return out;
}

OdometrySource odometrySource(const PluginReader& r, OdometrySource fallback) {
  std::string t;
  if (!r.text("odometrySource", t)) return fallback;
  const std::string l = lower(t);
  // Upstream's enum is ENCODER = 0, WORLD = 1; numbers are taken by those values.
  if (l == "encoder" || l == "0") return OdometrySource::Encoder;
  if (l == "world" || l == "1") return OdometrySource::World;
  r.fail("odometrySource", "expected world or encoder, got '" + t + "'");
}

}  // namespace

std::optional<DiffDriveConfig> parseDiffDrive(const ModelDescription& model) {
  return parsePlugin<DiffDriveConfig>(model, kDiffDriveFile, [](const PluginReader& r) {
    DiffDriveConfig c;
    c.plugin_name = r.name();
    c.where = r.where();
    c.robot_namespace_given = r.text("robotNamespace", c.robot_namespace);
    c.left_joint = r.joint("leftJoint", c.left_joint);
    c.right_joint = r.joint("rightJoint", c.right_joint);
    c.wheel_separation = r.number("wheelSeparation", c.wheel_separation, kPositive, "> 0 (m)");
    c.wheel_diameter = r.number("wheelDiameter", c.wheel_diameter, kPositive, "> 0 (m)");
    // <torque> is the name older tutorials use; <wheelTorque> wins when both are given.
    c.wheel_torque = r.number("torque", c.wheel_torque, kNonNegative, ">= 0 (N m)");
    c.wheel_torque = r.number("wheelTorque", c.wheel_torque, kNonNegative, ">= 0 (N m)");
    c.wheel_acceleration =
        r.number("wheelAcceleration", c.wheel_acceleration, kNonNegative, ">= 0 (m/s^2; 0 for unlimited)");
    c.command_topic = r.string("commandTopic", c.command_topic);
    c.odometry_topic = r.string("odometryTopic", c.odometry_topic);
    c.odometry_frame = r.string("odometryFrame", c.odometry_frame);
    c.robot_base_frame = r.string("robotBaseFrame", c.robot_base_frame);
    c.odometry_source = odometrySource(r, c.odometry_source);
    c.publish_tf = r.boolean("publishTf", c.publish_tf);
    c.publish_odom_tf = r.boolean("publishOdomTF", c.publish_odom_tf);
    c.publish_wheel_tf = r.boolean("publishWheelTF", c.publish_wheel_tf);
    c.publish_wheel_joint_state = r.boolean("publishWheelJointState", c.publish_wheel_joint_state);
    // Not validated: Noetic's plugin does not read it (removed in gazebo_plugins 2.8.3).
    std::string legacy;
    if (r.text("legacyMode", legacy)) c.legacy_mode = lower(legacy) == "true" || legacy == "1";
    c.update_rate = r.number("updateRate", c.update_rate, kNonNegative, ">= 0 (Hz; 0 for every step)");
    c.cmd_timeout = r.number("cmdTimeout", c.cmd_timeout, kNonNegative, ">= 0 (s; 0 for never)");
    return c;
  });
}

std::optional<SkidSteerDriveConfig> parseSkidSteerDrive(const ModelDescription& model) {
  return parsePlugin<SkidSteerDriveConfig>(model, kSkidSteerFile, [](const PluginReader& r) {
    SkidSteerDriveConfig c;
    c.plugin_name = r.name();
    c.where = r.where();
    c.robot_namespace_given = r.text("robotNamespace", c.robot_namespace);
    c.left_front_joint = r.joint("leftFrontJoint", c.left_front_joint);
    c.right_front_joint = r.joint("rightFrontJoint", c.right_front_joint);
    c.left_rear_joint = r.joint("leftRearJoint", c.left_rear_joint);
    c.right_rear_joint = r.joint("rightRearJoint", c.right_rear_joint);
    c.wheel_separation = r.number("wheelSeparation", c.wheel_separation, kPositive, "> 0 (m)");
    c.wheel_diameter = r.number("wheelDiameter", c.wheel_diameter, kPositive, "> 0 (m)");
    c.torque = r.number("torque", c.torque, kNonNegative, ">= 0 (N m)");
    c.command_topic = r.string("commandTopic", c.command_topic);
    c.odometry_topic = r.string("odometryTopic", c.odometry_topic);
    c.odometry_frame = r.string("odometryFrame", c.odometry_frame);
    c.robot_base_frame = r.string("robotBaseFrame", c.robot_base_frame);
    c.broadcast_tf = r.boolean("broadcastTF", c.broadcast_tf);
    c.update_rate = r.number("updateRate", c.update_rate, kNonNegative, ">= 0 (Hz; 0 for every step)");
    c.covariance_x = r.number("covariance_x", c.covariance_x, kNonNegative, ">= 0");
    c.covariance_y = r.number("covariance_y", c.covariance_y, kNonNegative, ">= 0");
    c.covariance_yaw = r.number("covariance_yaw", c.covariance_yaw, kNonNegative, ">= 0");
    c.cmd_timeout = r.number("cmdTimeout", c.cmd_timeout, kNonNegative, ">= 0 (s; 0 for never)");
    return c;
  });
}

std::string diffDriveNamespace(const DiffDriveConfig& config, const std::string& spawn_namespace,
                               const std::string& model_name) {
  if (config.robot_namespace_given) return config.robot_namespace.empty() ? model_name : config.robot_namespace;
  return spawn_namespace.empty() ? model_name : spawn_namespace;
}

std::string skidSteerNamespace(const SkidSteerDriveConfig& config, const std::string& spawn_namespace) {
  return config.robot_namespace_given ? config.robot_namespace : spawn_namespace;
}

std::string resolveFrame(const std::string& tf_prefix, const std::string& frame) {
  if (!frame.empty() && frame[0] == '/') return frame.substr(1);
  const auto b = tf_prefix.find_first_not_of('/');
  if (b == std::string::npos) return frame;
  const std::string prefix = tf_prefix.substr(b, tf_prefix.find_last_not_of('/') - b + 1);
  return prefix + "/" + frame;
}

// ---------------------------------------------------------------------------------------------
// Kinematics, ramp, timeout, odometry
// ---------------------------------------------------------------------------------------------

WheelSpeeds wheelSpeeds(double linear, double angular, double wheel_separation, double wheel_diameter) {
  const double radius = wheel_diameter / 2.0;
  return WheelSpeeds{(linear - angular * wheel_separation / 2.0) / radius,
                     (linear + angular * wheel_separation / 2.0) / radius};
}

double rampToward(double current, double target, double max_change) {
  if (!(max_change >= 0)) max_change = 0;  // NaN or negative: hold
  return current + std::clamp(target - current, -max_change, max_change);
}

DriveCommand::DriveCommand(double wheel_separation, double wheel_diameter, double wheel_acceleration,
                           double cmd_timeout)
    : wheel_separation_(wheel_separation),
      wheel_diameter_(wheel_diameter),
      wheel_acceleration_(wheel_acceleration),
      cmd_timeout_(cmd_timeout) {}

void DriveCommand::setTwist(double linear, double angular, double time) {
  has_command_ = true;
  linear_ = linear;
  angular_ = angular;
  command_time_ = time;
}

bool DriveCommand::timedOut(double time) const {
  return has_command_ && cmd_timeout_ > 0 && time - command_time_ > cmd_timeout_;
}

WheelSpeeds DriveCommand::update(double time, double dt) {
  WheelSpeeds target;
  if (has_command_ && !timedOut(time)) target = wheelSpeeds(linear_, angular_, wheel_separation_, wheel_diameter_);
  if (wheel_acceleration_ <= 0) {
    current_ = target;
  } else {
    const double max_change = wheel_acceleration_ / (wheel_diameter_ / 2.0) * std::max(dt, 0.0);
    current_.left = rampToward(current_.left, target.left, max_change);
    current_.right = rampToward(current_.right, target.right, max_change);
  }
  return current_;
}

void DriveCommand::reset() {
  has_command_ = false;
  linear_ = angular_ = command_time_ = 0.0;
  current_ = WheelSpeeds();
}

EncoderOdometry::EncoderOdometry(double wheel_separation, double wheel_diameter)
    : wheel_separation_(wheel_separation), wheel_radius_(wheel_diameter / 2.0) {}

void EncoderOdometry::reset(double x, double y, double heading) {
  x_ = x;
  y_ = y;
  heading_ = heading;
  distance_ = 0.0;
}

void EncoderOdometry::integrate(double left_rotation, double right_rotation) {
  const double left = left_rotation * wheel_radius_;
  const double right = right_rotation * wheel_radius_;
  const double ds = (left + right) / 2.0;
  const double dtheta = (right - left) / wheel_separation_;
  if (std::abs(dtheta) < 1e-6) {
    // Nearly straight: the arc formula would divide by ~0; the mid-heading step is exact to O(dtheta^2).
    const double mid = heading_ + dtheta / 2.0;
    x_ += ds * std::cos(mid);
    y_ += ds * std::sin(mid);
  } else {
    const double r = ds / dtheta;  // turning radius of the base
    x_ += r * (std::sin(heading_ + dtheta) - std::sin(heading_));
    y_ -= r * (std::cos(heading_ + dtheta) - std::cos(heading_));
  }
  heading_ += dtheta;
  distance_ += ds;
}

void EncoderOdometry::update(double left_angle, double right_angle) {
  if (has_reference_) integrate(left_angle - left_reference_, right_angle - right_reference_);
  has_reference_ = true;
  left_reference_ = left_angle;
  right_reference_ = right_angle;
}

}  // namespace bullet_sim
