#include "pioneer_ros/body_velocity_controller.h"

#include "numbers.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace pioneer_ros {

using numbers::clampTo;
using numbers::number;

namespace {

std::string validate(const AxisConfig& axis, const std::string& name) {
  const std::string gains = "controller_gains/body/" + name + "/";
  const std::pair<const char*, double> terms[] = {{"p", axis.p}, {"i", axis.i}, {"d", axis.d}};
  for (const auto& [term, value] : terms) {
    if (!std::isfinite(value)) return gains + term + ": expected a finite gain, got " + number(value);
  }
  // Comparisons written so that NaN fails them.
  if (axis.i_clamp && !(*axis.i_clamp >= 0.0))
    return gains + "i_clamp: expected a number >= 0, got " + number(*axis.i_clamp);
  if (!std::isfinite(axis.feedforward))
    return "feedforward/" + name + ": expected a finite number, got " + number(axis.feedforward);
  if (!(axis.limit > 0.0)) return "limits/" + name + ": expected a positive number, got " + number(axis.limit);
  return "";
}

}  // namespace

std::string validate(const ControllerConfig& config) {
  for (const std::string& problem : {validate(config.linear, "linear"), validate(config.angular, "angular")}) {
    if (!problem.empty()) return problem;
  }
  if (!(config.derivative_filter_time >= 0.0))
    return "derivative_filter_time: expected seconds >= 0, got " + number(config.derivative_filter_time);
  // A timer period of 1 / rate: infinity would make it 0.
  if (!(config.rate > 0.0) || !std::isfinite(config.rate))
    return "rate: expected a positive, finite number of Hz, got " + number(config.rate);
  if (!(config.cmd_timeout > 0.0))
    return "cmd_timeout: expected a positive number of seconds, got " + number(config.cmd_timeout);
  if (!(config.odom_timeout > 0.0))
    return "odom_timeout: expected a positive number of seconds, got " + number(config.odom_timeout);
  return "";
}

PidGains pidGains(const AxisConfig& axis, double derivative_filter_time) {
  PidGains gains;
  gains.p = axis.p;
  gains.i = axis.i;
  gains.d = axis.d;
  gains.i_clamp = axis.i_clamp.value_or(axis.limit);
  gains.output_min = -axis.limit;
  gains.output_max = axis.limit;
  gains.d_filter_time = derivative_filter_time;
  return gains;
}

namespace {

// Validates before the Pids are made, so that a bad configuration is reported by its
// parameter path rather than by a PidGains field.
const ControllerConfig& checked(const ControllerConfig& config) {
  const std::string problem = validate(config);
  if (!problem.empty()) throw std::invalid_argument(problem);
  return config;
}

}  // namespace

BodyVelocityController::BodyVelocityController(const ControllerConfig& config)
    : config_(checked(config)),
      linear_pid_(pidGains(config.linear, config.derivative_filter_time)),
      angular_pid_(pidGains(config.angular, config.derivative_filter_time)) {}

void BodyVelocityController::reset() {
  linear_pid_.reset();
  angular_pid_.reset();
  last_update_.reset();
}

void BodyVelocityController::setCommand(const PlanarVelocity& command, double stamp) {
  if (!std::isfinite(command.linear) || !std::isfinite(command.angular)) {
    throw std::invalid_argument("expected finite velocities, got " + number(command.linear) + ", " +
                                number(command.angular));
  }
  command_ = Stamped{command, stamp};
}

void BodyVelocityController::setMeasurement(const PlanarVelocity& measured, double stamp) {
  if (std::isfinite(measured.linear) && std::isfinite(measured.angular)) measurement_ = Stamped{measured, stamp};
}

std::optional<PlanarVelocity> BodyVelocityController::update(double now) {
  const ControllerConfig& c = config_;
  if (last_update_ && now < *last_update_) {  // the clock jumped back: a reset
    command_.reset();
    measurement_.reset();
    reset();
    mode_ = ControllerMode::kIdle;
  }
  if (!command_ || now - command_->stamp > c.cmd_timeout) {
    const bool was_active = mode_ != ControllerMode::kIdle;
    mode_ = ControllerMode::kIdle;
    reset();
    if (was_active) return PlanarVelocity{};
    return std::nullopt;
  }
  const PlanarVelocity command = command_->velocity;
  if (command.linear == 0.0 && command.angular == 0.0) {
    mode_ = ControllerMode::kStopped;
    reset();
    last_update_ = now;
    return PlanarVelocity{};
  }
  double dt = last_update_ ? now - *last_update_ : 0.0;
  last_update_ = now;
  const bool fresh = measurement_ && now - measurement_->stamp <= c.odom_timeout;
  if (!fresh) {
    mode_ = ControllerMode::kOpenLoop;
    linear_pid_.reset();
    angular_pid_.reset();
    return PlanarVelocity{clampTo(c.linear.feedforward * command.linear, -c.linear.limit, c.linear.limit),
                          clampTo(c.angular.feedforward * command.angular, -c.angular.limit, c.angular.limit)};
  }
  if (mode_ != ControllerMode::kClosedLoop) dt = 0.0;  // the first closed-loop step has no history to integrate over
  mode_ = ControllerMode::kClosedLoop;
  const PlanarVelocity measured = measurement_->velocity;
  return PlanarVelocity{
      linear_pid_.update(command.linear - measured.linear, dt, measured.linear,
                         c.linear.feedforward * command.linear),
      angular_pid_.update(command.angular - measured.angular, dt, measured.angular,
                          c.angular.feedforward * command.angular)};
}

}  // namespace pioneer_ros
