#pragma once
// Private: the sphere checker's arithmetic on blocks of spheres (sphere_checker.cpp), four lanes at a
// time with std::experimental::simd. Compiled twice from sphere_kernels.ipp: for AVX2 and for the
// x86-64 baseline; sphere_kernels() picks one by the CPU once. Both builds do the same operations in
// the same order without contraction (-ffp-contract=off), so they give the same answers bit for
// bit; only the speed differs.
#include <cstddef>

namespace amp::world::detail {

struct SphereScene;

// Blocks are structure-of-arrays whose length is a multiple of kSphereLanes (sphere_checker.cpp pads
// a link's spheres by repeating its last one, which changes no minimum).
inline constexpr std::size_t kSphereLanes = 4;

// A pose block: the poses of one link in kSphereLanes configurations, as 12 arrays of lanes (the
// rotation row-major, then the translation): entry e of lane k at [e * kSphereLanes + k].
inline constexpr std::size_t kPoseBlock = 12 * kSphereLanes;

struct SphereKernels {
  const char* name;  // "avx2" or "baseline"
  // out = parent * rhs, lane by lane (pose blocks).
  void (*compose)(const double* parent, const double* rhs, double* out);
  // rhs = fixed * (a turn about z by the lane's angle, given its cosine and sine); `fixed` is one
  // pose (12 values), rhs a pose block.
  void (*turn_z)(const double* fixed, const double* cos, const double* sin, double* rhs);
  // The world position of link-frame point p in each lane's pose.
  void (*place_point)(const double* pose, double px, double py, double pz, double* wx, double* wy, double* wz);
  // World centres: w = R * l + t for n spheres; `pose` is R row-major then t (12 values).
  void (*place)(const double* pose, const double* lx, const double* ly, const double* lz, double* wx, double* wy,
                double* wz, std::size_t n);
  // out[i] = signed distance from centre i to obstacle `o` of `scene`, less radius r[i].
  void (*obstacle_gaps)(const SphereScene& scene, std::size_t o, const double* wx, const double* wy, const double* wz,
                        const double* r, std::size_t n, double* out);
  // out[i] = |c - centre i| - radius - r[i]: the gap between one sphere and a block.
  void (*sphere_gaps)(double cx, double cy, double cz, double radius, const double* wx, const double* wy,
                      const double* wz, const double* r, std::size_t n, double* out);
};

// The AVX2 build when the CPU has AVX2, else the baseline's.
const SphereKernels& sphere_kernels();
// Each build, for tests that compare them.
const SphereKernels& sphere_kernels_avx2();
const SphereKernels& sphere_kernels_baseline();

}  // namespace amp::world::detail
