#include "bullet_sim_plugins/wheel_kinematics.h"

#include <algorithm>
#include <cmath>

namespace bullet_sim {

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
