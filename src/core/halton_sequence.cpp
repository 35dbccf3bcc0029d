#include "amp/core/halton_sequence.hpp"

#include <cmath>
#include <numeric>
#include <string>
#include <utility>

#include "amp/core/error.hpp"

namespace amp::core {

namespace {
constexpr int kPrimes[HaltonSequence::kMaxDimension] = {2,  3,  5,  7,  11, 13, 17, 19, 23, 29, 31,
                                                        37, 41, 43, 47, 53, 59, 61, 67, 71, 73, 79,
                                                        83, 89, 97, 101, 103, 107, 109, 113, 127, 131};
}  // namespace

HaltonSequence::HaltonSequence(int dimension, Rng& rng) {
  if (dimension < 1 || dimension > kMaxDimension) {
    throw ParameterError("halton sequence: dimension must be in [1, " + std::to_string(kMaxDimension) + "], got " +
                         std::to_string(dimension));
  }
  for (int i = 0; i < dimension; ++i) {
    const int b = kPrimes[i];
    bases_.push_back(b);
    // Fisher-Yates over the digits 1..b-1; 0 stays 0 so the infinitely many leading zeros of the
    // expansion stay zero and the point stays a finite sum.
    std::vector<int> perm(static_cast<std::size_t>(b));
    std::iota(perm.begin(), perm.end(), 0);
    for (int j = b - 1; j > 1; --j) {
      const auto k = 1 + static_cast<int>(rng.uniform_index(static_cast<std::uint64_t>(j)));
      std::swap(perm[static_cast<std::size_t>(j)], perm[static_cast<std::size_t>(k)]);
    }
    permutations_.push_back(std::move(perm));
    shifts_.push_back(rng.uniform01());
  }
}

double HaltonSequence::radical_inverse(std::uint64_t index, int base) {
  double scale = 1.0 / base, value = 0.0;
  for (; index > 0; index /= static_cast<std::uint64_t>(base), scale /= base) {
    value += static_cast<double>(index % static_cast<std::uint64_t>(base)) * scale;
  }
  return value;
}

void HaltonSequence::next(double* u) {
  for (std::size_t i = 0; i < bases_.size(); ++i) {
    const auto b = static_cast<std::uint64_t>(bases_[i]);
    const std::vector<int>& perm = permutations_[i];
    double scale = 1.0 / static_cast<double>(b), value = 0.0;
    for (std::uint64_t n = index_; n > 0; n /= b, scale /= static_cast<double>(b)) {
      value += perm[static_cast<std::size_t>(n % b)] * scale;
    }
    value += shifts_[i];
    if (value >= 1.0) value -= 1.0;
    u[i] = value < 1.0 ? value : std::nextafter(1.0, 0.0);  // rounding can leave exactly 1
  }
  ++index_;
}

}  // namespace amp::core
