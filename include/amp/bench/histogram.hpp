#pragma once
#include <cstddef>
#include <span>
#include <vector>

namespace amp::bench {

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

std::size_t bin_count(std::span<const double> x, BinRule rule);
// Throws ParameterError if a value is not finite.
Histogram histogram(std::span<const double> x, BinRule rule = BinRule::kFreedmanDiaconis);

}  // namespace amp::bench
