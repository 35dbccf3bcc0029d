#pragma once
// How far past its time limit a run may end: 5 % + 50 ms, the Release build's promise. Sanitizer
// builds (make sanitize) run instrumented code several times slower, frees included (ASan's
// quarantine), two tests at a time on a 2-core machine that is itself slower on some days: the CI
// saw runs end past ten times the promise, so they get thirty times it. The Release run is the one
// that holds runs to the promise.
#include "support/sanitizer_build.hpp"

namespace amp::test {

inline constexpr double kSanitizerSlowdown = kSanitizerBuild ? 30.0 : 1.0;

constexpr double time_allowance(double limit_s) { return kSanitizerSlowdown * (0.05 * limit_s + 0.05); }

}  // namespace amp::test
