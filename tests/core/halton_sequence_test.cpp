#include "amp/core/halton_sequence.hpp"

#include <cmath>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "amp/core/error.hpp"
#include "amp/core/joint_space.hpp"
#include "amp/core/se3_space.hpp"

namespace amp::core {
namespace {

std::vector<std::vector<double>> points(HaltonSequence& h, int n) {
  std::vector<std::vector<double>> out(static_cast<std::size_t>(n), std::vector<double>(static_cast<std::size_t>(h.dimension())));
  for (auto& p : out) h.next(p.data());
  return out;
}

// Warnock's closed form of the squared L2 star discrepancy of points in [0, 1)^d.
double l2_star_discrepancy_squared(const std::vector<std::vector<double>>& x) {
  const double n = static_cast<double>(x.size());
  const int d = static_cast<int>(x[0].size());
  double single = 0.0, pairs = 0.0;
  for (const auto& p : x) {
    double prod = 1.0;
    for (int k = 0; k < d; ++k) prod *= 1.0 - p[k] * p[k];
    single += prod;
    for (const auto& q : x) {
      double m = 1.0;
      for (int k = 0; k < d; ++k) m *= 1.0 - std::max(p[k], q[k]);
      pairs += m;
    }
  }
  return std::pow(3.0, -d) - std::pow(2.0, 1 - d) / n * single + pairs / (n * n);
}

TEST(HaltonSequence, RadicalInverseMatchesHandValues) {
  EXPECT_DOUBLE_EQ(HaltonSequence::radical_inverse(0, 2), 0.0);
  EXPECT_DOUBLE_EQ(HaltonSequence::radical_inverse(1, 2), 0.5);
  EXPECT_DOUBLE_EQ(HaltonSequence::radical_inverse(2, 2), 0.25);
  EXPECT_DOUBLE_EQ(HaltonSequence::radical_inverse(3, 2), 0.75);
  EXPECT_DOUBLE_EQ(HaltonSequence::radical_inverse(6, 2), 0.375);  // 110 -> 0.011
  EXPECT_NEAR(HaltonSequence::radical_inverse(1, 3), 1.0 / 3, 1e-15);
  EXPECT_NEAR(HaltonSequence::radical_inverse(5, 3), 7.0 / 9, 1e-15);  // 12 -> 0.21 = 2/3 + 1/9
  EXPECT_NEAR(HaltonSequence::radical_inverse(7, 5), 2.0 / 5 + 1.0 / 25, 1e-15);  // 12 -> 0.21 = 2/5 + 1/25
}

TEST(HaltonSequence, RejectsDimensionsOutsideOneToThirtyTwo) {
  Rng rng(1);
  EXPECT_THROW(HaltonSequence(0, rng), ParameterError);
  EXPECT_THROW(HaltonSequence(HaltonSequence::kMaxDimension + 1, rng), ParameterError);
  EXPECT_NO_THROW(HaltonSequence(HaltonSequence::kMaxDimension, rng));
}

TEST(HaltonSequence, IsFixedByTheSeedAndStaysInTheUnitCube) {
  Rng a(7), b(7), c(8);
  HaltonSequence ha(6, a), hb(6, b), hc(6, c);
  const auto pa = points(ha, 500), pb = points(hb, 500), pc = points(hc, 500);
  EXPECT_EQ(pa, pb);
  EXPECT_NE(pa, pc);
  for (const auto& p : pa) {
    for (const double u : p) {
      EXPECT_GE(u, 0.0);
      EXPECT_LT(u, 1.0);
    }
  }
}

TEST(HaltonSequence, EachCoordinateIsStratifiedLikeThePlainSequence) {
  // Indices 1..b^k of a coordinate in base b: the digit permutation maps the b^k values {j / b^k}
  // of indices 0..b^k-1 onto themselves, index 0 (value 0) is replaced by index b^k (a value below
  // 1/b^k), and the shift moves all of them alike. So every interval of length 1/b^k holds at most
  // two points and at most one interval is empty (independent uniforms: about 37% empty).
  Rng rng(3);
  HaltonSequence h(3, rng);
  const int bases[] = {2, 3, 5};
  const int powers[] = {10, 6, 4};
  const auto p = points(h, 1024);  // >= 2^10, 3^6 = 729, 5^4 = 625
  for (int c = 0; c < 3; ++c) {
    const int n = static_cast<int>(std::lround(std::pow(bases[c], powers[c])));
    std::vector<int> counts(static_cast<std::size_t>(n), 0);
    for (int i = 0; i < n; ++i) ++counts[static_cast<std::size_t>(p[static_cast<std::size_t>(i)][c] * n)];
    int empty = 0, most = 0;
    for (const int k : counts) {
      empty += k == 0;
      most = std::max(most, k);
    }
    EXPECT_LE(most, 2) << "base " << bases[c];
    EXPECT_LE(empty, 1) << "base " << bases[c];
  }
}

TEST(HaltonSequence, CoversTheSquareFarMoreEvenlyThanIndependentPoints) {
  // Expected squared L2 star discrepancy of n independent uniform points in [0,1)^d:
  // (2^-d - 3^-d) / n. The randomised Halton points must beat it by a wide margin.
  for (const std::uint64_t seed : {1u, 2u, 3u}) {
    Rng rng(seed);
    HaltonSequence h(2, rng);
    const auto p = points(h, 1024);
    const double random_expectation = (0.25 - 1.0 / 9) / 1024;
    EXPECT_LT(l2_star_discrepancy_squared(p), 0.1 * random_expectation) << "seed " << seed;
  }
}

TEST(SpaceFromUnit, SampleUniformIsFromUnitOfTheRngsUniforms) {
  const JointSpace se2 = make_se2_space(0, -1, 10, 1, 0.5);
  const Se3Space se3({0, 0, 0}, {1, 2, 3}, 1.0);
  for (const Space* space : {static_cast<const Space*>(&se2), static_cast<const Space*>(&se3)}) {
    Rng a(11), b(11);
    State s1, s2;
    space->sample_uniform(a, s1);
    std::vector<double> u(static_cast<std::size_t>(space->unit_dimension()));
    for (double& x : u) x = b.uniform01();
    space->from_unit(u.data(), s2);
    EXPECT_EQ(s1, s2) << space->kind();
  }
}

TEST(SpaceFromUnit, MapsTheCubeOntoTheBounds) {
  const JointSpace se2 = make_se2_space(0, -1, 10, 1, 0.5);
  const double lo[] = {0.0, 0.0, 0.0}, mid[] = {0.5, 0.5, 0.5};
  State s;
  se2.from_unit(lo, s);
  EXPECT_DOUBLE_EQ(s[0], 0.0);
  EXPECT_DOUBLE_EQ(s[1], -1.0);
  EXPECT_DOUBLE_EQ(s[2], -std::numbers::pi);  // the continuous joint's [-pi, pi)
  se2.from_unit(mid, s);
  EXPECT_DOUBLE_EQ(s[0], 5.0);
  EXPECT_DOUBLE_EQ(s[1], 0.0);
  EXPECT_DOUBLE_EQ(s[2], 0.0);
  const Se3Space se3({0, 0, 0}, {1, 2, 3}, 1.0);
  EXPECT_EQ(se3.unit_dimension(), 6);
  Rng rng(4);
  HaltonSequence h(6, rng);
  double u[6];
  for (int i = 0; i < 200; ++i) {
    h.next(u);
    se3.from_unit(u, s);
    EXPECT_TRUE(se3.in_bounds(s));
    EXPECT_NEAR(s.tail<4>().norm(), 1.0, 1e-12);
  }
}

}  // namespace
}  // namespace amp::core
