#pragma once
#include <span>

namespace amp::learn {

// Adjusted Rand index (Hubert & Arabie 1985) of two labelings of the same points: 1 for identical
// partitions (whatever the label names), about 0 for independent ones, negative below chance.
// ARI = (sum_ij C(n_ij, 2) - E) / (0.5 (sum_i C(a_i, 2) + sum_j C(b_j, 2)) - E),
// E = sum_i C(a_i, 2) sum_j C(b_j, 2) / C(n, 2), n_ij the contingency table, a and b its margins.
// When the denominator is 0 (both partitions trivial in the same way: one cluster each, or all
// singletons each) the partitions are equal and the index is 1.
// Throws ParameterError for different lengths or negative labels.
double adjusted_rand_index(std::span<const int> a, std::span<const int> b);

}  // namespace amp::learn
