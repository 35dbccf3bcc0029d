#pragma once
// How far past its time limit a run may end: 5 % + 50 ms, the Release build's promise. Sanitizer
// builds (make sanitize) run instrumented code several times slower, frees included, so they get
// ten times that.

namespace amp::test {

// GCC defines __SANITIZE_ADDRESS__ under -fsanitize=address; clang 14 answers __has_feature instead.
#if defined(__SANITIZE_ADDRESS__)
#define AMP_TEST_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define AMP_TEST_ASAN 1
#endif
#endif

#if defined(AMP_TEST_ASAN)
inline constexpr double kSanitizerSlowdown = 10.0;
#else
inline constexpr double kSanitizerSlowdown = 1.0;
#endif

constexpr double time_allowance(double limit_s) { return kSanitizerSlowdown * (0.05 * limit_s + 0.05); }

}  // namespace amp::test
