// A crash in the simulator names the signal and prints the stack it happened on, then dies of
// that signal (roslaunch reports the same exit status as without the handler).
#include <gtest/gtest.h>

#include <csignal>

#include "bullet_sim/crash_report.h"

namespace bullet_sim {
namespace {

// Not inlined and exported, so that its name is in the printed stack.
__attribute__((noinline)) void crashHere(volatile int* where) { *where = 1; }

TEST(CrashReportDeathTest, ASegfaultPrintsTheSignalAndTheStack) {
  EXPECT_EXIT(
      {
        reportCrashesOnStderr("bullet_sim_node");
        crashHere(nullptr);
      },
      testing::KilledBySignal(SIGSEGV), "bullet_sim_node crashed: Segmentation fault. The stack, innermost first:\n(.*\n)+");
}

TEST(CrashReportDeathTest, AnAbortIsReportedAsSuch) {
  EXPECT_EXIT(
      {
        reportCrashesOnStderr("bullet_sim_node");
        std::abort();
      },
      testing::KilledBySignal(SIGABRT), "bullet_sim_node crashed: Aborted\\.");
}

}  // namespace
}  // namespace bullet_sim
