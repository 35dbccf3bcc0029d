// `amp sins` with bad input: exit code 1, one stderr line naming the option, no output written.
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "support/cli_errors_fixture.hpp"

namespace {

namespace fs = std::filesystem;
using namespace amp::test;  // CliErrors, run helpers, kExit*
using ::testing::HasSubstr;

// Short runs: the errors are found before (or instead of) driving.
const std::string kQuick = "sins --worlds 3 --step-limit 200 -o out ";

class SinsErrors : public CliErrors {
 protected:
  void expect_sins_error(const std::string& args, std::initializer_list<std::string> expected) {
    const RunResult r = run(kQuick + args);
    expect_input_error(r, expected);
    EXPECT_EQ(r.out, "");
    EXPECT_FALSE(fs::exists(dir_ / "out")) << "an output directory was made for bad input";
  }
};

TEST_F(SinsErrors, ClutterOutsideTheOpenUnitInterval) {
  expect_sins_error("--clutter 0", {"--clutter", "(0, 1)"});
  expect_sins_error("--clutter 1", {"--clutter", "(0, 1)"});
  expect_sins_error("--clutter -0.2", {"--clutter"});
  expect_sins_error("--clutter lots", {"--clutter"});
  expect_sins_error("--param clutter=1", {"--param", "clutter"});
}

// No world can be drawn: the generator gives up after max_tries, reported at the option.
TEST_F(SinsErrors, ClutterSoHighNoWorldCanBeDrawn) {
  expect_sins_error("--clutter 0.9", {"--clutter", "0.9", "world 1"});
  expect_sins_error("--param change_at=2 --param clutter_after=0.95", {"--param clutter_after", "0.95", "world 3"});
}

TEST_F(SinsErrors, ZeroStepLimitControlIntervalOrCaseLength) {
  expect_sins_error("--step-limit 0", {"--step-limit"});
  expect_sins_error("--control-interval 0", {"--control-interval"});
  expect_sins_error("--case-length 0", {"--case-length"});
  expect_sins_error("--worlds 0", {"--worlds"});
  expect_sins_error("--param control_interval=0", {"--param", "control_interval"});
}

TEST_F(SinsErrors, MaxCasesBelowOne) {
  expect_sins_error("--max-cases 0", {"--max-cases"});
  expect_sins_error("--param max_cases=0", {"--param", "max_cases"});
}

TEST_F(SinsErrors, SchemaParametersOutsideTheirRanges) {
  expect_sins_error("--param obstacle_gain=7", {"--param", "obstacle_gain", "[0, 5]"});
  expect_sins_error("--param goal_gain=-1", {"--param", "goal_gain"});
  expect_sins_error("--param noise_persistence=0.5", {"--param", "noise_persistence"});
  expect_sins_error("--param learning_rate=0", {"--param", "learning_rate"});
  expect_sins_error("--param clutter_after=1.5", {"--param", "clutter_after"});
}

TEST_F(SinsErrors, NamedOptionOutOfItsSchemaRange) {
  expect_sins_error("--worlds 2000000", {"--worlds", "worlds"});
}

TEST_F(SinsErrors, UnknownSystem) { expect_sins_error("--system clever", {"--system", "clever"}); }

TEST_F(SinsErrors, UnknownParameterListsTheValidOnes) {
  expect_sins_error("--param nope=1", {"--param", "'nope'", "obstacle_gain", "max_cases", "change_at"});
  expect_sins_error("--param obstacle_gain", {"--param", "name=value"});
}

TEST_F(SinsErrors, OptionGivenTwice) {
  expect_sins_error("--param max_cases=5 --max-cases 4", {"--max-cases", "--param"});
}

TEST_F(SinsErrors, BadSeed) { expect_sins_error("--seed -1", {"--seed"}); }

TEST_F(SinsErrors, OutputDirectoryIsAFile) {
  { std::ofstream(dir_ / "out") << "keep"; }
  const RunResult r = run(kQuick);
  EXPECT_EQ(r.exit_code, kExitError);
  ASSERT_EQ(lines_of(r.err).size(), 1u) << r.err;
  EXPECT_THAT(r.err, HasSubstr("-o"));
  EXPECT_EQ(read_file(dir_ / "out"), "keep");
}

TEST_F(SinsErrors, OutputDirectoryWithoutItsParent) {
  const RunResult r = run("sins --worlds 3 --step-limit 200 -o missing/out");
  EXPECT_EQ(r.exit_code, kExitError);
  ASSERT_EQ(lines_of(r.err).size(), 1u) << r.err;
  EXPECT_THAT(r.err, HasSubstr("-o"));
  EXPECT_FALSE(fs::exists(dir_ / "missing"));
}

// --calibrate searches the scale and the step limit and writes nothing: options it would ignore are
// refused in one line, before any work.
TEST_F(SinsErrors, CalibrateRefusesWhatItWouldIgnore) {
  for (const char* args : {"--calibrate --scale classic", "--calibrate --system static", "--calibrate --json",
                           "--calibrate --param max_radius=3", "--calibrate --step-limit 50"}) {
    const RunResult r = run(std::string("sins ") + args);
    expect_input_error(r, {"--calibrate: ", "is not taken with it"});
    EXPECT_EQ(r.out, "") << args;
  }
  expect_input_error(run("sins --calibrate -o out"), {"--calibrate: --output"});
  EXPECT_FALSE(fs::exists(dir_ / "out"));
}

}  // namespace
