#include "amp/core/space.hpp"

#include <cmath>
#include <string>

#include "amp/core/error.hpp"

namespace amp::core {

void Space::set_resolution(double r) {
  if (!(r > 0.0) || !std::isfinite(r)) {
    throw ParameterError("resolution must be a positive number, got " + std::to_string(r));
  }
  resolution_ = r;
}

}  // namespace amp::core
