#pragma once
// The PID Gazebo's physics::JointController drives joints with (gazebo::common::PID), free of ROS:
// with error = measured - target,
//   effort = -(p * error + clamp(i * integral(error dt), i_min, i_max) + d * d(error)/dt),
// clamped to [cmd_min, cmd_max]. The integral stops growing at its bound (Gazebo sets it back to
// bound / i). Where we differ from Gazebo, so that a message's zero defaults mean "none":
//  - a bound pair whose max is not above its min (both 0) is no bound; Gazebo's common::PID clamps
//    the integral term to [0, 0] then, and the output too;
//  - the rate term starts from the first error after reset() or forgetLastError() (Gazebo's starts
//    from an error of 0: one step's kick of d * error / dt when a target is set).
namespace bullet_sim {

struct PidGains {
  double p = 0.0, i = 0.0, d = 0.0;
  double i_max = 0.0, i_min = 0.0;      // bounds of the integral term's effort
  double cmd_max = 0.0, cmd_min = 0.0;  // bounds of the effort
};

class Pid {
 public:
  explicit Pid(const PidGains& gains = PidGains()) : gains_(gains) {}

  const PidGains& gains() const { return gains_; }
  void setGains(const PidGains& gains) { gains_ = gains; }  // the integral and the last error stay
  void reset();            // forgets the integral and the last error
  void forgetLastError();  // the next update has no rate term (a new target: no kick)

  // The effort for `error` (measured - target) over a step of `dt` > 0 s. A non-finite error, or a
  // dt that is not > 0, gives 0 and changes nothing.
  double update(double error, double dt);

 private:
  PidGains gains_;
  double integral_ = 0.0;  // of the error over time
  double last_error_ = 0.0;
  bool has_last_error_ = false;
};

}  // namespace bullet_sim
