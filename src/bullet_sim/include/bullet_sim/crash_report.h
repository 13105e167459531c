// A crash that says where: on SIGSEGV, SIGBUS, SIGFPE, SIGILL or SIGABRT the program writes
// "<program> crashed: <signal>" and the stack it crashed on to stderr (roslaunch shows it in the
// terminal and in the node's log), then dies of the same signal, so roslaunch and a shell see the
// same exit status as without it. Functions of shared libraries are named; the executable's own
// show as addresses (`addr2line -e <program> <address>`).
#pragma once

namespace bullet_sim {

// Installs the handlers; `program` is the name printed (kept, so pass a string that lives on).
void reportCrashesOnStderr(const char* program);

}  // namespace bullet_sim
