#include "amp/learn/case_library.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "amp/core/error.hpp"
#include "amp/core/rng.hpp"
#include "learn/case_fixture.hpp"

namespace amp::learn {
namespace {

using namespace case_test;  // NOLINT: the shared fixture

// ---- Settings and construction ----

TEST(CaseSettings, DefaultsAreThePapersAndValid) {
  const CaseSettings s;
  EXPECT_EQ(s.max_cases, 10);
  EXPECT_EQ(s.case_length, 4);
  EXPECT_EQ(s.learning_rate, 0.5);
  EXPECT_EQ(s.new_case_threshold, 0.1);
  EXPECT_NO_THROW(s.validate());
}

TEST(CaseSettings, ValidationNamesTheSettingOnOneLine) {
  const auto expect_error = [](CaseSettings s, const std::string& name) {
    try {
      s.validate();
      ADD_FAILURE() << name << ": no error";
    } catch (const ParameterError& e) {
      const std::string msg = e.what();
      EXPECT_NE(msg.find("'" + name + "'"), std::string::npos) << msg;
      EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
    }
  };
  CaseSettings s;
  s.max_cases = 0;
  expect_error(s, "max_cases");
  s = {};
  s.case_length = 0;
  expect_error(s, "case_length");
  for (double lr : {0.0, -0.5, 1.5, std::nan("")}) {
    s = {};
    s.learning_rate = lr;
    expect_error(s, "learning_rate");
  }
  for (double t : {1.0, -0.1, 2.0}) {
    s = {};
    s.new_case_threshold = t;
    expect_error(s, "new_case_threshold");
  }
  s = {};
  s.learning_rate = 1.0;        // closed end
  s.new_case_threshold = 0.0;   // closed end
  EXPECT_NO_THROW(s.validate());
  s.max_cases = 0;
  EXPECT_THROW(CaseLibrary{s}, ParameterError);  // the constructor validates
}

TEST(CaseLibrary, StartsWithOneGenericCase) {
  const CaseLibrary lib(settings_of(5, 3));
  ASSERT_EQ(lib.size(), 1);
  const Case& c = lib.at(0);
  ASSERT_EQ(c.inputs.size(), 5u);
  ASSERT_EQ(c.outputs.size(), 5u);
  for (int k = 0; k < 5; ++k) {
    expect_array_near(c.inputs[k], {0.5, 0.5, 0.5, 0.5}, "input");
    expect_array_near(c.outputs[k], {0.5, 0.5, 0.5, 0.5}, "output");
  }
  EXPECT_EQ(c.uses, 0);
  EXPECT_EQ(c.mean_error, 0.0);
  EXPECT_EQ(lib.cases().capacity(), 3u);  // max_cases reserved
}

TEST(CaseLibrary, RestoringChecksTheCases) {
  const CaseSettings s = settings_of(2, 2);
  const Case ok = make_case({{0, 0, 0, 0}, {1, 1, 1, 1}}, {{0, 0, 0, 0}, {1, 1, 1, 1}});
  EXPECT_NO_THROW(CaseLibrary(s, {ok, ok}));
  EXPECT_THROW(CaseLibrary(s, {}), ParameterError);
  EXPECT_THROW(CaseLibrary(s, {ok, ok, ok}), ParameterError);                                  // > max_cases
  EXPECT_THROW(CaseLibrary(s, {make_case({{0, 0, 0, 0}}, {{0, 0, 0, 0}})}), ParameterError);  // short
  EXPECT_THROW(CaseLibrary(s, {make_case({{0, 0, 0, 0}, {1, 1, 2, 1}}, ok.outputs)}), ParameterError);
  EXPECT_THROW(CaseLibrary(s, {make_case(ok.inputs, ok.outputs, -1)}), ParameterError);
  EXPECT_THROW(CaseLibrary(s, {make_case(ok.inputs, ok.outputs, 1, 1.5)}), ParameterError);
}

// ---- Adapt ----

TEST(CaseLibraryAdapt, PredictsTheSampleAfterTheAlignmentPlusBoundedExploration) {
  const CaseLibrary lib = hand_library();
  const double error = 0.0625;  // RMS difference .25: the exploration's half-width
  for (int p = 1; p <= 3; ++p) {
    const Out& prediction = kCase1Outputs[std::min(p, 2)];  // p = 1 -> k1, p = 2 -> k2, p = 3 -> k2 (the last)
    for (std::uint64_t seed : {1u, 7u, 99u}) {
      core::Rng rng(seed), twin(seed);
      const Out got = lib.adapt({1, p, std::min(3, p), error}, rng);
      for (int x = 0; x < 4; ++x) {
        const double u = twin.uniform(-1.0, 1.0);  // one draw per output, in order
        EXPECT_EQ(got[x], std::clamp(prediction[x] + 0.25 * u, 0.0, 1.0)) << "p " << p << " x " << x;
      }
      EXPECT_EQ(rng.next_u64(), twin.next_u64());  // exactly four draws
    }
  }
  // An exact match installs the prediction as it is (and still draws four numbers).
  core::Rng rng(3), twin(3);
  EXPECT_EQ(lib.adapt({1, 1, 1, 0.0}, rng), kCase1Outputs[1]);
  for (int x = 0; x < 4; ++x) twin.uniform01();
  EXPECT_EQ(rng.next_u64(), twin.next_u64());
}

TEST(CaseLibraryAdapt, ExplorationStaysWithinTheRmsErrorAndTheUnitInterval) {
  const CaseLibrary lib = hand_library();  // case 0's outputs are .5 everywhere
  core::Rng rng(11);
  double widest = 0.0;
  for (int t = 0; t < 2000; ++t) {
    for (double y : lib.adapt({0, 3, 3, 0.0625}, rng)) {
      EXPECT_LE(std::abs(y - 0.5), 0.25);
      widest = std::max(widest, std::abs(y - 0.5));
    }
    for (double y : lib.adapt({1, 2, 2, 1.0}, rng)) {  // prediction 1 with half-width 1: clamped
      EXPECT_GE(y, 0.0);
      EXPECT_LE(y, 1.0);
    }
  }
  EXPECT_GT(widest, 0.24);  // and it does explore up to the bound
  EXPECT_THROW(lib.adapt({2, 1, 1, 0.0}, rng), ParameterError);
}

// ---- Learn ----

TEST(CaseLibraryLearn, RelativeSimilarityIsPastMeanErrorOverThisError) {
  const CaseSettings s = settings_of(3);
  const Case fresh = make_case({{0, 0, 0, 0}, {0, 0, 0, 0}, {0, 0, 0, 0}}, kCase1Outputs);
  Case used = fresh;
  used.uses = 3;
  used.mean_error = 0.02;
  Case exact = fresh;
  exact.uses = 2;  // always matched exactly
  const CaseLibrary lib(s, {fresh, used, exact});
  EXPECT_EQ(lib.relative_similarity({0, 3, 3, 0.5}), 1.0);  // first use
  EXPECT_NEAR(lib.relative_similarity({1, 3, 3, 0.04}), 0.5, kTol);
  EXPECT_NEAR(lib.relative_similarity({1, 3, 3, 0.01}), 2.0, kTol);
  EXPECT_EQ(lib.relative_similarity({2, 3, 3, 0.0}), 1.0);  // exact again: as good as before, not 0
}

TEST(CaseLibraryLearn, ReinforcementMovesTheAlignedPartWithOverlapAttenuation) {
  CaseLibrary lib = hand_library();
  const CaseHistory h = hand_history();
  const CaseMatch m = lib.match(1, 3, h);  // full overlap: weights .5, .5 * 2/3, .5 * 1/3
  ASSERT_EQ(lib.learn(m, h), Learned::kReinforced);  // first use: relative similarity 1
  const Case& c = lib.at(1);
  // k2 (newest, w = 1/2): inputs (0, 0) -> h2 (1, .25); outputs 1 -> .5.
  expect_array_near(c.inputs[2], {0.5, 0.125, 0, 0}, "k2 inputs");
  expect_array_near(c.outputs[2], {0.75, 0.75, 0.75, 0.75}, "k2 outputs");
  // k1 (w = 1/3): inputs (1, .5) -> h1 (.5, .5); outputs (.25, .75, 0, 1) -> 1.
  expect_array_near(c.inputs[1], {1 - 0.5 / 3, 0.5, 0, 0}, "k1 inputs");
  expect_array_near(c.outputs[1], {0.25 + 0.75 / 3, 0.75 + 0.25 / 3, 1.0 / 3, 1}, "k1 outputs");
  // k0 (oldest, w = 1/6): inputs (.5, .5) -> h0 (0, .5); outputs .5 -> 0.
  expect_array_near(c.inputs[0], {0.5 - 0.5 / 6, 0.5, 0, 0}, "k0 inputs");
  expect_array_near(c.outputs[0], {0.5 - 0.5 / 6, 0.5 - 0.5 / 6, 0.5 - 0.5 / 6, 0.5 - 0.5 / 6}, "k0 outputs");
  EXPECT_EQ(c.uses, 1);
  EXPECT_EQ(c.mean_error, m.error);
  expect_array_near(lib.at(0).inputs[0], {0.5, 0.5, 0, 0}, "case 0 untouched");
  EXPECT_EQ(lib.at(0).uses, 0);
}

// Reward weighting (an AMP addition): each aligned output sample moves by the overlap weight times
// the history sample's reward; inputs move as before.
TEST(CaseLibraryLearn, RewardWeightingScalesOnlyTheOutputs) {
  for (const bool weighted : {true, false}) {
    CaseSettings s = hand_library().settings();
    s.reward_weighted = weighted;
    CaseLibrary lib(s, hand_library().cases());
    CaseHistory h(3);
    h.push({0, 0.5, 0, 0}, kHistoryOutputs[0], 1.0);
    h.push({0.5, 0.5, 0, 0}, kHistoryOutputs[1], 0.5);
    h.push({1, 0.25, 0, 0}, kHistoryOutputs[2], 0.0);
    EXPECT_EQ(h.reward(1), 0.5);
    ASSERT_EQ(lib.learn(lib.match(1, 3, h), h), Learned::kReinforced);
    const Case& c = lib.at(1);
    expect_array_near(c.inputs[2], {0.5, 0.125, 0, 0}, "k2 inputs");
    expect_array_near(c.inputs[1], {1 - 0.5 / 3, 0.5, 0, 0}, "k1 inputs");
    if (weighted) {
      expect_array_near(c.outputs[2], {1, 1, 1, 1}, "k2 outputs (reward 0)");
      // k1: w = 1/3 x reward 1/2; outputs (.25, .75, 0, 1) -> 1.
      expect_array_near(c.outputs[1], {0.25 + 0.75 / 6, 0.75 + 0.25 / 6, 1.0 / 6, 1}, "k1 outputs");
    } else {
      expect_array_near(c.outputs[2], {0.75, 0.75, 0.75, 0.75}, "k2 outputs (the paper's rule)");
      expect_array_near(c.outputs[1], {0.25 + 0.75 / 3, 0.75 + 0.25 / 3, 1.0 / 3, 1}, "k1 outputs");
    }
    // k0: w = 1/6 x reward 1, either way.
    expect_array_near(c.outputs[0], {0.5 - 0.5 / 6, 0.5 - 0.5 / 6, 0.5 - 0.5 / 6, 0.5 - 0.5 / 6}, "k0 outputs");
  }
  CaseHistory h(2);
  EXPECT_THROW(h.push({0, 0, 0, 0}, {0, 0, 0, 0}, 1.5), ParameterError);
  EXPECT_THROW(h.push({0, 0, 0, 0}, {0, 0, 0, 0}, -0.1), ParameterError);
  EXPECT_EQ(h.size(), 0);
}

// Outcome credit (an AMP addition): with outcome_rate > 0 the interval's reinforcement moves the
// inputs only, and shift_outputs moves one output sample toward (or away from) a point, clamped.
TEST(CaseLibraryLearn, WithOutcomeCreditReinforcementLeavesTheOutputs) {
  CaseSettings s = hand_library().settings();
  s.outcome_rate = 0.5;
  CaseLibrary lib(s, hand_library().cases());
  const CaseHistory h = hand_history();
  ASSERT_EQ(lib.learn(lib.match(1, 3, h), h), Learned::kReinforced);
  expect_array_near(lib.at(1).inputs[2], {0.5, 0.125, 0, 0}, "k2 inputs move as before");
  for (int k = 0; k < 3; ++k) expect_array_near(lib.at(1).outputs[k], kCase1Outputs[k], "outputs untouched");
  // Case 1, sample 1: (.25, .75, 0, 1) toward (1, .25, .5, 1) by 0.4: (.55, .55, .2, 1).
  lib.shift_outputs(1, 1, {1, 0.25, 0.5, 1}, 0.4);
  expect_array_near(lib.at(1).outputs[1], {0.55, 0.55, 0.2, 1}, "toward");
  // Away from (1, 1, 0, 0) by 0.5: (.55 - .225, .55 - .225, .2 + .1, 1 + .5 -> 1).
  lib.shift_outputs(1, 1, {1, 1, 0, 0}, -0.5);
  expect_array_near(lib.at(1).outputs[1], {0.325, 0.325, 0.3, 1}, "away, clamped");
  EXPECT_THROW(lib.shift_outputs(2, 0, {0, 0, 0, 0}, 0.1), ParameterError);
  EXPECT_THROW(lib.shift_outputs(0, 3, {0, 0, 0, 0}, 0.1), ParameterError);
}

TEST(CaseLibraryAdapt, ALeastSpreadWidensAnExactMatch) {
  const CaseLibrary lib = hand_library();
  core::Rng rng(21), twin(21);
  const Out got = lib.adapt({1, 1, 1, 0.0}, rng, 0.3);  // sqrt(0) < .3: the spread is .3
  for (int x = 0; x < 4; ++x) EXPECT_EQ(got[x], std::clamp(kCase1Outputs[1][x] + 0.3 * twin.uniform(-1.0, 1.0), 0.0, 1.0));
  core::Rng a(2), b(2);
  EXPECT_EQ(lib.adapt({1, 1, 1, 0.0625}, a, 0.1), lib.adapt({1, 1, 1, 0.0625}, b));  // .25 > .1: unchanged
}

TEST(CaseLibraryLearn, PartialOverlapLeavesThePredictionAlone) {
  CaseLibrary lib = hand_library();
  const CaseHistory h = hand_history();
  const CaseMatch m = lib.retrieve(h);  // case 1, p = 2, o = 2: weights .5 and .25
  ASSERT_EQ(m.position, 2);
  ASSERT_EQ(lib.learn(m, h), Learned::kReinforced);
  const Case& c = lib.at(1);
  expect_array_near(c.inputs[2], {0, 0, 0, 0}, "k2 inputs");  // the prediction, not aligned
  expect_array_near(c.outputs[2], {1, 1, 1, 1}, "k2 outputs");
  // k1 <- h2 with w = 1/2: inputs (1, .5) -> (1, .25); outputs (.25, .75, 0, 1) -> .5.
  expect_array_near(c.inputs[1], {1, 0.375, 0, 0}, "k1 inputs");
  expect_array_near(c.outputs[1], {0.375, 0.625, 0.25, 0.75}, "k1 outputs");
  // k0 <- h1 with w = 1/4: inputs already equal; outputs .5 -> 1.
  expect_array_near(c.inputs[0], {0.5, 0.5, 0, 0}, "k0 inputs");
  expect_array_near(c.outputs[0], {0.625, 0.625, 0.625, 0.625}, "k0 outputs");
}

TEST(CaseLibraryLearn, AWorseButNotVeryBadMatchKeepsTheCase) {
  const CaseHistory h = hand_history();
  Case c0 = hand_library().at(0);
  c0.uses = 4;
  c0.mean_error = 0.03;  // this use: E(0, 3) = .046875, relative similarity .64
  CaseLibrary lib(settings_of(3), {c0});
  const CaseMatch m = lib.match(0, 3, h);
  ASSERT_NEAR(lib.relative_similarity(m), 0.03 / 0.046875, kTol);
  EXPECT_EQ(lib.learn(m, h), Learned::kKept);
  EXPECT_EQ(lib.at(0).inputs, c0.inputs);
  EXPECT_EQ(lib.at(0).outputs, c0.outputs);
  EXPECT_EQ(lib.at(0).uses, 5);
  EXPECT_NEAR(lib.at(0).mean_error, (4 * 0.03 + 0.046875) / 5, kTol);
  EXPECT_EQ(lib.size(), 1);
}

TEST(CaseLibraryLearn, AVeryBadMatchCreatesACaseFromTheHistory) {
  const CaseHistory h = hand_history();
  Case c0 = hand_library().at(0);
  c0.uses = 2;
  c0.mean_error = 0.004;  // this use: E(0, 3) = .046875, relative similarity .085 < .1
  CaseLibrary lib(settings_of(3, 2), {c0});
  const CaseMatch m = lib.match(0, 3, h);
  EXPECT_EQ(lib.learn(m, h), Learned::kCreated);
  ASSERT_EQ(lib.size(), 2);
  const Case& fresh = lib.at(1);
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(fresh.inputs[i], h.input(i));
    EXPECT_EQ(fresh.outputs[i], h.output(i));
  }
  EXPECT_EQ(fresh.uses, 0);  // the use is the matched case's
  EXPECT_EQ(fresh.mean_error, 0.0);
  EXPECT_EQ(lib.at(0).inputs, c0.inputs);  // the matched case is not moved
  EXPECT_EQ(lib.at(0).uses, 3);
  EXPECT_NEAR(lib.at(0).mean_error, (2 * 0.004 + 0.046875) / 3, kTol);
  EXPECT_EQ(lib.cases().capacity(), 2u);  // reserved: no reallocation

