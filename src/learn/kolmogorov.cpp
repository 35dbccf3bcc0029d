#include "amp/learn/kolmogorov.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include "amp/core/error.hpp"

namespace amp::learn {
namespace {

constexpr double kSwitch = 1.18;        // below: the theta-function series; above: the alternating one
constexpr double kRelativeTerm = 1e-17; // stop summing once a term is this small relative to the sum
constexpr int kMaxTerms = 100;          // never reached (< 10 terms needed), a guard only

// sqrt(2 pi)/x sum exp(-(2k-1)^2 pi^2 / (8 x^2)), for 0 < x.
double small_x_cdf(double x) {
  const double a = -std::numbers::pi * std::numbers::pi / (8.0 * x * x);
  double sum = 0.0;
  for (int k = 1; k <= kMaxTerms; ++k) {
    const double m = 2.0 * k - 1.0;
    const double term = std::exp(a * m * m);
    sum += term;
    if (term <= kRelativeTerm * sum) break;
  }
  return std::sqrt(2.0 * std::numbers::pi) / x * sum;
}

// 2 sum (-1)^(k-1) exp(-2 k^2 x^2) = 1 - K(x).
double large_x_sf(double x) {
  double sum = 0.0;
  for (int k = 1; k <= kMaxTerms; ++k) {
    const double term = std::exp(-2.0 * k * k * x * x);
    sum += (k % 2 == 1) ? term : -term;
    if (term <= kRelativeTerm * sum) break;
  }
  return 2.0 * sum;
}

}  // namespace

double kolmogorov_cdf(double x) {
  if (!(x > 0.0)) return 0.0;
  if (x < kSwitch) return small_x_cdf(x);
  return 1.0 - large_x_sf(x);
}

double kolmogorov_sf(double x) {
  if (!(x > 0.0)) return 1.0;
  if (x < kSwitch) return 1.0 - small_x_cdf(x);
  return large_x_sf(x);
}

double kolmogorov_quantile(double p) {
  if (!(p >= 0.0 && p <= 1.0)) throw ParameterError("kolmogorov_quantile: p: " + std::to_string(p) + " outside [0, 1]");
  if (p == 0.0) return 0.0;
  if (p == 1.0) return std::numeric_limits<double>::infinity();
  // K rises from 0 to 1 within (0.05, 40); for p near 1, compare the survival function instead.
  const double q = 1.0 - p;
  double lo = 0.0;
  double hi = 40.0;
  for (int i = 0; i < 200 && hi - lo > 4.0 * std::numeric_limits<double>::epsilon() * hi; ++i) {
    const double mid = 0.5 * (lo + hi);
    const bool below = p < 0.5 ? kolmogorov_cdf(mid) < p : kolmogorov_sf(mid) > q;
    (below ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

double ks_statistic(std::span<const double> sorted_model_cdf) {
  const double n = static_cast<double>(sorted_model_cdf.size());
  double d = 0.0;
  for (std::size_t i = 0; i < sorted_model_cdf.size(); ++i) {
    const double f = sorted_model_cdf[i];
    d = std::max({d, (static_cast<double>(i) + 1.0) / n - f, f - static_cast<double>(i) / n});
  }
  return d;
}

double stephens_scale(int n) {
  const double r = std::sqrt(static_cast<double>(n));
  return r + 0.12 + 0.11 / r;
}

double ks_p_value(double d, int n) { return kolmogorov_sf(stephens_scale(n) * d); }

double ks_critical_value(int n, double alpha) {
  if (!(alpha > 0.0 && alpha < 1.0)) {
    throw ParameterError("ks_critical_value: alpha: " + std::to_string(alpha) + " outside (0, 1)");
  }
  if (n < 1) throw ParameterError("ks_critical_value: n: " + std::to_string(n) + " < 1");
  return kolmogorov_quantile(1.0 - alpha) / stephens_scale(n);
}

}  // namespace amp::learn
