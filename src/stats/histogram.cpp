#include "amp/stats/histogram.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "amp/core/error.hpp"
#include "amp/stats/descriptive.hpp"

namespace amp::stats {
namespace {

std::size_t sturges(std::size_t n) {
  return static_cast<std::size_t>(std::ceil(std::log2(static_cast<double>(n)) + 1.0));
}

}  // namespace

std::size_t bin_count(std::span<const double> x, BinRule rule, std::size_t max_bins) {
  if (x.empty()) return 0;
  const auto [lo, hi] = std::minmax_element(x.begin(), x.end());
  if (*lo == *hi) return 1;
  std::size_t k = sturges(x.size());
  if (rule == BinRule::kFreedmanDiaconis) {
    std::vector<double> sorted(x.begin(), x.end());
    std::sort(sorted.begin(), sorted.end());
    const double iqr = quantile(sorted, 0.75) - quantile(sorted, 0.25);
    const double width = 2.0 * iqr * std::pow(static_cast<double>(x.size()), -1.0 / 3.0);
    if (width > 0.0) k = static_cast<std::size_t>(std::max(1.0, std::ceil((*hi - *lo) / width)));
  }
  return std::min(k, max_bins);
}

Histogram histogram(std::span<const double> x, BinRule rule) {
  Histogram h;
  if (x.empty()) return h;
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (!std::isfinite(x[i])) {
      throw ParameterError("histogram: x[" + std::to_string(i) + "]: value is not finite: " + std::to_string(x[i]));
    }
  }
  const auto [lo_it, hi_it] = std::minmax_element(x.begin(), x.end());
  const double lo = *lo_it;
  const double hi = *hi_it;
  if (lo == hi) {
    h.edges = {lo - 0.5, lo + 0.5};
    h.counts = {x.size()};
    return h;
  }
  h.edges = equal_width_edges(lo, hi, bin_count(x, rule));
  h.counts = bin_counts(x, h.edges);
  return h;
}

std::vector<double> equal_width_edges(double lo, double hi, std::size_t bins) {
  std::vector<double> edges(bins + 1);
  for (std::size_t i = 0; i <= bins; ++i) {
    edges[i] = lo + (hi - lo) * static_cast<double>(i) / static_cast<double>(bins);
  }
  edges.back() = hi;  // exact, so that max falls in the last bin whatever the rounding
  return edges;
}

std::vector<std::size_t> bin_counts(std::span<const double> x, std::span<const double> edges) {
  std::vector<std::size_t> counts(edges.size() < 2 ? 0 : edges.size() - 1, 0);
  if (counts.empty()) return counts;
  // Bins are found against the stored edges (not by dividing by the width), so a value printed on
  // an edge is counted where the printed edges say it belongs.
  for (double v : x) {
    const auto above = std::upper_bound(edges.begin(), edges.end(), v);
    const auto bin = std::clamp<std::ptrdiff_t>(above - edges.begin() - 1, 0, std::ssize(counts) - 1);
    ++counts[static_cast<std::size_t>(bin)];
  }
  return counts;
}

}  // namespace amp::stats
