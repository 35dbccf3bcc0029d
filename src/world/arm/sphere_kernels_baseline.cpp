// The sphere kernels built for the x86-64 baseline (CMakeLists.txt gives this file -ffp-contract=off).
#define AMP_KERNEL_NS baseline
#define AMP_KERNEL_NAME "baseline"
#include "world/arm/sphere_kernels.ipp"

namespace amp::world::detail {
const SphereKernels& sphere_kernels_baseline() { return baseline::kKernels; }

// Chosen once, on first use: a CPU without AVX2 runs the baseline build, with the same answers.
const SphereKernels& sphere_kernels() {
#if defined(__x86_64__) || defined(__i386__)
  static const bool avx2 = __builtin_cpu_supports("avx2") != 0;
#else
  static const bool avx2 = false;  // the "avx2" build is the baseline's code here
#endif
  static const SphereKernels& chosen = avx2 ? sphere_kernels_avx2() : sphere_kernels_baseline();
  return chosen;
}
}  // namespace amp::world::detail
