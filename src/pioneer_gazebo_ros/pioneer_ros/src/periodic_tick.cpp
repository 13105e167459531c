#include "pioneer_ros/periodic_tick.h"

#include <stdexcept>

namespace pioneer_ros {

PeriodicTick::PeriodicTick(std::chrono::nanoseconds period, std::chrono::nanoseconds start)
    : period_(period), next_(start + period), last_(start) {
  if (period.count() <= 0) throw std::invalid_argument("PeriodicTick: expected a positive period");
}

bool PeriodicTick::due(std::chrono::nanoseconds now) {
  if (now < last_) next_ = now + period_;  // the clock jumped back
  last_ = now;
  if (now < next_) return false;
  next_ += period_;
  if (next_ <= now) next_ = now + period_;  // late by a period or more: no burst
  return true;
}

}  // namespace pioneer_ros
