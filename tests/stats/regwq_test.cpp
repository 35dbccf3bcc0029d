#include "amp/stats/regwq.hpp"

#include <cmath>
#include <vector>

#include <boost/math/distributions/students_t.hpp>
#include <gtest/gtest.h>

#include "amp/core/error.hpp"

namespace amp::stats {
namespace {

using Subsets = std::vector<std::vector<std::size_t>>;

// Five groups of n = 5 sharing the deviations (-1, 1, 0, -2, 2) from their means, so that
// SS_within = 5 * 10 = 50, df = 20, MSE = 2.5 and the standard error sqrt(MSE / n) = sqrt(0.5).
// Means A 11, B 13, C 16.3, D 16.4, E 21; given out of order (C, A, E, B, D) to exercise sorting.
const std::vector<double> kA = {10, 12, 11, 9, 13};
std::vector<double> shifted(double by) {
  std::vector<double> g(kA);
  for (double& v : g) v += by;
  return g;
}
const Groups kBalanced = {shifted(5.3), kA, shifted(10.0), shifted(2.0), shifted(5.4)};
enum { kC = 0, kAIdx = 1, kE = 2, kB = 3, kD = 4 };

// Critical values at alpha = 0.01, k = 5, df = 20, from R (root of ptukey, which qtukey matches
// to 3e-7): uniroot(function(q) ptukey(q, p, 20) - (1 - alpha_p), c(0.5, 50), tol = 1e-13)$root
//   p = 5, 4: alpha_p = 0.01                         q = 5.293252519, 5.018016132
//   p = 3:    alpha_p = 1 - 0.99^(3/5) = 0.006012056  q = 4.959151617
//   p = 2:    alpha_p = 1 - 0.99^(2/5) = 0.004012064  q = 4.595976399
// Critical ranges q * sqrt(0.5): 3.742895, 3.548273, 3.506650, 3.249846.
// Steps by hand (ordered positions A0 B1 C2 D3 E4):
//   p=5 A..E 10.0 > 3.7429 significant
//   p=4 A..D  5.4 > 3.5483 significant;  B..E 8.0 > 3.5483 significant
//   p=3 A..C  5.3 > 3.5067 significant;  B..D 3.4 < 3.5067 NOT;  C..E 4.7 > 3.5067 significant
//   p=2 A-B   2.0 < 3.2498 NOT;  B-C and C-D lie inside B..D: not tested (B-C, 3.3, would have
//       passed 3.2498 on its own);  D-E 4.6 > 3.2498 significant
// Homogeneous subsets (SPSS layout): {A, B}, {B, C, D}, {E}.
TEST(Regwq, BalancedExampleStepByStep) {
  const RegwqResult r = regwq(kBalanced, 0.01);
  ASSERT_EQ(r.status, TestStatus::kOk);
  EXPECT_NEAR(r.mse, 2.5, 1e-12);
  EXPECT_EQ(r.df_error, 20.0);
  EXPECT_EQ(r.order, (std::vector<std::size_t>{kAIdx, kB, kC, kD, kE}));

  struct Expected {
    std::size_t lo, hi;
    double alpha_p, q, critical;
    bool significant;
  };
  const Expected expected[] = {
      {0, 4, 0.01, 5.293252519, 3.742895, true},
      {0, 3, 0.01, 5.018016132, 3.548273, true},
      {1, 4, 0.01, 5.018016132, 3.548273, true},
      {0, 2, 0.006012056338, 4.959151617, 3.506650, true},
      {1, 3, 0.006012056338, 4.959151617, 3.506650, false},
      {2, 4, 0.006012056338, 4.959151617, 3.506650, true},
      {0, 1, 0.004012064419, 4.595976399, 3.249846, false},
      {3, 4, 0.004012064419, 4.595976399, 3.249846, true},
  };
  ASSERT_EQ(r.steps.size(), std::size(expected));
  for (std::size_t i = 0; i < r.steps.size(); ++i) {
    const RegwqStep& s = r.steps[i];
    EXPECT_EQ(s.lo, expected[i].lo) << i;
    EXPECT_EQ(s.hi, expected[i].hi) << i;
    EXPECT_EQ(s.p, static_cast<int>(s.hi - s.lo + 1)) << i;
    EXPECT_NEAR(s.alpha_p, expected[i].alpha_p, 1e-11) << i;
    EXPECT_NEAR(s.q_critical, expected[i].q, 1e-6) << i;
    EXPECT_NEAR(s.critical_range, expected[i].critical, 1e-6) << i;
    EXPECT_EQ(s.significant, expected[i].significant) << i;
  }
  EXPECT_EQ(r.subsets, (Subsets{{kAIdx, kB}, {kB, kC, kD}, {kE}}));

  const std::vector<std::pair<int, int>> different = {{kAIdx, kC}, {kAIdx, kD}, {kAIdx, kE}, {kB, kE}, {kC, kE}, {kD, kE}};
  const std::vector<std::pair<int, int>> same = {{kAIdx, kB}, {kB, kC}, {kB, kD}, {kC, kD}};
  for (auto [a, b] : different) {
    EXPECT_TRUE(r.differs[a][b]) << a << "," << b;
    EXPECT_TRUE(r.differs[b][a]) << a << "," << b;
  }
  for (auto [a, b] : same) EXPECT_FALSE(r.differs[a][b]) << a << "," << b;
}

// Unequal sizes (Tukey-Kramer). Means: g0 7.05 (n 4), g1 4.8333 (n 6), g2 10.24 (n 5),
// g3 8.3125 (n 8); SS_within = 13.524083, df = 19, MSE = 0.7117938596. k = 4, alpha = 0.01:
//   p = 4, 3: alpha_p = 0.01, q = 5.053908059, 4.669433376;  p = 2: 1 - 0.99^(1/2) = 0.005012563, q = 4.486738883
// Ordered g1 < g0 < g3 < g2. By hand, critical = q sqrt(MSE / 2 (1 / n_a + 1 / n_b)):
//   p=4 g1..g2 5.4067 > 5.0539 sqrt(0.35590 (1/6 + 1/5)) = 1.825682 significant
//   p=3 g1..g3 3.4792 > 4.6694 sqrt(0.35590 (1/6 + 1/8)) = 1.504422 significant
//       g0..g2 3.1900 > 4.6694 sqrt(0.35590 (1/4 + 1/5)) = 1.868670 significant
//   p=2 g1-g0  2.2167 > 1.727775 significant;  g0-g3 1.2625 < 1.639112 NOT;  g3-g2 1.9275 > 1.525930 significant
// Subsets: {g1}, {g0, g3}, {g2}.
TEST(Regwq, UnequalSizesUseTukeyKramer) {
  const Groups g = {
      {6.9, 7.4, 5.8, 8.1},
      {4.1, 5.3, 3.8, 6.0, 4.6, 5.2},
      {10.2, 9.1, 11.4, 10.8, 9.7},
      {7.2, 8.8, 7.9, 9.4, 8.1, 7.5, 8.6, 9.0},
  };
  const RegwqResult r = regwq(g);  // alpha defaults to the paper's 0.01
  ASSERT_EQ(r.status, TestStatus::kOk);
  EXPECT_NEAR(r.mse, 0.7117938596, 1e-9);
  EXPECT_EQ(r.order, (std::vector<std::size_t>{1, 0, 3, 2}));
  const double critical[] = {1.825682, 1.504422, 1.868670, 1.727775, 1.639112, 1.525930};
  const bool significant[] = {true, true, true, true, false, true};
  ASSERT_EQ(r.steps.size(), 6u);
  for (std::size_t i = 0; i < 6; ++i) {
    EXPECT_NEAR(r.steps[i].critical_range, critical[i], 1e-6) << i;
    EXPECT_EQ(r.steps[i].significant, significant[i]) << i;
  }
  EXPECT_NEAR(r.steps[3].alpha_p, 1.0 - std::sqrt(0.99), 1e-12);
  EXPECT_EQ(r.subsets, (Subsets{{1}, {0, 3}, {2}}));
  EXPECT_FALSE(r.differs[0][3]);
  EXPECT_TRUE(r.differs[0][1]);
  EXPECT_TRUE(r.differs[1][2]);
  EXPECT_TRUE(r.differs[3][2]);
}

// With two groups REGWQ is the pooled two-sample t test at level alpha: q = sqrt(2) t(1 - alpha/2; df).
TEST(Regwq, TwoGroupsIsTheTTest) {
  const Groups g = {{1.0, 2.0, 3.0, 4.0}, {3.5, 4.5, 5.5, 6.5, 7.5}};
  const RegwqResult r = regwq(g, 0.05);
  ASSERT_EQ(r.steps.size(), 1u);
  const double t = boost::math::quantile(boost::math::students_t(7.0), 0.975);
  EXPECT_NEAR(r.steps[0].q_critical, std::sqrt(2.0) * t, 1e-8);
  EXPECT_EQ(r.steps[0].alpha_p, 0.05);
  // Means 2.5 and 5.5: MSE = (5 + 10) / 7, SE = sqrt(MSE (1/4 + 1/5)) = 0.97590; |t| = 3 / 0.97590 = 3.074 > 2.365.
  EXPECT_TRUE(r.steps[0].significant);
  EXPECT_TRUE(r.differs[0][1]);
  EXPECT_EQ(r.subsets, (Subsets{{0}, {1}}));
}

TEST(Regwq, IdenticalMeansFormOneSubset) {
  const Groups g = {{1.0, 2.0, 3.0}, {3.0, 2.0, 1.0}, {2.0, 1.0, 3.0}};
  const RegwqResult r = regwq(g);
  ASSERT_EQ(r.steps.size(), 1u);  // the full range is not significant, nothing inside is tested
  EXPECT_EQ(r.subsets, (Subsets{{0, 1, 2}}));
}

TEST(Regwq, DegenerateAndBadInput) {
  const RegwqResult constant = regwq({{2.0, 2.0}, {5.0, 5.0, 5.0}});
  EXPECT_EQ(constant.status, TestStatus::kZeroVariance);
  EXPECT_TRUE(constant.steps.empty());
  EXPECT_TRUE(constant.subsets.empty());
  EXPECT_FALSE(constant.differs[0][1]);
  EXPECT_EQ(regwq({{2.0}, {5.0}}).status, TestStatus::kTooFewObservations);
  EXPECT_THROW(regwq({{1.0, 2.0}}), ParameterError);
  EXPECT_THROW(regwq(kBalanced, 0.0), ParameterError);
  EXPECT_THROW(regwq(kBalanced, 1.0), ParameterError);
}

}  // namespace
}  // namespace amp::stats
