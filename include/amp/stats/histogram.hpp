#pragma once
#include <cstddef>
#include <span>
#include <vector>

namespace amp::stats {

// How many equal-width bins span [min, max].
enum class BinRule {
  kSturges,           // ceil(log2(n) + 1), R's nclass.Sturges
  kFreedmanDiaconis,  // ceil(range / (2 IQR n^(-1/3))), IQR by type-7 quartiles; Sturges when IQR = 0
};

// Equal-width histogram. Bin i is [edges[i], edges[i+1]), the last bin also holds max (R's
// hist(right = FALSE, include.lowest = TRUE)). edges.size() == counts.size() + 1, except for an
// empty sample (both empty). All-equal samples get one bin [v - 0.5, v + 0.5].
struct Histogram {
  std::vector<double> edges;
  std::vector<std::size_t> counts;
};

// Freedman-Diaconis follows heavy-tailed run-cost distributions better than Sturges, which
// assumes near-normal data; it is the default. At most kMaxBins bins.
inline constexpr std::size_t kMaxBins = 1000;

// Bins `rule` asks for (0 for an empty sample, 1 when all values are equal), at most max_bins.
std::size_t bin_count(std::span<const double> x, BinRule rule, std::size_t max_bins = kMaxBins);
// Throws ParameterError if a value is not finite.
Histogram histogram(std::span<const double> x, BinRule rule = BinRule::kFreedmanDiaconis);

// The building blocks of histogram(), for bins shared by several samples (the report's charts):
// bins + 1 edges lo + (hi - lo) i / bins, the last exactly hi; and the count of x per bin, bin i
// [edges[i], edges[i+1]), values below the first edge in the first bin and values at or above the
// last edge in the last (so values mapped through a transform that rounds still land in a bin).
std::vector<double> equal_width_edges(double lo, double hi, std::size_t bins);
std::vector<std::size_t> bin_counts(std::span<const double> x, std::span<const double> edges);

}  // namespace amp::stats
