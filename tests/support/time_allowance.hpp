#pragma once
// How far past its time limit a run may end: 5 % + 50 ms, the Release build's promise. Sanitizer
// builds (make sanitize) run instrumented code several times slower, frees included (ASan's
// quarantine), two tests at a time on a 2-core machine that is itself slower on some days: the CI
// saw runs end past ten times the promise, so they get thirty times it. The Release run is the one
// that holds runs to the promise.
//
// The default suite measures a run's CPU time, not its wall time (issue 34: a busy machine made a
// wall-clock check fail). A run stops on the wall clock, so the CPU time it spends before its
// deadline is at most the limit however loaded the machine is, and only work done past the
// deadline can take it beyond: the check fails for an overrunning run, never for a slow machine.
// Planners and navigators run on the calling thread. The wall-clock promise itself is checked by
// the `timing` label alone (tests/roadmap/run_limits_test.cpp), which CI runs after the suite.
#include <time.h>

#include "support/sanitizer_build.hpp"

namespace amp::test {

inline constexpr double kSanitizerSlowdown = kSanitizerBuild ? 30.0 : 1.0;

constexpr double time_allowance(double limit_s) { return kSanitizerSlowdown * (0.05 * limit_s + 0.05); }

// The calling thread's CPU time, in seconds.
inline double thread_cpu_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

}  // namespace amp::test
