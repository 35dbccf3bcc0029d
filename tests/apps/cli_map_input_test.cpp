// A ROS map_server YAML given straight to `amp plan`, `amp explore` and `amp navigate`, with the
// query on the command line: it plans like the problem file that names the same map, and a missing
// flag is one line that names it.
#include <filesystem>
#include <fstream>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "support/cli_errors_fixture.hpp"

namespace {

using namespace amp::test;
using ::testing::HasSubstr;

// The office map as a problem file would use it (problems/office-map.yaml: disc of 0.25, start
// (1, 1), goal (9, 6.5)), and as the map alone with the same query.
TEST_F(CliErrors, AMapWithStartAndGoalPlansAsItsProblemFileDoes) {
  const RunResult file = run("plan " + bundled("office-map.yaml") + " --seed 3 --json");
  const RunResult map = run("plan " + bundled("maps/office.yaml") + " --start 1 1 --goal 9 6.5 --radius 0.25 --seed 3 --json");
  ASSERT_EQ(file.exit_code, 0) << file.err;
  ASSERT_EQ(map.exit_code, 0) << map.err;
  nlohmann::json a = nlohmann::json::parse(file.out), b = nlohmann::json::parse(map.out);
  EXPECT_EQ(b.at("status"), "solved");
  for (const char* key : {"path_length", "nodes", "edges", "cd_calls"}) EXPECT_EQ(a.at(key), b.at(key)) << key;
  EXPECT_EQ(b.at("problem"), "office");
}

TEST_F(CliErrors, AMapWithoutTheQueryNamesTheMissingFlag) {
  expect_input_error(plan(bundled("maps/office.yaml")), {"--start", "map_server", "--start X Y"});
  expect_input_error(plan(bundled("maps/office.yaml"), "--start 1 1"), {"--goal", "--goal X Y"});
  expect_input_error(run("navigate " + bundled("maps/lab.yaml") + " --goal 4 5"), {"--start"});
  expect_input_error(run("explore " + bundled("maps/office.yaml") + " --steps 100"), {"--start"});
}

TEST_F(CliErrors, TheQueryIsCheckedOnTheMap) {
  expect_input_error(plan(bundled("maps/office.yaml"), "--start 1 1 --goal 8 6"), {"office.yaml", "goal", "collision"});
  expect_input_error(plan(bundled("maps/office.yaml"), "--start 1 1 --goal 9 6.5 --radius 0"), {"--radius"});
  expect_input_error(plan(bundled("maps/office.yaml"), "--start 1 --goal 9 6.5"), {"--start"});
}

TEST_F(CliErrors, QueryFlagsAreRefusedWithAProblemFile) {
  expect_input_error(plan(bundled("walls.yaml"), "--start 1 1"), {"--start", "walls.yaml", "its own"});
  expect_input_error(plan(bundled("walls.yaml"), "--radius 0.3"), {"--radius"});
}

TEST_F(CliErrors, ExploreAndNavigateTakeAMap) {
  const RunResult e = run("explore " + bundled("maps/office.yaml") + " --start 1 1 --steps 3000 --queries 1 --json");
  ASSERT_EQ(e.exit_code, 0) << e.err;
  EXPECT_EQ(nlohmann::json::parse(e.out).at("steps"), 3000);
  const RunResult n = run("navigate " + bundled("maps/lab.yaml") + " --start 1 1 --goal 4 5 --radius 0.27 --runs 1 --json");
  ASSERT_EQ(n.exit_code, 0) << n.err;
  EXPECT_EQ(nlohmann::json::parse(n.out).at("runs"), 1);
}

}  // namespace
