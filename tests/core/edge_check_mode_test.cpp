// edge_check_mode.cpp: the problem field `edge_check`, by name and back.
#include "amp/core/edge_check_mode.hpp"

#include <string>

#include <gtest/gtest.h>

#include "amp/core/error.hpp"

namespace amp::core {
namespace {

TEST(EdgeCheckMode, ParsesBothNamesAndPrintsThemBack) {
  EXPECT_EQ(parse_edge_check_mode("discrete"), EdgeCheckMode::kDiscrete);
  EXPECT_EQ(parse_edge_check_mode("certified"), EdgeCheckMode::kCertified);
  for (const EdgeCheckMode m : {EdgeCheckMode::kDiscrete, EdgeCheckMode::kCertified}) {
    EXPECT_EQ(parse_edge_check_mode(to_string(m)), m);
  }
  EXPECT_STREQ(to_string(EdgeCheckMode::kDiscrete), "discrete");
  EXPECT_STREQ(to_string(EdgeCheckMode::kCertified), "certified");
}

TEST(EdgeCheckMode, AnyOtherTextIsAOneLineParameterError) {
  for (const std::string bad : {"", "Discrete", "certify", "discrete ", "continuous"}) {
    try {
      parse_edge_check_mode(bad);
      ADD_FAILURE() << "'" << bad << "' was accepted";
    } catch (const ParameterError& e) {
      EXPECT_EQ(std::string(e.what()), "expected 'certified' or 'discrete', got '" + bad + "'");
    }
  }
}

}  // namespace
}  // namespace amp::core
