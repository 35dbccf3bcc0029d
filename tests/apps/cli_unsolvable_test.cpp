// Unsolvable problems through `amp plan`: exit code 2 at the node or time limit, one stderr line.
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "support/cli_errors_fixture.hpp"

namespace {

namespace fs = std::filesystem;
using namespace amp::test;  // CliErrors, run helpers, kData, kExit*
using ::testing::HasSubstr;
using ::testing::StartsWith;

// ---- unsolvable problems end at their limit with exit code 2

TEST_F(CliErrors, SealedGoalStopsAtNodeLimit) {
  const RunResult r = plan(data("sealed.yaml"), "--node-limit 300");
  EXPECT_EQ(r.exit_code, kExitNotSolved) << r.err;
  EXPECT_THAT(r.out, testing::ContainsRegex("status +node_limit"));
  EXPECT_THAT(r.out, testing::ContainsRegex("nodes +300\n"));
  const std::vector<std::string> lines = lines_of(r.err);
  ASSERT_EQ(lines.size(), 1u) << r.err;
  EXPECT_THAT(lines[0], StartsWith("amp: no solution"));
  EXPECT_THAT(lines[0], HasSubstr("node_limit"));
  EXPECT_FALSE(fs::exists(dir_ / "out.path"));  // no path to write
}

TEST_F(CliErrors, SealedGoalStopsAtTimeLimit) {
  const RunResult r = run("plan " + data("sealed.yaml") + " --json --time-limit 0.2 --node-limit 1000000000");
  EXPECT_EQ(r.exit_code, kExitNotSolved) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j.at("status"), "timeout");
  const std::vector<std::string> lines = lines_of(r.err);
  ASSERT_EQ(lines.size(), 1u) << r.err;
  EXPECT_THAT(lines[0], StartsWith("amp: no solution"));
  EXPECT_THAT(lines[0], HasSubstr("timeout"));
}

}  // namespace
