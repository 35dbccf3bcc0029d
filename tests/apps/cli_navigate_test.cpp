// `amp navigate`: the record's keys, record.json, the same seed giving the same record; bad input
// ends with exit code 1 and one line naming the option or the file.
#include <filesystem>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "support/cli_errors_fixture.hpp"
#include "support/sanitizer_build.hpp"

namespace {

namespace fs = std::filesystem;
using namespace amp::test;  // CliErrors, run helpers, kData, kExit*

const char* const kKeys[] = {"method", "runs", "solved_runs", "collisions_total", "planning_time_median_s",
                             "execution_time_median_s", "distance_median", "min_clearance_min", "waypoints"};

TEST_F(CliErrors, NavigatePolicyOutOfTheLab) {
  // One run (and one DWA run for Table 2) under the sanitizers, three otherwise.
  const int runs = kSanitizerBuild ? 1 : 3;
  const std::string args =
      "navigate " + bundled("policy-lab.yaml") + " --runs " + std::to_string(runs) + " --seed 4 --json --param max_time=60";
  const RunResult r = run(args + " -o out");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  for (const char* key : kKeys) EXPECT_TRUE(j.contains(key)) << key;
  for (const auto& [key, value] : j.items()) EXPECT_FALSE(value.is_object() || value.is_array()) << key << " is not flat";
  EXPECT_EQ(j.at("method"), "policy-search");
  EXPECT_EQ(j.at("runs"), runs);
  EXPECT_EQ(j.at("solved_runs"), runs);  // the searched policy leaves the lab on the noisy robot
  EXPECT_GE(j.at("min_clearance_min").get<double>(), 0.0);  // never through a wall
  EXPECT_GE(j.at("waypoints").get<double>(), 2.0);
  EXPECT_GT(j.at("distance_median").get<double>(), 5.0);  // longer than the straight 5 m through the wall
  const nlohmann::json record = nlohmann::json::parse(read_file(dir_ / "out" / "record.json"));
  ASSERT_EQ(record.at("run_details").size(), static_cast<std::size_t>(runs));
  for (const auto& run : record.at("run_details")) EXPECT_FALSE(run.at("speeds").empty());
  // Table 2 has both methods on the same seeds; the chosen one's row is the printed record.
  ASSERT_EQ(record.at("table2").size(), 2u);
  EXPECT_EQ(record.at("table2")[0].at("method"), "policy-search");
  EXPECT_EQ(record.at("table2")[1].at("method"), "dwa");
  EXPECT_EQ(record.at("table2")[0].at("solved_runs"), j.at("solved_runs"));
  EXPECT_EQ(record.at("table2")[1].at("runs"), runs);
  // Figure 3: four phases over the map; Figure 4: one velocity line per method.
  const std::string phases = read_file(dir_ / "out" / "phases.svg");
  std::size_t panels = 0;
  for (auto at = phases.find("class=\"phase\""); at != std::string::npos; at = phases.find("class=\"phase\"", at + 1)) ++panels;
  EXPECT_EQ(panels, 4u);
  for (const char* phase : {"(a) value iteration path", "(b) projected waypoints", "(c) after policy search",
                            "(d) after insertions"}) {
    EXPECT_THAT(phases, ::testing::HasSubstr(phase));
  }
  EXPECT_THAT(phases, ::testing::HasSubstr("driven (first seed)"));  // the first run's trace, on the last panel
  EXPECT_THAT(phases, ::testing::Not(::testing::HasSubstr(">stopped<")));  // it arrived
  const std::string velocity = read_file(dir_ / "out" / "velocity.svg");
  EXPECT_THAT(velocity, ::testing::HasSubstr("policy search"));
  EXPECT_THAT(velocity, ::testing::HasSubstr("DWA"));
  // Same seed, same record (planning time aside); an existing record.json is kept without --force.
  nlohmann::json again = nlohmann::json::parse(run(args).out), first = j;
  again.erase("planning_time_median_s");
  first.erase("planning_time_median_s");
  EXPECT_EQ(again, first);
  const RunResult kept = run(args + " -o out");
  EXPECT_EQ(kept.exit_code, kExitError);
  EXPECT_THAT(kept.err, ::testing::HasSubstr("record.json"));
}

TEST_F(CliErrors, NavigatePrintsTable2ForBothMethods) {
  // A policy-search parameter is not an error for DWA, which runs beside it on the same seeds.
  const RunResult r = run("navigate " + bundled("policy-lab.yaml") + " --runs 1 --param max_time=30 --param d_approach=0.25");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(r.out, ::testing::HasSubstr("Table 2"));
  EXPECT_THAT(r.out, ::testing::ContainsRegex("policy-search +1/1"));
  EXPECT_THAT(r.out, ::testing::ContainsRegex("  dwa +[01]/1"));
}

TEST_F(CliErrors, NavigateDwaRunsOnTheSameProblem) {
  const RunResult r = run("navigate " + bundled("policy-lab.yaml") + " --method dwa --runs 1 --json --param max_time=20");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j.at("method"), "dwa");
  EXPECT_EQ(j.at("waypoints"), 0.0);
  EXPECT_LE(j.at("execution_time_median_s").get<double>(), 20.0 + 1e-9);
  EXPECT_GE(j.at("min_clearance_min").get<double>(), 0.0);
}

TEST_F(CliErrors, NavigateARectangularFootprintThroughTheLabDoor) {
  // 0.7 m x 0.54 m, checked at its heading: it lines up with the 60 cm door and never touches it.
  // DWA, which runs beside it and stalls at the door until max_time, samples 5 x 5 velocities here
  // (20 x 20 by default) so the test stays fast under the sanitizers.
  const RunResult r = run("navigate " + bundled("policy-lab.yaml") +
                          " --runs 2 --json --param footprint_length=0.7 --param max_time=40 --param v_samples=5 --param omega_samples=5");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j.at("solved_runs"), 2);
  EXPECT_EQ(j.at("collisions_total"), 0.0);
  EXPECT_GE(j.at("min_clearance_min").get<double>(), 0.0);
}

TEST_F(CliErrors, NavigateBadInput) {
  const std::string lab = bundled("policy-lab.yaml");
  expect_input_error(run("navigate " + lab + " --runs 0"), {"--runs"});
  expect_input_error(run("navigate " + lab + " --method teleport"), {"--method"});
  expect_input_error(run("navigate " + lab + " --param d_approach=0"), {"d_approach"});
  expect_input_error(run("navigate " + lab + " --param sigma_v=-1"), {"sigma_v"});
  expect_input_error(run("navigate " + lab + " --param v_max=0"), {"v_max"});
  expect_input_error(run("navigate " + lab + " --param accel=-2"), {"accel"});
  expect_input_error(run("navigate " + lab + " --param footprint_length=0.3"), {"footprint_length"});  // < 0.54 wide
  expect_input_error(run("navigate " + lab + " --param d_aproach=0.2"), {"--param", "d_aproach"});  // neither method's
  expect_input_error(run("navigate " + data("lab_wide_robot.yaml")), {"no passage wide enough for the footprint"});
  expect_input_error(run("navigate " + data("goal_in_collision.yaml")), {"goal_in_collision.yaml", "goal"});
  expect_input_error(run("navigate " + data("ok.yaml")), {"map worlds"});
  EXPECT_FALSE(fs::exists(dir_ / "out"));
}

}  // namespace
