#include "amp/study/record_json.hpp"

#include <cmath>

namespace amp::study {

nlohmann::ordered_json param_json(const core::ParamValue& v) {
  if (!v.is_number()) return v.string();
  const double x = v.number();
  if (x == std::floor(x) && std::abs(x) < 9e15) return static_cast<long long>(x);
  return x;
}

nlohmann::ordered_json finite_or_null(double x) { return std::isfinite(x) ? nlohmann::ordered_json(x) : nullptr; }

nlohmann::ordered_json optional_json(const std::optional<double>& x) {
  return x ? nlohmann::ordered_json(*x) : nlohmann::ordered_json();
}

}  // namespace amp::study
