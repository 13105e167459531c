#include "sim_control/pid.h"

#include <ros/param.h>

#include <algorithm>
#include <cmath>

#include "sim_control/controller_params.h"

namespace sim_control {
namespace {
// Not std::clamp: gains set by hand may have min > max, which std::clamp leaves undefined.
double clampTo(double value, double min, double max) { return std::max(min, std::min(value, max)); }
}  // namespace

bool Pid::init(const ros::NodeHandle& nh, std::string& error) {
  // `pid: 100` instead of `pid: {p: 100}` would otherwise be reported as a missing p.
  XmlRpc::XmlRpcValue group;
  if (ros::param::get(nh.getNamespace(), group) && group.getType() != XmlRpc::XmlRpcValue::TypeStruct) {
    error = nh.getNamespace() + ": expected the PID gains as a dictionary, e.g. {p: 100.0, i: 0.01, d: 10.0}, got " +
            ros_params::describe(group);
    return false;
  }
  ros_params::Reader params(nh);
  PidGains gains;
  // Like control_toolbox: only p is required; i and d default to 0.
  if (!readFinite(params, "p", &gains.p, "a number (the proportional gain)", true) && !ros::param::has(nh.getNamespace()))
    params.problem("nothing is set under " + nh.getNamespace() + ", e.g. pid: {p: 100.0, i: 0.01, d: 10.0}");
  readFinite(params, "i", &gains.i, "a number (the integral gain)");
  readFinite(params, "d", &gains.d, "a number (the derivative gain)");
  // control_toolbox: i_clamp (default 0) gives the symmetric bounds; i_clamp_min / i_clamp_max
  // override one side each and are forced to <= 0 / >= 0. With the default 0 the integral
  // term is held at 0, as it is with control_toolbox (and so with ros_control in Gazebo).
  double i_clamp = 0.0;
  readFinite(params, "i_clamp", &i_clamp, "a number (the integral term's bound)");
  gains.i_clamp_min = -std::abs(i_clamp);
  gains.i_clamp_max = std::abs(i_clamp);
  readFinite(params, "i_clamp_min", &gains.i_clamp_min, "a number (the integral term's lower bound)");
  readFinite(params, "i_clamp_max", &gains.i_clamp_max, "a number (the integral term's upper bound)");
  params.read("antiwindup", &gains.antiwindup);
  if (!noProblems(params, error)) return false;
  gains.i_clamp_min = -std::abs(gains.i_clamp_min);
  gains.i_clamp_max = std::abs(gains.i_clamp_max);
  gains_ = gains;
  reset();
  return true;
}

void Pid::reset() {
  p_error_last_ = p_error_ = d_error_ = i_term_ = command_ = 0.0;
  has_last_error_ = false;
}

double Pid::compute(double error, double error_dot, double dt) {
  // control_toolbox returns 0 and keeps its state for a zero step or a non-finite input; a
  // negative step (sim time jumping back on a world reset) is treated the same.
  if (!(dt > 0.0) || !std::isfinite(dt) || !std::isfinite(error) || !std::isfinite(error_dot)) return 0.0;
  p_error_ = error;
  d_error_ = error_dot;
  // The integral is kept as the i term itself (i * ∫error dt). Without antiwindup only the term's
  // contribution is clamped and the state may keep growing; with antiwindup the state is clamped,
  // so it unwinds as soon as the error changes sign.
  i_term_ += gains_.i * dt * error;
  double i_term;
  if (gains_.antiwindup) {
    i_term_ = clampTo(i_term_, gains_.i_clamp_min, gains_.i_clamp_max);
    i_term = i_term_;
  } else {
    i_term = clampTo(i_term_, gains_.i_clamp_min, gains_.i_clamp_max);
  }
  command_ = gains_.p * error + i_term + gains_.d * error_dot;
  return command_;
}

double Pid::compute(double error, double dt) {
  if (!(dt > 0.0) || !std::isfinite(dt) || !std::isfinite(error)) return 0.0;
  // control_toolbox differentiates from a last error of 0 after reset, a kick of error/dt on the
  // first step; with no previous error we use a rate of 0 instead.
  const double error_dot = has_last_error_ ? (error - p_error_last_) / dt : 0.0;
  p_error_last_ = error;
  has_last_error_ = true;
  return compute(error, error_dot, dt);
}

}  // namespace sim_control
