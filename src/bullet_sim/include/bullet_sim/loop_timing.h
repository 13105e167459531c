#pragma once
// Where the node's time goes (bullet_sim_node --timing): wall time per part of the loop, summed
// over the run and printed per step when the node exits. Off by default: reading the clock around
// every part costs a little of what it measures.
#include <chrono>
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace bullet_sim {

class LoopTiming {
 public:
  using Clock = std::chrono::steady_clock;

  explicit LoopTiming(bool enabled) : enabled_(enabled) {}
  bool enabled() const { return enabled_; }

  // Starts the clock for the next part. Like lap and countStep, nothing when disabled.
  void mark() {
    if (enabled_) mark_ = Clock::now();
  }
  // The time since the last mark or lap goes to the part named `part` + `detail`.
  void lap(std::string_view part, const char* detail = "") {
    if (enabled_) record(part, detail);
  }
  void countStep() {
    if (enabled_) ++steps_;
  }

  // The table: each part's mean microseconds per step and share of the measured time, largest
  // first, with `sim_seconds` of sim time in the wall time between the first and last step.
  std::string report(double sim_seconds) const;

 private:
  void record(std::string_view part, const char* detail);

  struct Part {
    std::string name;    // part
    std::string detail;  // appended to the name in the report
    double seconds = 0.0;
  };

  bool enabled_;
  long steps_ = 0;
  Clock::time_point mark_;
  // In the order first seen. The loop laps its parts in the same order every step, so the part
  // after the last one recorded is checked first: a lap costs a clock read and a short compare.
  std::vector<Part> parts_;
  std::size_t next_ = 0;
  Clock::time_point first_, last_;
};

}  // namespace bullet_sim
