// The sphere kernels built for AVX2 (CMakeLists.txt gives this file -mavx2 -ffp-contract=off).
#define AMP_KERNEL_NS avx2
#define AMP_KERNEL_NAME "avx2"
#include "world/arm/sphere_kernels.ipp"

namespace amp::world::detail {
const SphereKernels& sphere_kernels_avx2() { return avx2::kKernels; }
}  // namespace amp::world::detail
