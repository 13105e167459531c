#include "bullet_sim/crash_report.h"

#include <execinfo.h>
#include <signal.h>
#include <string.h>
#include <unistd.h>

#include <initializer_list>

namespace bullet_sim {
namespace {

const char* program_name = "program";

void writeText(const char* text) {
  // Only async-signal-safe calls in a handler: write(2), not iostreams or printf.
  ssize_t ignored = write(STDERR_FILENO, text, strlen(text));
  (void)ignored;
}

void onCrash(int signal_number) {
  writeText("\n");
  writeText(program_name);
  writeText(" crashed: ");
  writeText(strsignal(signal_number));
  writeText(". The stack, innermost first:\n");
  void* frames[64];
  const int count = backtrace(frames, 64);
  backtrace_symbols_fd(frames, count, STDERR_FILENO);
  // SA_RESETHAND restored the default action: dying of the same signal keeps the exit status.
  raise(signal_number);
}

}  // namespace

void reportCrashesOnStderr(const char* program) {
  program_name = program;
  // backtrace() loads libgcc on its first call, which is not safe inside a handler: call it now.
  void* warm_up[1];
  backtrace(warm_up, 1);
  struct sigaction action {};
  action.sa_handler = onCrash;
  action.sa_flags = SA_RESETHAND;
  sigemptyset(&action.sa_mask);
  for (int signal_number : {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT}) sigaction(signal_number, &action, nullptr);
}

}  // namespace bullet_sim
