#include "sim_control/diff_drive_kinematics.h"

#include <algorithm>
#include <cmath>

namespace sim_control {
namespace diff_drive {

WheelVelocities inverseKinematics(double linear, double angular, double wheel_separation,
                                  double left_wheel_radius, double right_wheel_radius) {
  WheelVelocities w;
  w.left = (linear - angular * wheel_separation / 2.0) / left_wheel_radius;
  w.right = (linear + angular * wheel_separation / 2.0) / right_wheel_radius;
  return w;
}

BodyTwist forwardKinematics(double left_wheel_velocity, double right_wheel_velocity, double wheel_separation,
                            double left_wheel_radius, double right_wheel_radius) {
  const double left = left_wheel_velocity * left_wheel_radius;  // contact point speeds, m/s
  const double right = right_wheel_velocity * right_wheel_radius;
  BodyTwist t;
  t.linear = (right + left) * 0.5;
  t.angular = (right - left) / wheel_separation;
  return t;
}

// --- RollingMean ---

RollingMean::RollingMean(std::size_t size) : size_(std::max<std::size_t>(size, 1)) { samples_.reserve(size_); }

void RollingMean::push(double value) {
  if (samples_.size() < size_) {
    samples_.push_back(value);
  } else {
    samples_[next_] = value;
    next_ = (next_ + 1) % size_;
  }
}

double RollingMean::mean() const {
  if (samples_.empty()) return 0.0;
  double sum = 0.0;  // summed afresh each time: no drift from a running sum
  for (double s : samples_) sum += s;
  return sum / static_cast<double>(samples_.size());
}

void RollingMean::reset() {
  samples_.clear();
  next_ = 0;
}

// --- Odometry ---

Odometry::Odometry(std::size_t velocity_rolling_window_size)
    : linear_mean_(velocity_rolling_window_size), angular_mean_(velocity_rolling_window_size) {}

void Odometry::init(double time) {
  linear_mean_.reset();
  angular_mean_.reset();
  timestamp_ = time;
}

bool Odometry::update(double left_position, double right_position, double time) {
  const double left_cur = left_position * left_wheel_radius_;  // arc length rolled, m
  const double right_cur = right_position * right_wheel_radius_;
  if (!has_wheel_positions_) {
    left_wheel_old_pos_ = left_cur;
    right_wheel_old_pos_ = right_cur;
    has_wheel_positions_ = true;
  }
  const double left_delta = left_cur - left_wheel_old_pos_;
  const double right_delta = right_cur - right_wheel_old_pos_;
  left_wheel_old_pos_ = left_cur;
  right_wheel_old_pos_ = right_cur;

  const double linear = (right_delta + left_delta) * 0.5;
  const double angular = (right_delta - left_delta) / wheel_separation_;
  integrate(linear, angular);

  if (time < timestamp_) timestamp_ = time;  // time went backwards (simulation reset)
  const double dt = time - timestamp_;
  if (dt < 0.0001) return false;  // too short an interval to estimate a velocity from
  timestamp_ = time;

  linear_mean_.push(linear / dt);
  angular_mean_.push(angular / dt);
  linear_ = linear_mean_.mean();
  angular_ = angular_mean_.mean();
  return true;
}

void Odometry::updateOpenLoop(double linear, double angular, double time) {
  linear_ = linear;
  angular_ = angular;
  double dt = time - timestamp_;
  if (dt < 0.0) dt = 0.0;  // time went backwards (simulation reset)
  timestamp_ = time;
  integrate(linear * dt, angular * dt);
}

void Odometry::integrate(double linear, double angular) {
  if (std::fabs(angular) < 1e-6)
    integrateRungeKutta2(linear, angular);
  else
    integrateExact(linear, angular);
}

void Odometry::integrateRungeKutta2(double linear, double angular) {
  const double direction = heading_ + angular * 0.5;  // heading at the middle of the step
  x_ += linear * std::cos(direction);
  y_ += linear * std::sin(direction);
  heading_ += angular;
}

void Odometry::integrateExact(double linear, double angular) {
  const double heading_old = heading_;
  const double r = linear / angular;  // signed radius of the arc
  heading_ += angular;
  x_ += r * (std::sin(heading_) - std::sin(heading_old));
  y_ += -r * (std::cos(heading_) - std::cos(heading_old));
}

void Odometry::setWheelParams(double wheel_separation, double left_wheel_radius, double right_wheel_radius) {
  wheel_separation_ = wheel_separation;
  left_wheel_radius_ = left_wheel_radius;
  right_wheel_radius_ = right_wheel_radius;
}

void Odometry::setVelocityRollingWindowSize(std::size_t size) {
  linear_mean_ = RollingMean(size);
  angular_mean_ = RollingMean(size);
}

void Odometry::resetPose(double x, double y, double heading) {
  x_ = x;
  y_ = y;
  heading_ = heading;
}

// --- SpeedLimiter ---

namespace {
double clamp(double v, double lo, double hi) { return std::min(std::max(v, lo), hi); }
double ratio(double limited, double requested) { return requested != 0.0 ? limited / requested : 1.0; }
}  // namespace

double SpeedLimiter::limit(double& v, double v0, double v1, double dt) const {
  const double requested = v;
  limitJerk(v, v0, v1, dt);
  limitAcceleration(v, v0, dt);
  limitVelocity(v);
  return ratio(v, requested);
}

double SpeedLimiter::limitVelocity(double& v) const {
  const double requested = v;
  if (has_velocity_limits) v = clamp(v, min_velocity, max_velocity);
  return ratio(v, requested);
}

double SpeedLimiter::limitAcceleration(double& v, double v0, double dt) const {
  const double requested = v;
  if (has_acceleration_limits) {
    const double dv = clamp(v - v0, min_acceleration * dt, max_acceleration * dt);
    v = v0 + dv;
  }
  return ratio(v, requested);
}

double SpeedLimiter::limitJerk(double& v, double v0, double v1, double dt) const {
  const double requested = v;
  if (has_jerk_limits) {
    const double dv = v - v0;
    const double dv0 = v0 - v1;
    const double dt2 = 2.0 * dt * dt;
    const double da = clamp(dv - dv0, min_jerk * dt2, max_jerk * dt2);
    v = v0 + dv0 + da;
  }
  return ratio(v, requested);
}

}  // namespace diff_drive
}  // namespace sim_control
