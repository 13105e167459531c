#pragma once
// A discrete PID controller with anti-windup and output limits (no ROS).
//
// u = feedforward + p * e + I + D, clamped to [output_min, output_max], where
// - I is the integral term, i * integral(e dt), itself clamped to [-i_clamp, i_clamp] (in output
//   units, like control_toolbox's i_clamp), and not integrated further while the output is
//   saturated in the direction the error pushes (conditional integration), so it does not wind
//   up while the output is limited;
// - D is d times the rate of change of the error, or, when the caller passes the measurement,
//   of minus the measurement (the same thing for a constant setpoint, without the kick a step
//   in the setpoint gives), low-pass filtered with time constant d_filter_time.
#include <limits>
#include <optional>
#include <string>

namespace pioneer_ros {

struct PidGains {
  double p = 0.0, i = 0.0, d = 0.0;
  double i_clamp = std::numeric_limits<double>::infinity();  // largest |I|, in output units
  double output_min = -std::numeric_limits<double>::infinity();
  double output_max = std::numeric_limits<double>::infinity();
  double d_filter_time = 0.0;  // s, time constant of the derivative's low-pass filter
};

// "" when the gains can be used; otherwise what is wrong, naming the field:
// "i_clamp: expected a number >= 0, got -1".
std::string validate(const PidGains& gains);

// "PidGains(p=0.5, i=2, d=0.01, i_clamp=0.3, output=[-1, 1], d_filter_time=0.05)", for logs.
std::string describe(const PidGains& gains);

class Pid {
 public:
  // Throws std::invalid_argument with validate()'s message when the gains are bad.
  explicit Pid(const PidGains& gains);

  // Forgets the integral and the derivative's history (e.g. after a pause).
  void reset();

  // The output for this error after dt seconds. dt <= 0 (a repeated time stamp) gives the
  // proportional and feedforward response without integrating or differentiating. With a
  // measurement, D acts on minus the measurement instead of the error. Throws
  // std::invalid_argument when the error or the feedforward is not finite.
  double update(double error, double dt, std::optional<double> measurement = std::nullopt,
                double feedforward = 0.0);

  const PidGains& gains() const { return gains_; }
  double integral() const { return integral_; }      // the I term, in output units
  double derivative() const { return derivative_; }  // the filtered rate of the differentiated signal
  double output() const { return output_; }
  bool saturated() const { return saturated_; }      // the last output was limited

 private:
  PidGains gains_;
  double integral_ = 0.0;
  double derivative_ = 0.0;
  std::optional<double> previous_;  // the last differentiated signal
  double output_ = 0.0;
  bool saturated_ = false;
};

}  // namespace pioneer_ros