  // The library is now full: the same very bad match changes nothing but the statistics.
  CaseLibrary full(settings_of(3, 1), {c0});
  EXPECT_EQ(full.learn(m, h), Learned::kFull);
  EXPECT_EQ(full.size(), 1);
  EXPECT_EQ(full.at(0).inputs, c0.inputs);
  EXPECT_EQ(full.at(0).outputs, c0.outputs);
  EXPECT_EQ(full.at(0).uses, 3);
}

TEST(CaseLibraryLearn, NoCaseFromAHistoryThatIsNotFull) {
  Case c0 = hand_library().at(0);
  c0.uses = 2;
  c0.mean_error = 0.001;
  CaseLibrary lib(settings_of(3), {c0});
  CaseHistory h(3);
  h.push({1, 1, 1, 1}, {0, 0, 0, 0});
  h.push({1, 1, 1, 1}, {0, 0, 0, 0});
  const CaseMatch m = lib.retrieve(h);
  ASSERT_LT(lib.relative_similarity(m), 0.1);
  EXPECT_EQ(lib.learn(m, h), Learned::kKept);
  EXPECT_EQ(lib.size(), 1);
  EXPECT_EQ(lib.at(0).uses, 3);
}

TEST(CaseLibraryLearn, RejectsAMatchThatDoesNotFit) {
  CaseLibrary lib = hand_library();
  const CaseHistory h = hand_history();
  EXPECT_THROW(lib.learn({2, 3, 3, 0.1}, h), ParameterError);  // no case 2
  EXPECT_THROW(lib.learn({0, 3, 2, 0.1}, h), ParameterError);  // overlap not min(size, p)
  EXPECT_THROW(lib.learn({0, 3, 3, 0.1}, CaseHistory(4)), ParameterError);
  EXPECT_EQ(lib.at(0).uses, 0);
}

TEST(CaseLibraryLearn, ACycleNeverGrowsTheCasesStorage) {
  // Retrieve, adapt, learn on a drifting history: the library's capacity never changes.
  CaseSettings s = settings_of(4, 3);
  CaseLibrary lib(s);
  const auto capacity = lib.cases().capacity();
  CaseHistory h(4);
  core::Rng rng(5);
  Out outputs{0.5, 0.5, 0.5, 0.5};
  int created = 0;
  for (int t = 0; t < 300; ++t) {
    const double phase = (t / 50) % 2 == 0 ? 0.1 : 0.9;  // two regimes
    h.push({phase, phase, rng.uniform(0, 0.1), rng.uniform(0, 0.1)}, outputs);
    const CaseMatch m = lib.retrieve(h);
    outputs = lib.adapt(m, rng);
    created += lib.learn(m, h) == Learned::kCreated;
    ASSERT_EQ(lib.cases().capacity(), capacity);
  }
  EXPECT_GE(created, 1);
  EXPECT_LE(lib.size(), 3);
}

}  // namespace
}  // namespace amp::learn
