#include "bullet_sim/loop_timing.h"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <utility>

namespace bullet_sim {

void LoopTiming::record(std::string_view part, const char* detail) {
  const Clock::time_point now = Clock::now();
  const auto is = [&](const Part& p) { return p.name == part && std::strcmp(p.detail.c_str(), detail) == 0; };
  std::size_t i = next_;
  if (i >= parts_.size() || !is(parts_[i])) {
    i = std::find_if(parts_.begin(), parts_.end(), is) - parts_.begin();
    if (i == parts_.size()) parts_.push_back({std::string(part), detail, 0.0});
  }
  parts_[i].seconds += std::chrono::duration<double>(now - mark_).count();
  next_ = i + 1;
  if (first_ == Clock::time_point()) first_ = mark_;
  last_ = now;
  mark_ = now;
}

std::string LoopTiming::report(double sim_seconds) const {
  if (steps_ == 0) return "bullet_sim loop timing: no step was taken\n";
  std::vector<std::pair<double, std::string>> parts;
  double measured = 0.0;
  for (const Part& p : parts_) {
    parts.emplace_back(p.seconds, p.name + p.detail);
    measured += p.seconds;
  }
  std::sort(parts.rbegin(), parts.rend());
  const double wall = std::chrono::duration<double>(last_ - first_).count();
  char line[512];
  std::snprintf(line, sizeof line,
                "bullet_sim loop timing: %ld steps, %.2f s of sim time in %.2f s of wall time (real-time factor "
                "%.2f); %.2f us per step measured:\n",
                steps_, sim_seconds, wall, wall > 0 ? sim_seconds / wall : 0.0, 1e6 * measured / steps_);
  std::string out = line;
  for (const auto& [seconds, part] : parts) {
    std::snprintf(line, sizeof line, "  %8.3f us/step %5.1f %%  %s\n", 1e6 * seconds / steps_,
                  measured > 0 ? 100.0 * seconds / measured : 0.0, part.c_str());
    out += line;
  }
  return out;
}

}  // namespace bullet_sim
