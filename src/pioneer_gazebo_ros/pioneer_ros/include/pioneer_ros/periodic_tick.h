#pragma once
// When a periodic task is due, on a clock read only at discrete instants (no ROS): the node's
// 20 Hz update on sim time, read from /clock messages. As ros::Timer on sim time: due first one
// period after the start, then every period; a late instant gives one call, not a burst to catch
// up; a clock that jumps back (a simulation reset) starts the schedule again from there. Times
// are whole nanoseconds, as ros::Time has them, so that the schedule does not drift.
#include <chrono>

namespace pioneer_ros {

class PeriodicTick {
 public:
  // Throws std::invalid_argument unless period > 0.
  PeriodicTick(std::chrono::nanoseconds period, std::chrono::nanoseconds start);

  // True when the task is due at `now` (and schedules the next time).
  bool due(std::chrono::nanoseconds now);

 private:
  std::chrono::nanoseconds period_;
  std::chrono::nanoseconds next_;
  std::chrono::nanoseconds last_;  // the last instant seen
};

}  // namespace pioneer_ros
