#pragma once
// Replaces global operator new / delete (the single-object forms) with a counting pair, for tests
// that prove a hot loop allocates nothing. Include it in exactly one translation unit of a test
// executable (each test file is its own executable here). allocations() counts every allocation
// while g_counting is true (the default), so a test may switch it off around set-up.
#include <atomic>
#include <cstdlib>
#include <new>

namespace amp::test {
inline std::atomic<long> g_allocations{0};
inline std::atomic<bool> g_counting{true};
inline long allocations() { return g_allocations.load(std::memory_order_relaxed); }
}  // namespace amp::test

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"  // malloc/free pair by design
void* operator new(std::size_t n) {
  if (amp::test::g_counting.load(std::memory_order_relaxed)) {
    amp::test::g_allocations.fetch_add(1, std::memory_order_relaxed);
  }
  if (void* p = std::malloc(n == 0 ? 1 : n)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
// The array forms are left alone: the library's call the two above, and under AddressSanitizer,
// which replaces them too, a library built apart (FCL) would otherwise free ASan's new[] with free.
#pragma GCC diagnostic pop
