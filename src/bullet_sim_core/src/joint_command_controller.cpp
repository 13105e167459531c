#include "bullet_sim_core/joint_command_controller.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace bullet_sim {
namespace {

std::string notFinite(const std::string& field, double value, bool bound) {
  if (bound ? !std::isnan(value) : std::isfinite(value)) return "";
  std::ostringstream text;
  text << field << ": expected a " << (bound ? "number (infinite is no bound)" : "finite number") << ", got "
       << (std::isnan(value) ? "nan" : value > 0 ? "inf" : "-inf");
  return text.str();
}

std::string validatePid(const std::string& name, const PidTarget& t) {
  const std::pair<const char*, double> finite[] = {
      {"target", t.target}, {"p", t.gains.p}, {"i", t.gains.i}, {"d", t.gains.d}};
  const std::pair<const char*, double> bounds[] = {
      {"i_max", t.gains.i_max}, {"i_min", t.gains.i_min}, {"cmd_max", t.gains.cmd_max}, {"cmd_min", t.gains.cmd_min}};
  for (const auto& [field, value] : finite)
    if (std::string e = notFinite(name + "." + field, value, false); !e.empty()) return e;
  for (const auto& [field, value] : bounds)
    if (std::string e = notFinite(name + "." + field, value, true); !e.empty()) return e;
  return "";
}

}  // namespace

std::string validate(const JointCommand& command) {
  if (command.force)
    if (std::string e = notFinite("force", *command.force, false); !e.empty()) return e;
  if (command.position)
    if (std::string e = validatePid("position", *command.position); !e.empty()) return e;
  if (command.velocity)
    if (std::string e = validatePid("velocity", *command.velocity); !e.empty()) return e;
  return "";
}

JointCommandController::JointCommandController(double effort_limit)
    : effort_limit_(effort_limit > 0 ? effort_limit : std::numeric_limits<double>::infinity()) {}

void JointCommandController::command(const JointCommand& command) {
  if (command.reset) {
    force_.reset();
    position_.reset();
    velocity_.reset();
  }
  if (command.force) force_ = command.force;
  // A PID that takes up a target afresh starts from nothing; one already holding keeps its integral.
  // Either way the rate term starts again, so a jump in the target gives no kick.
  if (command.position) {
    if (!position_) position_pid_.reset();
    position_ = command.position;
    position_pid_.setGains(position_->gains);
    position_pid_.forgetLastError();
  }
  if (command.velocity) {
    if (!velocity_) velocity_pid_.reset();
    velocity_ = command.velocity;
    velocity_pid_.setGains(velocity_->gains);
    velocity_pid_.forgetLastError();
  }
}

double JointCommandController::limited(double effort) const {
  return std::clamp(effort, -effort_limit_, effort_limit_);
}

double JointCommandController::effort(double position, double velocity, double dt) {
  double sum = force_ ? limited(*force_) : 0.0;
  if (position_) sum += limited(position_pid_.update(position - position_->target, dt));
  if (velocity_) sum += limited(velocity_pid_.update(velocity - velocity_->target, dt));
  return limited(sum);
}

}  // namespace bullet_sim
