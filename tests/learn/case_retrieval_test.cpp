// learn::CaseLibrary::retrieve: the similarity metric and the reverse sweep (Ram & Santamaria
// 1993, section 2.4) against hand computations, the tie rules, and a naive exhaustive search.
#include <algorithm>
#include <tuple>
#include <vector>

#include <gtest/gtest.h>

#include "amp/core/error.hpp"
#include "amp/core/rng.hpp"
#include "amp/learn/case_library.hpp"
#include "learn/case_fixture.hpp"

namespace amp::learn {
namespace {

using namespace case_test;  // NOLINT: the shared fixture

TEST(CaseLibraryRetrieve, ErrorsMatchTheHandComputation) {
  const CaseLibrary lib = hand_library();
  const CaseHistory h = hand_history();
  // E(j, p) = sum over the overlap of squared differences / (4 o); the newest sample h2 sits on k = p - 1.
  // Case 0 (constant): h2 -> .5^2 + .25^2 = .3125, h1 -> 0, h0 -> .5^2 = .25.
  EXPECT_EQ(lib.match(0, 3, h).error, (0.3125 + 0 + 0.25) / 12);  // 0.046875
  EXPECT_EQ(lib.match(0, 2, h).error, (0.3125 + 0) / 8);          // 0.0390625
  EXPECT_EQ(lib.match(0, 1, h).error, 0.3125 / 4);                // 0.078125
  // Case 1 at p = 3: h2 - k2 = (1, .25) -> 1.0625; h1 - k1 = (-.5, 0) -> .25; h0 - k0 = (-.5, 0) -> .25.
  EXPECT_EQ(lib.match(1, 3, h).error, (1.0625 + 0.25 + 0.25) / 12);
  // p = 2: h2 - k1 = (0, -.25) -> .0625; h1 - k0 = 0.
  EXPECT_EQ(lib.match(1, 2, h).error, 0.0625 / 8);  // 0.0078125
  // p = 1: h2 - k0 = (.5, -.25) -> .3125.
  EXPECT_EQ(lib.match(1, 1, h).error, 0.3125 / 4);
  EXPECT_EQ(lib.match(1, 2, h).overlap, 2);
  EXPECT_EQ(lib.match(1, 1, h).overlap, 1);

  // The reverse sweep picks the partial overlap: case 1 with its first two samples under the
  // history's last two, leaving k = 2 as the prediction.
  const CaseMatch best = lib.retrieve(h);
  EXPECT_EQ(best.case_index, 1);
  EXPECT_EQ(best.position, 2);
  EXPECT_EQ(best.overlap, 2);
  EXPECT_EQ(best.error, 0.0078125);
}

TEST(CaseLibraryRetrieve, ShortHistoryOverlapsOnlyWhatItHas) {
  const CaseLibrary lib = hand_library();
  CaseHistory h(3);
  h.push({1, 0.25, 0, 0}, {0, 0, 0, 0});
  // One sample: o = 1 at every p; against case 1: k2 -> 1.0625, k1 -> .0625, k0 -> .3125 (each / 4).
  EXPECT_EQ(lib.match(1, 3, h).overlap, 1);
  EXPECT_EQ(lib.match(1, 3, h).error, 1.0625 / 4);
  const CaseMatch best = lib.retrieve(h);
  EXPECT_EQ(best.case_index, 1);
  EXPECT_EQ(best.position, 2);
  EXPECT_EQ(best.overlap, 1);
  EXPECT_EQ(best.error, 0.0625 / 4);
}

TEST(CaseLibraryRetrieve, EmptyHistoryIsTheWorstMatchOnCaseZero) {
  const CaseLibrary lib = hand_library();
  const CaseMatch m = lib.retrieve(CaseHistory(3));
  EXPECT_EQ(m.case_index, 0);
  EXPECT_EQ(m.position, 1);
  EXPECT_EQ(m.overlap, 0);
  EXPECT_EQ(m.error, 1.0);
}

TEST(CaseLibraryRetrieve, TiesKeepTheLargerOverlapThenTheLowerCaseThenTheLargerPosition) {
  const In a{0.5, 0.5, 0.5, 0.5};
  const std::vector<Out> outs(2, Out{0, 0, 0, 0});
  CaseHistory full(2);
  full.push(a, {0, 0, 0, 0});
  full.push(a, {0, 0, 0, 0});
  {
    // Case 0 at p = 1 (o = 1): (.75 - .5)^2 / 4 = .015625.
    // Case 1 at p = 2 (o = 2): (.0625 + .0625) / 8 = .015625, the same error over more samples.
    const CaseLibrary lib(settings_of(2), {make_case({{0.75, 0.5, 0.5, 0.5}, {0, 0, 0, 0}}, outs),
                                           make_case({{0.25, 0.5, 0.5, 0.5}, {0.5, 0.5, 0.5, 0.75}}, outs)});
    ASSERT_EQ(lib.match(0, 1, full).error, 0.015625);
    ASSERT_EQ(lib.match(1, 2, full).error, 0.015625);
    ASSERT_EQ(lib.match(1, 1, full).error, 0.015625);  // case 1 at p = 1 ties too, with o = 1
    const CaseMatch m = lib.retrieve(full);
    EXPECT_EQ(m.case_index, 1);
    EXPECT_EQ(m.position, 2);
    EXPECT_EQ(m.overlap, 2);
  }
  CaseHistory one(2);
  one.push(a, {0, 0, 0, 0});
  const In b{0, 0, 0, 0};
  {
    // One sample, so o = 1 everywhere. Case 0 matches exactly at p = 1 only, case 1 at p = 1 and 2:
    // equal errors and overlaps, so the lower case wins although case 1 also matches at p = 2.
    const CaseLibrary lib(settings_of(2), {make_case({a, b}, outs), make_case({a, a}, outs)});
    const CaseMatch m = lib.retrieve(one);
    EXPECT_EQ(m.case_index, 0);
    EXPECT_EQ(m.position, 1);
    EXPECT_EQ(m.error, 0.0);
  }
  {
    // Within a case, equal errors and overlaps: the larger p, the first in the sweep.
    const CaseLibrary lib(settings_of(2), {make_case({b, b}, outs), make_case({a, a}, outs)});
    const CaseMatch m = lib.retrieve(one);
    EXPECT_EQ(m.case_index, 1);
    EXPECT_EQ(m.position, 2);
    EXPECT_EQ(m.overlap, 1);
  }
}

TEST(CaseLibraryRetrieve, RejectsAHistoryOfAnotherLength) {
  const CaseLibrary lib = hand_library();
  EXPECT_THROW(lib.retrieve(CaseHistory(4)), ParameterError);
  EXPECT_THROW(lib.match(2, 1, hand_history()), ParameterError);
  EXPECT_THROW(lib.match(0, 4, hand_history()), ParameterError);
  EXPECT_THROW(lib.match(0, 0, hand_history()), ParameterError);
}

// The naive search: score every (case, alignment) and take the least by (error, -overlap, case, -p).
CaseMatch naive_retrieve(const std::vector<Case>& cases, int length, const CaseHistory& env) {
  if (env.size() == 0) return {0, 1, 0, 1.0};
  std::vector<CaseMatch> all;
  for (int j = 0; j < static_cast<int>(cases.size()); ++j) {
    for (int p = 1; p <= length; ++p) {
      const int o = std::min(env.size(), p);
      double sum = 0.0;
      for (int i = 0; i < o; ++i) {
        for (int x = 0; x < 4; ++x) {
          const double d = env.input(env.size() - 1 - i)[x] - cases[j].inputs[p - 1 - i][x];
          sum += d * d;
        }
      }
      all.push_back({j, p, o, sum / (4.0 * o)});
    }
  }
  return *std::min_element(all.begin(), all.end(), [](const CaseMatch& u, const CaseMatch& v) {
    return std::make_tuple(u.error, -u.overlap, u.case_index, -u.position) <
           std::make_tuple(v.error, -v.overlap, v.case_index, -v.position);
  });
}

TEST(CaseLibraryRetrieve, IsExhaustiveOnRandomLibraries) {
  core::Rng rng(2026);
  int ties = 0;
  for (int trial = 0; trial < 600; ++trial) {
    const int length = 1 + static_cast<int>(rng.uniform_index(8));
    const int max_cases = 1 + static_cast<int>(rng.uniform_index(6));
    // A third of the trials draw from [0, 1), a third from {0, .25, .5, .75, 1} and a third from
    // {0, 1}: on the coarse grids equal errors are common.
    const int grid = trial % 3;
    const auto value = [&] {
      if (grid == 0) return rng.uniform01();
      return grid == 1 ? 0.25 * static_cast<double>(rng.uniform_index(5)) : static_cast<double>(rng.uniform_index(2));
    };
    std::vector<Case> cases(1 + rng.uniform_index(static_cast<std::uint64_t>(max_cases)));
    for (Case& c : cases) {
      c.inputs.resize(length);
      c.outputs.resize(length);
      for (In& v : c.inputs) std::generate(v.begin(), v.end(), value);
      for (Out& v : c.outputs) std::generate(v.begin(), v.end(), value);
    }
    CaseHistory env(length);
    const int pushes = static_cast<int>(rng.uniform_index(static_cast<std::uint64_t>(2 * length + 1)));
    for (int t = 0; t < pushes; ++t) env.push({value(), value(), value(), value()}, {value(), value(), value(), value()});
    const CaseLibrary lib(settings_of(length, max_cases), cases);
    const CaseMatch got = lib.retrieve(env);
    const CaseMatch want = naive_retrieve(cases, length, env);
    EXPECT_EQ(got.case_index, want.case_index) << "trial " << trial;
    EXPECT_EQ(got.position, want.position) << "trial " << trial;
    EXPECT_EQ(got.overlap, want.overlap) << "trial " << trial;
    EXPECT_DOUBLE_EQ(got.error, want.error) << "trial " << trial;
    int best_count = 0;  // how often the rules had to break a tie
    for (int j = 0; j < lib.size(); ++j) {
      for (int p = 1; p <= length && env.size() > 0; ++p) best_count += lib.match(j, p, env).error == want.error;
    }
    ties += best_count > 1;
  }
  EXPECT_GT(ties, 50);  // the coarse trials did exercise the tie rules
}

}  // namespace
}  // namespace amp::learn
