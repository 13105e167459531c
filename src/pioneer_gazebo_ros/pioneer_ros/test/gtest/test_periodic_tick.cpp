// pioneer_ros::PeriodicTick: the node's update schedule on sim time (no ROS).
#include <gtest/gtest.h>

#include <chrono>
#include <stdexcept>
#include <vector>

#include "pioneer_ros/periodic_tick.h"

namespace pioneer_ros {
namespace {

using std::chrono::milliseconds;

// The clock readings at which the task was due, for readings every `step` from 0 to `end`.
std::vector<long> dueAt(PeriodicTick& tick, milliseconds step, milliseconds end) {
  std::vector<long> due;
  for (milliseconds now{0}; now <= end; now += step) {
    if (tick.due(now)) due.push_back(now.count());
  }
  return due;
}

TEST(PeriodicTick, DueEveryPeriodFromOnePeriodAfterTheStart) {
  PeriodicTick tick(milliseconds(50), milliseconds(0));
  // /clock at 100 Hz of sim time, the update at 20 Hz.
  EXPECT_EQ(dueAt(tick, milliseconds(10), milliseconds(200)), (std::vector<long>{50, 100, 150, 200}));
}

TEST(PeriodicTick, KeepsItsPhaseWhenReadingsFallBetweenTicks) {
  PeriodicTick tick(milliseconds(50), milliseconds(0));
  // Readings every 30 ms: due at the first reading at or past 50, 100, 150, ... ms.
  EXPECT_EQ(dueAt(tick, milliseconds(30), milliseconds(300)), (std::vector<long>{60, 120, 150, 210, 270, 300}));
}

TEST(PeriodicTick, ALateReadingGivesOneCallNotABurst) {
  PeriodicTick tick(milliseconds(50), milliseconds(0));
  EXPECT_TRUE(tick.due(milliseconds(1000)));   // 19 periods late: one call
  EXPECT_FALSE(tick.due(milliseconds(1000)));  // not again at the same instant
  EXPECT_FALSE(tick.due(milliseconds(1040)));
  EXPECT_TRUE(tick.due(milliseconds(1050)));   // then every period from the late call
}

TEST(PeriodicTick, StartsAgainWhenTheClockJumpsBack) {
  PeriodicTick tick(milliseconds(50), milliseconds(0));
  EXPECT_TRUE(tick.due(milliseconds(10000)));
  EXPECT_FALSE(tick.due(milliseconds(0)));  // reset_simulation
  EXPECT_FALSE(tick.due(milliseconds(40)));
  EXPECT_TRUE(tick.due(milliseconds(50)));
}

TEST(PeriodicTick, RefusesAPeriodThatIsNotPositive) {
  EXPECT_THROW(PeriodicTick(milliseconds(0), milliseconds(0)), std::invalid_argument);
}

}  // namespace
}  // namespace pioneer_ros
