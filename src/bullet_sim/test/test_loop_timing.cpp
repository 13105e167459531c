// bullet_sim_node --timing's accounting: every lap lands in its part, the parts are listed largest
// first with their share, and what is reported never exceeds the wall time that passed.
#include <gtest/gtest.h>

#include <chrono>
#include <string>
#include <thread>

#include "bullet_sim/loop_timing.h"

namespace bullet_sim {
namespace {

double numberBefore(const std::string& text, const std::string& suffix) {
  const size_t end = text.find(suffix);
  EXPECT_NE(end, std::string::npos) << "no '" << suffix << "' in\n" << text;
  if (end == std::string::npos) return -1;
  size_t start = text.rfind(' ', end - 2);
  return std::stod(text.substr(start + 1, end - start - 1));
}

TEST(LoopTiming, ReportsEachPartPerStepLargestFirst) {
  using namespace std::chrono_literals;
  LoopTiming timing(true);
  const auto start = LoopTiming::Clock::now();
  for (int i = 0; i < 5; ++i) {
    timing.mark();
    std::this_thread::sleep_for(1ms);
    timing.lap("short part");
    std::this_thread::sleep_for(4ms);
    timing.lap(std::string("plugin"), ", after the step");
    timing.countStep();
  }
  const double wall_us_per_step =
      std::chrono::duration<double, std::micro>(LoopTiming::Clock::now() - start).count() / 5;
  const std::string report = timing.report(0.005);
  EXPECT_NE(report.find("5 steps"), std::string::npos) << report;
  // Slept at least as long as asked, and the parts cannot add up to more than the time that passed.
  const double longer = numberBefore(report, " us/step");
  EXPECT_GE(longer, 4000) << report;
  EXPECT_LE(longer, wall_us_per_step) << report;
  EXPECT_LT(report.find("plugin, after the step"), report.find("short part")) << report;
  EXPECT_GE(numberBefore(report, " us per step measured"), 5000) << report;
  EXPECT_LE(numberBefore(report, " us per step measured"), wall_us_per_step) << report;
}

TEST(LoopTiming, APartLappedTwiceInAStepIsOneLine) {
  using namespace std::chrono_literals;
  LoopTiming timing(true);
  for (int i = 0; i < 3; ++i) {
    timing.mark();
    std::this_thread::sleep_for(1ms);
    timing.lap("callbacks");
    std::this_thread::sleep_for(1ms);
    timing.lap(std::string("model 'a': plugin"), ", before the step");
    std::this_thread::sleep_for(1ms);
    timing.lap("callbacks");  // out of the usual order: found by name, not by position
    timing.countStep();
  }
  const std::string report = timing.report(0.003);
  const size_t first = report.find("callbacks");
  ASSERT_NE(first, std::string::npos) << report;
  EXPECT_EQ(report.find("callbacks", first + 1), std::string::npos) << report;
  // Twice a millisecond per step, at least.
  EXPECT_GE(numberBefore(report.substr(0, first + 9), " us/step"), 2000) << report;
  EXPECT_LT(first, report.find("model 'a': plugin, before the step")) << report;
}

TEST(LoopTiming, DisabledRecordsNothing) {
  LoopTiming timing(false);
  timing.mark();
  timing.lap("physics step");
  timing.countStep();
  EXPECT_EQ(timing.report(1.0), "bullet_sim loop timing: no step was taken\n");
}

}  // namespace
}  // namespace bullet_sim
