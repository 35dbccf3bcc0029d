// `amp plan` with bad command-line options (limits, seed, planner parameters): exit code 1 and one
// stderr line naming the option.
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "support/cli_errors_fixture.hpp"

namespace {

namespace fs = std::filesystem;
using namespace amp::test;  // CliErrors, run helpers, kData, kExit*
using ::testing::HasSubstr;
using ::testing::StartsWith;

// ---- command-line options

TEST_F(CliErrors, NegativeTimeLimit) { expect_input_error(plan(data("ok.yaml"), "--time-limit -1"), {"--time-limit"}); }

TEST_F(CliErrors, ZeroTimeLimit) { expect_input_error(plan(data("ok.yaml"), "--time-limit 0"), {"--time-limit"}); }

TEST_F(CliErrors, NanTimeLimit) {
  expect_input_error(plan(data("ok.yaml"), "--time-limit nan"), {"--time-limit", "'nan'"});
}

TEST_F(CliErrors, FractionalNodeLimit) {
  expect_input_error(plan(data("ok.yaml"), "--node-limit 1.5"), {"--node-limit", "'1.5'"});
}

TEST_F(CliErrors, NegativeSeed) { expect_input_error(plan(data("ok.yaml"), "--seed -1"), {"--seed", "'-1'"}); }

TEST_F(CliErrors, ZeroNodeLimit) { expect_input_error(plan(data("ok.yaml"), "--node-limit 0"), {"--node-limit"}); }

TEST_F(CliErrors, ParamOutOfRange) {
  expect_input_error(plan(data("ok.yaml"), "--param k=0"), {"prm", "'k'", "0 is outside [1, "});
}

TEST_F(CliErrors, ParamNotANumber) {
  expect_input_error(plan(data("ok.yaml"), "--param k=abc"), {"prm", "'k'", "'abc'"});
}

TEST_F(CliErrors, UnknownParam) {
  expect_input_error(plan(data("ok.yaml"), "--param nope=3"), {"prm", "unknown parameter 'nope'", "valid: k"});
}

TEST_F(CliErrors, SeedInCollisionIsNamed) {
  expect_input_error(plan(data("seed_in_collision.yaml"), "--planner prm-l"),
                     {"seed_in_collision.yaml", "seeds[2]", "[5, 6]", "collision"});
}

TEST_F(CliErrors, CompetenceParametersOutOfRange) {
  expect_input_error(plan(data("ok.yaml"), "--planner prm-c --param o=0.5"), {"prm-c", "'o'", "0.5 is outside"});
  expect_input_error(plan(data("ok.yaml"), "--planner prm-g --param s=0"), {"prm-g", "'s'", "0 is outside"});
  expect_input_error(plan(data("ok.yaml"), "--planner prm-l --param n=-1"), {"prm-l", "'n'", "-1 is outside"});
  expect_input_error(plan(data("ok.yaml"), "--planner prm-l --param steps=0"), {"prm-l", "'steps'", "0 is outside"});
}

TEST_F(CliErrors, ProblemGridOfZeroSteps) {
  // The problem's own planner parameter is checked like a command-line one, for the planners that take it.
  expect_input_error(plan(data("grid_steps_zero.yaml"), "--planner prm-l"), {"prm-l", "'steps'", "0 is outside"});
  EXPECT_EQ(plan(data("grid_steps_zero.yaml"), "--planner prm").exit_code, 0);
}

TEST_F(CliErrors, UnknownPlannerListsTheValidOnes) {
  expect_input_error(plan(data("ok.yaml"), "--planner nope"), {"unknown planner 'nope'", "valid: ", "prm"});
}

}  // namespace
