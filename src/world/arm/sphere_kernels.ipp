// The sphere kernels' code (sphere_kernels.hpp), included by one file per instruction set with
// AMP_KERNEL_NS naming its namespace. Not a header: it defines functions.
#include <algorithm>
#include <cmath>
#include <experimental/simd>

#include "world/arm/sphere_kernels.hpp"
#include "world/arm/sphere_scene.hpp"

namespace amp::world::detail::AMP_KERNEL_NS {

namespace stdx = std::experimental;
using Lanes = stdx::fixed_size_simd<double, kSphereLanes>;

inline Lanes load(const double* p) { return Lanes(p, stdx::element_aligned); }
inline void store(const Lanes& v, double* p) { v.copy_to(p, stdx::element_aligned); }

// Pose blocks (sphere_kernels.hpp): entry e's lanes.
inline Lanes entry(const double* block, int e) { return load(block + e * kSphereLanes); }

void compose(const double* p, const double* q, double* out) {
  Lanes a[12], b[12];
  for (int e = 0; e < 12; ++e) a[e] = entry(p, e), b[e] = entry(q, e);
  for (int row = 0; row < 3; ++row) {
    for (int col = 0; col < 3; ++col) {
      store(a[row * 3] * b[col] + a[row * 3 + 1] * b[3 + col] + a[row * 3 + 2] * b[6 + col], out + (row * 3 + col) * kSphereLanes);
    }
    store(a[row * 3] * b[9] + a[row * 3 + 1] * b[10] + a[row * 3 + 2] * b[11] + a[9 + row], out + (9 + row) * kSphereLanes);
  }
}

// A turn about z mixes the first two columns: col0' = c col0 + s col1, col1' = c col1 - s col0.
void turn_z(const double* m, const double* cos, const double* sin, double* rhs) {
  const Lanes c = load(cos), s = load(sin);
  for (int row = 0; row < 3; ++row) {
    const double x = m[row * 3], y = m[row * 3 + 1];
    store(c * x + s * y, rhs + (row * 3) * kSphereLanes);
    store(c * y - s * x, rhs + (row * 3 + 1) * kSphereLanes);
    store(Lanes(m[row * 3 + 2]), rhs + (row * 3 + 2) * kSphereLanes);
    store(Lanes(m[9 + row]), rhs + (9 + row) * kSphereLanes);
  }
}

void place_point(const double* pose, double px, double py, double pz, double* wx, double* wy, double* wz) {
  double* const out[3] = {wx, wy, wz};
  for (int row = 0; row < 3; ++row) {
    store(entry(pose, row * 3) * px + entry(pose, row * 3 + 1) * py + entry(pose, row * 3 + 2) * pz + entry(pose, 9 + row), out[row]);
  }
}

void place(const double* m, const double* lx, const double* ly, const double* lz, double* wx, double* wy, double* wz,
           std::size_t n) {
  for (std::size_t i = 0; i < n; i += kSphereLanes) {
    const Lanes x = load(lx + i), y = load(ly + i), z = load(lz + i);
    store(m[0] * x + m[1] * y + m[2] * z + m[9], wx + i);
    store(m[3] * x + m[4] * y + m[5] * z + m[10], wy + i);
    store(m[6] * x + m[7] * y + m[8] * z + m[11], wz + i);
  }
}

// The obstacle's frame: q = R (p - c).
struct Local {
  Lanes x, y, z;
};

inline Local to_local(const SphereScene& s, std::size_t o, const Lanes& px, const Lanes& py, const Lanes& pz) {
  const Lanes dx = px - s.cx[o], dy = py - s.cy[o], dz = pz - s.cz[o];
  return {s.r[0][o] * dx + s.r[1][o] * dy + s.r[2][o] * dz, s.r[3][o] * dx + s.r[4][o] * dy + s.r[5][o] * dz,
          s.r[6][o] * dx + s.r[7][o] * dy + s.r[8][o] * dz};
}

// Box: outside, the length of the positive excess; inside, the largest excess (obstacle_distance).
inline Lanes box_distance(const Local& q, double hx, double hy, double hz) {
  const Lanes dx = stdx::abs(q.x) - hx, dy = stdx::abs(q.y) - hy, dz = stdx::abs(q.z) - hz;
  const Lanes ox = stdx::max(dx, Lanes(0.0)), oy = stdx::max(dy, Lanes(0.0)), oz = stdx::max(dz, Lanes(0.0));
  return stdx::sqrt(ox * ox + oy * oy + oz * oz) + stdx::min(stdx::max(dx, stdx::max(dy, dz)), Lanes(0.0));
}

// A z-axis cylinder: the same in the (radial, axial) plane.
inline Lanes cylinder_distance(const Local& q, double radius, double half_length) {
  const Lanes dr = stdx::sqrt(q.x * q.x + q.y * q.y) - radius;
  const Lanes dz = stdx::abs(q.z) - half_length;
  const Lanes or_ = stdx::max(dr, Lanes(0.0)), oz = stdx::max(dz, Lanes(0.0));
  return stdx::sqrt(or_ * or_ + oz * oz) + stdx::min(stdx::max(dr, dz), Lanes(0.0));
}

void obstacle_gaps(const SphereScene& s, std::size_t o, const double* wx, const double* wy, const double* wz,
                   const double* r, std::size_t n, double* out) {
  for (std::size_t i = 0; i < n; i += kSphereLanes) {
    const Lanes px = load(wx + i), py = load(wy + i), pz = load(wz + i);
    Lanes d;
    if (o < s.boxes) {
      d = box_distance(to_local(s, o, px, py, pz), s.ex[o], s.ey[o], s.ez[o]);
    } else if (o < s.boxes + s.cylinders) {
      d = cylinder_distance(to_local(s, o, px, py, pz), s.ex[o], s.ey[o]);
    } else {
      const Lanes dx = px - s.cx[o], dy = py - s.cy[o], dz = pz - s.cz[o];
      d = stdx::sqrt(dx * dx + dy * dy + dz * dz) - s.ex[o];
    }
    store(d - load(r + i), out + i);
  }
}

void sphere_gaps(double cx, double cy, double cz, double radius, const double* wx, const double* wy, const double* wz,
                 const double* r, std::size_t n, double* out) {
  for (std::size_t i = 0; i < n; i += kSphereLanes) {
    const Lanes dx = load(wx + i) - cx, dy = load(wy + i) - cy, dz = load(wz + i) - cz;
    store(stdx::sqrt(dx * dx + dy * dy + dz * dz) - radius - load(r + i), out + i);
  }
}

const SphereKernels kKernels{AMP_KERNEL_NAME, compose, turn_z, place_point, place, obstacle_gaps, sphere_gaps};

}  // namespace amp::world::detail::AMP_KERNEL_NS
