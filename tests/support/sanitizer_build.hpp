#pragma once
// Whether the tests are built with AddressSanitizer (make sanitize), and what that changes: the
// instrumented code runs several times slower, so property tests draw a share of their cases (the
// Release run draws them all; the sanitizers look for memory errors and undefined behaviour, which
// the share's planners, worlds and robots reach as well) and time limits get a wider allowance.

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
inline constexpr bool kSanitizerBuild = true;
#else
inline constexpr bool kSanitizerBuild = false;
#endif

// The cases of a property test's `n` that a build draws: all of them, or a quarter (at least one)
// under the sanitizers.
constexpr int case_share(int n) { return kSanitizerBuild ? (n + 3) / 4 : n; }

}  // namespace amp::test
