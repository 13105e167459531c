#pragma once
// A PID with control_toolbox's parameters and behaviour: p (required), i, d, i_clamp (or
// i_clamp_min / i_clamp_max), antiwindup.
#include <ros/node_handle.h>

#include <string>

namespace sim_control {

struct PidGains {
  double p = 0.0, i = 0.0, d = 0.0;
  double i_clamp_min = 0.0, i_clamp_max = 0.0;
  bool antiwindup = false;
};

class Pid {
 public:
  Pid() = default;
  explicit Pid(const PidGains& gains) : gains_(gains) {}
  // Reads the gains under nh (e.g. <controller>/pid). False with `error` naming the missing or
  // bad parameter (e.g. "/simple_model/joint1_position_controller/pid/p: required, expected a number").
  bool init(const ros::NodeHandle& nh, std::string& error);
  void reset();
  // Command for this error and its rate (control_toolbox's computeCommand(error, error_dot, dt)).
  double compute(double error, double error_dot, double dt);
  // Same, with the error rate from the last error (computeCommand(error, dt)).
  double compute(double error, double dt);
  const PidGains& gains() const { return gains_; }
  void setGains(const PidGains& gains) { gains_ = gains; }
  // Terms of the last computation, for control_msgs/JointControllerState.
  double lastError() const { return p_error_; }
  double lastErrorDot() const { return d_error_; }
  double lastCommand() const { return command_; }

 private:
  PidGains gains_;
  double p_error_last_ = 0.0, p_error_ = 0.0, d_error_ = 0.0, i_term_ = 0.0, command_ = 0.0;
  bool has_last_error_ = false;
};

}  // namespace sim_control
