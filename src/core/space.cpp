#include "amp/core/space.hpp"

#include <array>
#include <cmath>
#include <vector>
#include <string>

#include "amp/core/error.hpp"

namespace amp::core {

void Space::sample_uniform(Rng& rng, State& out) const {
  constexpr int kInline = 32;  // no allocation for any space we bundle
  const int n = unit_dimension();
  std::array<double, kInline> inline_u{};
  std::vector<double> heap_u;
  double* u = inline_u.data();
  if (n > kInline) {
    heap_u.resize(static_cast<std::size_t>(n));
    u = heap_u.data();
  }
  for (int i = 0; i < n; ++i) u[i] = rng.uniform01();
  from_unit(u, out);
}

void Space::set_resolution(double r) {
  if (!(r > 0.0) || !std::isfinite(r)) {
    throw ParameterError("resolution must be a positive number, got " + std::to_string(r));
  }
  resolution_ = r;
}

}  // namespace amp::core
