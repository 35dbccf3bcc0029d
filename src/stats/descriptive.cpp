#include "amp/stats/descriptive.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <boost/math/distributions/students_t.hpp>

#include "amp/core/error.hpp"

namespace amp::stats {

double quantile(std::span<const double> sorted, double prob) {
  if (sorted.empty()) throw ParameterError("quantile: sample: is empty");
  if (!(prob >= 0.0 && prob <= 1.0)) {
    throw ParameterError("quantile: prob: need 0 <= prob <= 1, got " + std::to_string(prob));
  }
  const double h = static_cast<double>(sorted.size() - 1) * prob;
  const auto lo = static_cast<std::size_t>(std::floor(h));
  if (lo + 1 >= sorted.size()) return sorted.back();
  return sorted[lo] + (h - static_cast<double>(lo)) * (sorted[lo + 1] - sorted[lo]);
}

std::optional<double> median(std::span<const double> sample) {
  if (sample.empty()) return std::nullopt;
  std::vector<double> sorted(sample.begin(), sample.end());
  std::sort(sorted.begin(), sorted.end());
  return quantile(sorted, 0.5);
}

Summary describe(std::span<const double> x) {
  Summary s;
  s.n = x.size();
  if (x.empty()) return s;
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (!std::isfinite(x[i])) {
      throw ParameterError("describe: x[" + std::to_string(i) + "]: value is not finite: " + std::to_string(x[i]));
    }
  }
  // Two passes: the mean, then squared deviations from it, so that large run costs with a small
  // spread do not cancel (the one-pass sum of squares loses digits at 1e6 +- 1).
  double sum = 0.0;
  for (double v : x) sum += v;
  s.mean = sum / static_cast<double>(s.n);
  if (s.n > 1) {
    double ss = 0.0;
    for (double v : x) ss += (v - s.mean) * (v - s.mean);
    s.std_dev = std::sqrt(ss / static_cast<double>(s.n - 1));
    if (s.mean != 0.0) s.cv_percent = 100.0 * s.std_dev / s.mean;
    const boost::math::students_t t(static_cast<double>(s.n - 1));
    const double half = boost::math::quantile(t, 0.975) * s.std_dev / std::sqrt(static_cast<double>(s.n));
    s.ci95_low = s.mean - half;
    s.ci95_high = s.mean + half;
  }
  std::vector<double> sorted(x.begin(), x.end());
  std::sort(sorted.begin(), sorted.end());
  s.min = sorted.front();
  s.max = sorted.back();
  s.q1 = quantile(sorted, 0.25);
  s.median = quantile(sorted, 0.5);
  s.q3 = quantile(sorted, 0.75);
  return s;
}

}  // namespace amp::stats
