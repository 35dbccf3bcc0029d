#include "amp/stats/studentized_range.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <string>

#include <boost/math/distributions/chi_squared.hpp>
#include <boost/math/quadrature/gauss.hpp>
#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <boost/math/tools/toms748_solve.hpp>

#include "amp/core/error.hpp"

namespace amp::stats {
namespace {

// Inner integral over z: phi(8.5) ~ 1.7e-16, so [-8.5, 8.5] holds all of the mass that a double
// can see; unit panels with 10 Gauss-Legendre nodes resolve even the narrow integrand of k = 20.
constexpr double kZMax = 8.5;
constexpr int kInnerPanels = 17;
constexpr int kInnerNodes = 10;
// P(range of k <= 100 normals >= 20) < 1e-40: W is 1 at double precision beyond this.
constexpr double kRangeCertain = 20.0;
// Chi-square mass left out of the outer integral on each side.
constexpr double kChiTail = 1e-15;
// Outer adaptive Gauss-Kronrod: relative tolerance per piece and maximum bisection depth.
constexpr double kOuterTolerance = 1e-11;
constexpr unsigned kOuterDepth = 12;
// W(w) rises from ~0 to ~1 for w in roughly [1, 8]; splitting the outer integral at s = c / q keeps
// that rise inside pieces of its own even when q is large and the chi density is wide.
constexpr std::array<double, 3> kRiseBreaks = {1.0, 3.0, 8.0};
// Quantile: bits of q to resolve, iteration cap, and doublings allowed when bracketing.
constexpr int kRootBits = 36;
constexpr std::uintmax_t kRootIterations = 200;
constexpr int kMaxDoublings = 80;

double upper_tail(double x) { return 0.5 * std::erfc(x / std::sqrt(2.0)); }  // 1 - Phi(x)

// b^e by squaring: exact enough and several times faster than std::pow in the innermost loop.
double int_pow(double b, int e) {
  double r = 1.0;
  while (e > 0) {
    if (e & 1) r *= b;
    b *= b;
    e >>= 1;
  }
  return r;
}

// The inner z nodes never change, so phi(z) and the tails at z are tabulated once; an evaluation of
// W then costs one erfc per node instead of three transcendental calls.
constexpr int kInnerCount = kInnerPanels * kInnerNodes;
struct InnerNodes {
  std::array<double, kInnerCount> z{};
  std::array<double, kInnerCount> weight{};      // Gauss-Legendre weight * phi(z)
  std::array<double, kInnerCount> tail_up{};     // 1 - Phi(z)
  std::array<double, kInnerCount> tail_down{};   // Phi(z)
};

InnerNodes make_inner_nodes() {
  using Gauss = boost::math::quadrature::gauss<double, kInnerNodes>;
  const auto& x = Gauss::abscissa();  // non-negative half of the symmetric rule
  const auto& w = Gauss::weights();
  InnerNodes nodes;
  const double half = kZMax / kInnerPanels;  // half a panel width
  int n = 0;
  const auto add = [&](double z, double weight) {
    nodes.z[n] = z;
    nodes.weight[n] = weight * std::exp(-0.5 * z * z) / std::sqrt(2.0 * std::numbers::pi);
    nodes.tail_up[n] = upper_tail(z);
    nodes.tail_down[n] = upper_tail(-z);
    ++n;
  };
  for (int panel = 0; panel < kInnerPanels; ++panel) {
    const double centre = -kZMax + (2 * panel + 1) * half;
    for (std::size_t i = 0; i < x.size(); ++i) {
      add(centre + half * x[i], half * w[i]);
      if (x[i] != 0.0) add(centre - half * x[i], half * w[i]);
    }
  }
  return nodes;
}

const InnerNodes& inner_nodes() {
  static const InnerNodes nodes = make_inner_nodes();  // immutable once built; thread-safe init
  return nodes;
}

// W(w) = k int phi(z) [Phi(z + w) - Phi(z)]^(k-1) dz: P(range of k iid standard normals <= w),
// i.e. the cdf for df = infinity. The bracket is formed from upper tails on the side where both
// terms are small, so it keeps its relative precision far out in the tails.
double range_cdf(double w, int k) {
  if (w <= 0.0) return 0.0;
  if (w >= kRangeCertain) return 1.0;
  const InnerNodes& nodes = inner_nodes();
  double sum = 0.0;
  for (int i = 0; i < kInnerCount; ++i) {
    const double z = nodes.z[i];
    double band = 0.0;
    if (z >= 0.0) {
      band = nodes.tail_up[i] - upper_tail(z + w);
    } else if (z + w <= 0.0) {
      band = upper_tail(-(z + w)) - nodes.tail_down[i];
    } else {
      band = 1.0 - upper_tail(z + w) - nodes.tail_down[i];
    }
    if (band > 0.0) sum += nodes.weight[i] * int_pow(band, k - 1);
  }
  return std::min(1.0, k * sum);
}

void check_shape(int k, double df, const char* function) {
  if (k < 2) throw ParameterError(std::string(function) + ": k: need at least 2 means, got " + std::to_string(k));
  if (!(df >= 1.0)) {
    throw ParameterError(std::string(function) + ": df: need df >= 1 (or infinity), got " + std::to_string(df));
  }
}

}  // namespace

double studentized_range_cdf(double q, int k, double df) {
  check_shape(k, df, "studentized_range_cdf");
  if (std::isnan(q)) throw ParameterError("studentized_range_cdf: q: is NaN");
  if (q <= 0.0) return 0.0;
  if (std::isinf(q)) return 1.0;
  if (std::isinf(df)) return range_cdf(q, k);

  // S = sqrt(X / df) with X ~ chi2(df): f_S(s) = 2 df s f_X(df s^2).
  const boost::math::chi_squared chi(df);
  const auto integrand = [&](double s) { return 2.0 * df * s * boost::math::pdf(chi, df * s * s) * range_cdf(q * s, k); };
  const double s_lo = std::sqrt(boost::math::quantile(chi, kChiTail) / df);
  const double s_hi = std::sqrt(boost::math::quantile(boost::math::complement(chi, kChiTail)) / df);

  std::array<double, kRiseBreaks.size() + 3> breaks{};
  std::size_t n = 0;
  breaks[n++] = s_lo;
  breaks[n++] = std::sqrt((df - 1.0) / df);  // mode of f_S
  for (double c : kRiseBreaks) breaks[n++] = c / q;
  breaks[n++] = s_hi;
  std::sort(breaks.begin(), breaks.begin() + n);

  using Kronrod = boost::math::quadrature::gauss_kronrod<double, 31>;
  double sum = 0.0;
  for (std::size_t i = 0; i + 1 < n; ++i) {
    const double a = std::clamp(breaks[i], s_lo, s_hi);
    const double b = std::clamp(breaks[i + 1], s_lo, s_hi);
    if (b > a) sum += Kronrod::integrate(integrand, a, b, kOuterDepth, kOuterTolerance);
  }
  return std::clamp(sum, 0.0, 1.0);
}

double studentized_range_quantile(double p, int k, double df) {
  check_shape(k, df, "studentized_range_quantile");
  if (!(p >= 0.0 && p <= 1.0)) {
    throw ParameterError("studentized_range_quantile: p: need 0 <= p <= 1, got " + std::to_string(p));
  }
  if (p == 0.0) return 0.0;
  if (p == 1.0) return std::numeric_limits<double>::infinity();

  const auto f = [&](double q) { return studentized_range_cdf(q, k, df) - p; };
  // Bracket: f(0) = -p < 0; double the upper end until the cdf passes p.
  double lo = 0.0;
  double f_lo = -p;
  double hi = 1.0;
  double f_hi = f(hi);
  for (int i = 0; f_hi < 0.0; ++i) {
    if (i == kMaxDoublings) return std::numeric_limits<double>::infinity();  // p is 1 within cdf error
    lo = hi;
    f_lo = f_hi;
    hi *= 2.0;
    f_hi = f(hi);
  }
  if (f_hi == 0.0) return hi;
  std::uintmax_t iterations = kRootIterations;
  const auto [a, b] = boost::math::tools::toms748_solve(f, lo, hi, f_lo, f_hi,
                                                        boost::math::tools::eps_tolerance<double>(kRootBits), iterations);
  return 0.5 * (a + b);
}

}  // namespace amp::stats
