#pragma once
// Shared by the case library tests: a hand-computed library and history (learn::CaseLibrary).
#include <array>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "amp/learn/case_library.hpp"

namespace amp::learn::case_test {

inline constexpr double kTol = 1e-12;
using In = CaseInputs;
using Out = CaseOutputs;

inline CaseSettings settings_of(int length, int max_cases = 10) {
  CaseSettings s;
  s.case_length = length;
  s.max_cases = max_cases;
  return s;
}

inline Case make_case(std::vector<In> inputs, std::vector<Out> outputs, int uses = 0, double mean_error = 0.0) {
  return Case{std::move(inputs), std::move(outputs), uses, mean_error};
}

inline void expect_array_near(const std::array<double, 4>& got, const std::array<double, 4>& want, const char* what) {
  for (int x = 0; x < 4; ++x) EXPECT_NEAR(got[x], want[x], kTol) << what << " [" << x << "]";
}

// The hand-computed fixture. Case length 3; only the first two inputs vary (the others are 0 in
// cases and history alike, and add nothing to any error). Every value is a multiple of 1/16, so
// the errors below are exact in binary.
//   history inputs (oldest first): h0 = (0, .5), h1 = (.5, .5), h2 = (1, .25)
//   case 0: (.5, .5) at k = 0, 1, 2
//   case 1: k0 = (.5, .5), k1 = (1, .5), k2 = (0, 0)
inline const std::vector<Out> kCase1Outputs{{0.5, 0.5, 0.5, 0.5}, {0.25, 0.75, 0, 1}, {1, 1, 1, 1}};
inline const std::vector<Out> kHistoryOutputs{{0, 0, 0, 0}, {1, 1, 1, 1}, {0.5, 0.5, 0.5, 0.5}};

inline CaseLibrary hand_library(CaseSettings s = settings_of(3)) {
  return CaseLibrary(s, {make_case({{0.5, 0.5, 0, 0}, {0.5, 0.5, 0, 0}, {0.5, 0.5, 0, 0}},
                                   {{0.5, 0.5, 0.5, 0.5}, {0.5, 0.5, 0.5, 0.5}, {0.5, 0.5, 0.5, 0.5}}),
                         make_case({{0.5, 0.5, 0, 0}, {1, 0.5, 0, 0}, {0, 0, 0, 0}}, kCase1Outputs)});
}

inline CaseHistory hand_history() {
  CaseHistory h(3);
  h.push({0, 0.5, 0, 0}, kHistoryOutputs[0]);
  h.push({0.5, 0.5, 0, 0}, kHistoryOutputs[1]);
  h.push({1, 0.25, 0, 0}, kHistoryOutputs[2]);
  return h;
}

}  // namespace amp::learn::case_test
