#pragma once
// Counts the over-aligned single-object operator new too, into the same g_allocations as
// counting_allocator.hpp (included first). The KD-tree keeps its boxes and leaf coordinates in
// cache-line-aligned vectors (DynamicKdTree's AlignedAllocator calls operator new(n, align_val_t)),
// which the unaligned replacement alone would not see, so a test of the tree would pass blind to
// them. Include it, after counting_allocator.hpp, in exactly one translation unit of a test
// executable. As there, the array forms are left alone; every scalar aligned form that a scalar
// aligned delete may meet is replaced, so each block is freed by the family that made it.
#include <cstddef>
#include <cstdlib>
#include <new>

#include "support/counting_allocator.hpp"

namespace amp::test::detail {
inline void* counted_aligned(std::size_t n, std::align_val_t al) noexcept {
  if (g_counting.load(std::memory_order_relaxed)) g_allocations.fetch_add(1, std::memory_order_relaxed);
  const auto a = static_cast<std::size_t>(al);
  const std::size_t size = n == 0 ? a : (n + a - 1) / a * a;  // aligned_alloc wants a multiple of a
  return std::aligned_alloc(a, size);
}
}  // namespace amp::test::detail

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"  // aligned_alloc/free pair by design
void* operator new(std::size_t n, std::align_val_t al) {
  if (void* p = amp::test::detail::counted_aligned(n, al)) return p;
  throw std::bad_alloc();
}
void* operator new(std::size_t n, std::align_val_t al, const std::nothrow_t&) noexcept {
  return amp::test::detail::counted_aligned(n, al);
}
void operator delete(void* p, std::align_val_t) noexcept { std::free(p); }
void operator delete(void* p, std::size_t, std::align_val_t) noexcept { std::free(p); }
void operator delete(void* p, std::align_val_t, const std::nothrow_t&) noexcept { std::free(p); }
#pragma GCC diagnostic pop
