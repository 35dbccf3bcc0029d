#pragma once
#include <cstdint>
#include <vector>

#include "amp/core/rng.hpp"

namespace amp::core {

// A randomised Halton sequence in [0, 1)^d: coordinate i is the radical inverse of the index in the
// i-th prime base, with a random permutation of the nonzero digits per coordinate (so the large
// bases' coordinates are not correlated, Faure-Lemieux style) and a random Cranley-Patterson shift.
// Every point is uniform in the cube, yet n consecutive points cover it far more evenly than n random
// ones (discrepancy O(log^d n / n) instead of O(sqrt(log log n / n))): a small target region of volume
// v is hit about every 1/v points, not after a geometric waiting time. All randomness comes from the
// Rng the sequence is made with, so a run's seed fixes it.
class HaltonSequence {
 public:
  static constexpr int kMaxDimension = 32;

  // Throws ParameterError unless 1 <= dimension <= kMaxDimension.
  HaltonSequence(int dimension, Rng& rng);
  // The next point, `dimension` values in [0, 1).
  void next(double* u);
  int dimension() const { return static_cast<int>(bases_.size()); }
  std::uint64_t index() const { return index_; }

  // The plain radical inverse of `index` in `base` (digits mirrored about the point): tested against
  // hand values.
  static double radical_inverse(std::uint64_t index, int base);

 private:
  std::vector<int> bases_;
  std::vector<std::vector<int>> permutations_;  // per coordinate, a permutation of 0..base-1 fixing 0
  std::vector<double> shifts_;
  std::uint64_t index_ = 1;  // 0 is the origin in every base: skipped
};

}  // namespace amp::core
