// learn::CaseHistory, the ring of recent samples SINS matches its cases against (declared in
// case_library.hpp beside the library).
#include <algorithm>
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "amp/core/error.hpp"
#include "amp/learn/case_library.hpp"

namespace amp::learn {
namespace {

TEST(CaseHistory, KeepsTheLastSamplesOldestFirst) {
  CaseHistory h(3);
  EXPECT_EQ(h.capacity(), 3);
  EXPECT_EQ(h.size(), 0);
  for (int t = 0; t < 5; ++t) {
    const double v = t / 8.0;
    h.push({v, v, v, v}, {1 - v, 1 - v, 1 - v, 1 - v});
    EXPECT_EQ(h.size(), std::min(t + 1, 3));
    EXPECT_EQ(h.input(h.size() - 1)[0], v);  // the newest is last
  }
  EXPECT_TRUE(h.full());
  // Samples 2, 3, 4 remain, oldest first, outputs beside their inputs.
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(h.input(i)[2], (i + 2) / 8.0);
    EXPECT_EQ(h.output(i)[3], 1 - (i + 2) / 8.0);
  }
  h.clear();
  EXPECT_EQ(h.size(), 0);
  EXPECT_FALSE(h.full());
  h.push({0.75, 0, 0, 0}, {0, 0, 0, 0});
  EXPECT_EQ(h.size(), 1);
  EXPECT_EQ(h.input(0)[0], 0.75);
}

TEST(CaseHistory, RejectsValuesOutsideTheUnitIntervalAndStaysUnchanged) {
  EXPECT_THROW(CaseHistory(0), ParameterError);
  CaseHistory h(2);
  h.push({0.25, 0.25, 0.25, 0.25}, {0, 0, 0, 0});
  EXPECT_THROW(h.push({0.5, 1.5, 0, 0}, {0, 0, 0, 0}), ParameterError);
  EXPECT_THROW(h.push({0.5, 0, 0, 0}, {0, 0, 0, std::nan("")}), ParameterError);
  try {
    h.push({0, 0, -0.25, 0}, {0, 0, 0, 0});
    FAIL();
  } catch (const ParameterError& e) {
    EXPECT_EQ(std::string(e.what()), "case_history: input 2 is -0.25, outside [0, 1]");
  }
  EXPECT_EQ(h.size(), 1);
  EXPECT_EQ(h.input(0)[0], 0.25);
}

}  // namespace
}  // namespace amp::learn
