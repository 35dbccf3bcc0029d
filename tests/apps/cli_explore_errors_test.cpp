// `amp explore` with bad input: exit code 1, one stderr line naming the file or the option, no
// output written; a query between points that are not connected is a result (unsolvable), not an error.
#include <filesystem>
#include <fstream>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "support/cli_errors_fixture.hpp"

namespace {

namespace fs = std::filesystem;
using namespace amp::test;  // CliErrors, run helpers, kData, kExit*
using ::testing::HasSubstr;

// Short runs: the errors are found before (or without) a long exploration.
const std::string kQuick = " --steps 500 --queries 1 -o out";

class ExploreErrors : public CliErrors {
 protected:
  void expect_explore_error(const std::string& args, std::initializer_list<std::string> expected) {
    expect_input_error(run("explore " + args), expected);
    EXPECT_FALSE(fs::exists(dir_ / "out")) << "an output directory was made for bad input";
  }
};

TEST_F(ExploreErrors, QueryStartInAnObstacle) {
  expect_explore_error(data("ok.yaml") + kQuick + " --query 5 5 9 9", {"--query 1", "start", "obstacle"});
}

TEST_F(ExploreErrors, QueryTargetOutsideTheMap) {
  expect_explore_error(data("ok.yaml") + kQuick + " --query 1 1 12 9", {"--query 1", "target", "outside the map"});
}

TEST_F(ExploreErrors, QueryWithTooFewNumbers) {
  expect_explore_error(data("ok.yaml") + kQuick + " --query 1 1 9", {"--query"});
}

TEST_F(ExploreErrors, ProblemStartOutsideTheMap) {
  expect_explore_error(data("start_out_of_bounds.yaml") + kQuick, {"start_out_of_bounds.yaml", "start"});
}

TEST_F(ExploreErrors, ProblemStartInAnObstacle) {
  expect_explore_error(data("start_in_obstacle.yaml") + kQuick, {"start_in_obstacle.yaml", "start"});
}

TEST_F(ExploreErrors, MapWithNoFreeCell) {
  expect_explore_error(data("no_free.yaml") + kQuick, {"no_free.yaml"});
}

TEST_F(ExploreErrors, RobotThatIsNotADisc) {
  expect_explore_error(data("rigid_robot.yaml") + kQuick, {"rigid_robot.yaml", "disc"});
}

TEST_F(ExploreErrors, ThreeDimensionalWorld) {
  expect_explore_error(bundled("walls3d.yaml") + kQuick, {"walls3d.yaml"});
}

TEST_F(ExploreErrors, WindowBelowOne) {
  expect_explore_error(data("ok.yaml") + kQuick + " --param window=0", {"--param", "window", "0 is outside"});
}

TEST_F(ExploreErrors, MaxClustersBelowThree) {
  expect_explore_error(data("ok.yaml") + kQuick + " --max-clusters 2", {"--max-clusters"});
  expect_explore_error(data("ok.yaml") + kQuick + " --param max_clusters=2", {"--param", "max_clusters"});
}

TEST_F(ExploreErrors, InsertEveryBelowOne) {
  expect_explore_error(data("ok.yaml") + kQuick + " --param insert_every=0", {"--param", "insert_every"});
}

TEST_F(ExploreErrors, DeleteEveryBelowOne) {
  expect_explore_error(data("ok.yaml") + kQuick + " --param delete_every=0", {"--param", "delete_every"});
}

TEST_F(ExploreErrors, StepsBelowOne) {
  expect_explore_error(data("ok.yaml") + " --steps 0 -o out", {"--steps"});
}

TEST_F(ExploreErrors, UnknownParameterListsTheValidOnes) {
  expect_explore_error(data("ok.yaml") + kQuick + " --param nope=1", {"--param", "'nope'", "window"});
}

TEST_F(ExploreErrors, OptionGivenTwice) {
  expect_explore_error(data("ok.yaml") + kQuick + " --param max_clusters=50 --max-clusters 40", {"--max-clusters"});
}

TEST_F(ExploreErrors, UnknownExplorationStrategy) {
  expect_explore_error(data("ok.yaml") + kQuick + " --exploration spiral", {"--exploration", "spiral"});
}

TEST_F(ExploreErrors, RefusesToOverwriteWithoutForce) {
  fs::create_directories(dir_ / "mine");
  { std::ofstream(dir_ / "mine" / "figure1.svg") << "keep"; }
  const RunResult r = run("explore " + data("ok.yaml") + " --steps 500 --queries 1 -o mine");
  EXPECT_EQ(r.exit_code, kExitError);
  ASSERT_EQ(lines_of(r.err).size(), 1u) << r.err;
  EXPECT_THAT(r.err, HasSubstr("--force"));
  EXPECT_EQ(read_file(dir_ / "mine" / "figure1.svg"), "keep");
  EXPECT_FALSE(fs::exists(dir_ / "mine" / "record.json"));
  const RunResult forced = run("explore " + data("ok.yaml") + " --steps 500 --queries 1 -o mine --force");
  EXPECT_EQ(forced.exit_code, 0) << forced.err;
  EXPECT_NE(read_file(dir_ / "mine" / "figure1.svg"), "keep");
}

TEST_F(ExploreErrors, OutputDirectoryIsAFile) {
  { std::ofstream(dir_ / "out") << "keep"; }
  const RunResult r = run("explore " + data("ok.yaml") + kQuick);
  EXPECT_EQ(r.exit_code, kExitError);
  EXPECT_THAT(r.err, HasSubstr("-o"));
  EXPECT_EQ(read_file(dir_ / "out"), "keep");
}

// The sealed box's inside is free but not reachable from the start: the query ends unsolvable,
// the command succeeds, and queries_solved does not count it.
TEST_F(CliErrors, ExploreQueryBetweenUnconnectedPointsIsUnsolvable) {
  const RunResult r = run("explore " + data("sealed.yaml") + " --steps 2000 --query 1 1 8 8 --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j.at("queries"), 1);
  EXPECT_EQ(j.at("queries_solved"), 0);
  EXPECT_TRUE(j.at("path_ratio_median").is_null());
}

}  // namespace
