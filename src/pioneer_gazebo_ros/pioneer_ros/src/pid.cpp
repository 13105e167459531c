#include "pioneer_ros/pid.h"

#include "numbers.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace pioneer_ros {

using numbers::clampTo;
using numbers::number;

std::string validate(const PidGains& gains) {
  const std::pair<const char*, double> terms[] = {{"p", gains.p}, {"i", gains.i}, {"d", gains.d}};
  for (const auto& [name, value] : terms) {
    if (!std::isfinite(value)) return std::string(name) + ": expected a finite gain, got " + number(value);
  }
  // Written as !(x >= 0) so that NaN fails too.
  if (!(gains.i_clamp >= 0.0)) return "i_clamp: expected a number >= 0, got " + number(gains.i_clamp);
  if (!(gains.output_min <= gains.output_max))
    return "output_min " + number(gains.output_min) + " is above output_max " + number(gains.output_max);
  if (!(gains.d_filter_time >= 0.0))
    return "d_filter_time: expected seconds >= 0, got " + number(gains.d_filter_time);
  return "";
}

std::string describe(const PidGains& gains) {
  std::ostringstream out;
  out << "PidGains(p=" << gains.p << ", i=" << gains.i << ", d=" << gains.d << ", i_clamp=" << gains.i_clamp
      << ", output=[" << gains.output_min << ", " << gains.output_max << "], d_filter_time=" << gains.d_filter_time
      << ")";
  return out.str();
}

Pid::Pid(const PidGains& gains) : gains_(gains) {
  const std::string problem = validate(gains);
  if (!problem.empty()) throw std::invalid_argument(problem);
}

void Pid::reset() {
  integral_ = 0.0;
  derivative_ = 0.0;
  previous_.reset();
  output_ = 0.0;
  saturated_ = false;
}

double Pid::update(double error, double dt, std::optional<double> measurement, double feedforward) {
  if (!std::isfinite(error) || !std::isfinite(feedforward)) {
    throw std::invalid_argument("expected a finite error and feedforward, got " + number(error) + " and " +
                                number(feedforward));
  }
  const PidGains& g = gains_;
  double candidate = integral_;
  if (dt > 0.0) {
    const double signal = measurement ? -*measurement : error;
    if (previous_) {
      const double rate = (signal - *previous_) / dt;
      const double alpha = dt / (g.d_filter_time + dt);
      derivative_ += alpha * (rate - derivative_);
    }
    previous_ = signal;
    candidate = clampTo(integral_ + g.i * error * dt, -g.i_clamp, g.i_clamp);
  }
  const double fixed = feedforward + g.p * error + g.d * derivative_;
  double unsaturated = fixed + candidate;
  double output = clampTo(unsaturated, g.output_min, g.output_max);
  // Conditional integration: keep the old integral when the output is limited and the new
  // integral would push it further into the limit.
  if (output != unsaturated && (candidate - integral_) * (unsaturated - output) > 0.0) {
    unsaturated = fixed + integral_;
    output = clampTo(unsaturated, g.output_min, g.output_max);
  } else {
    integral_ = candidate;
  }
  saturated_ = output != unsaturated;
  output_ = output;
  return output;
}

}  // namespace pioneer_ros
