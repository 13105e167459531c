#include "bullet_sim_core/pid.h"

#include <algorithm>
#include <cmath>

namespace bullet_sim {

void Pid::reset() {
  integral_ = 0.0;
  forgetLastError();
}

void Pid::forgetLastError() {
  last_error_ = 0.0;
  has_last_error_ = false;
}

double Pid::update(double error, double dt) {
  if (!std::isfinite(error) || !(dt > 0)) return 0.0;
  integral_ += error * dt;
  double i_term = gains_.i * integral_;
  if (gains_.i_max > gains_.i_min && gains_.i != 0.0) {
    // Held at its bound, the integral does not wind up beyond what the bound lets through.
    i_term = std::clamp(i_term, gains_.i_min, gains_.i_max);
    integral_ = i_term / gains_.i;
  }
  const double rate = has_last_error_ ? (error - last_error_) / dt : 0.0;
  last_error_ = error;
  has_last_error_ = true;
  double effort = -(gains_.p * error + i_term + gains_.d * rate);
  if (gains_.cmd_max > gains_.cmd_min) effort = std::clamp(effort, gains_.cmd_min, gains_.cmd_max);
  return effort;
}

}  // namespace bullet_sim
