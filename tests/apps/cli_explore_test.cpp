// `amp explore` end to end on the bundled office map: the record's keys and consistency, the files
// of -o DIR, and the same seed giving the same record.
#include <algorithm>
#include <filesystem>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "support/cli_errors_fixture.hpp"
#include "support/sanitizer_build.hpp"

namespace {

namespace fs = std::filesystem;
using namespace amp::test;  // CliErrors, run helpers
using ::testing::HasSubstr;

const char* const kKeys[] = {"method",         "steps",          "clusters",          "coverage",
                             "quantisation_error", "queries",    "queries_solved",    "replans_median",
                             "replans_max",    "path_ratio_median", "explore_time_s", "query_time_median_s"};

// The record without its wall-clock times (the one part a seed does not fix).
nlohmann::json untimed(nlohmann::json j) {
  j.erase("explore_time_s");
  j.erase("query_time_median_s");
  return j;
}

TEST_F(CliErrors, ExploreOfficeRecordFilesAndSameSeed) {
  // A quarter of the exploration under the sanitizers: the same record, files and repeat, on 500 steps.
  const int steps = kSanitizerBuild ? 500 : 2000;
  const std::string args =
      "explore " + bundled("office-map.yaml") + " --steps " + std::to_string(steps) + " --queries 2 --seed 2 --json";
  const RunResult r = run(args + " -o out");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err, "");  // no progress bar when stderr is not a terminal
  const nlohmann::json j = nlohmann::json::parse(r.out);
  for (const char* key : kKeys) EXPECT_TRUE(j.contains(key)) << key;
  for (const auto& [key, value] : j.items()) EXPECT_FALSE(value.is_object() || value.is_array()) << key << " is not flat";
  EXPECT_EQ(j.at("method"), "pgcs");
  EXPECT_EQ(j.at("steps"), steps);
  EXPECT_EQ(j.at("queries"), 2);
  EXPECT_LE(j.at("queries_solved").get<int>(), 2);
  EXPECT_GE(j.at("clusters").get<int>(), 1);
  EXPECT_GE(j.at("coverage").get<double>(), 0.0);
  EXPECT_LE(j.at("coverage").get<double>(), 1.0);
  EXPECT_GE(j.at("quantisation_error").get<double>(), 0.0);
  EXPECT_LE(j.at("replans_median").get<double>(), j.at("replans_max").get<double>());

  for (const char* f : {"figure1.svg", "curves.svg", "queries.svg", "record.json"}) {
    EXPECT_TRUE(fs::is_regular_file(dir_ / "out" / f)) << f;
  }
  EXPECT_THAT(read_file(dir_ / "out" / "figure1.svg"), HasSubstr("class=\"graph-panel\""));
  const nlohmann::json record = nlohmann::json::parse(read_file(dir_ / "out" / "record.json"));
  EXPECT_EQ(record.at("query_details").size(), 2u);
  EXPECT_FALSE(record.at("curves").empty());
  nlohmann::json flat = record;  // record.json: the printed record plus the details
  for (const char* k : {"settings", "query_details", "curves"}) flat.erase(k);
  EXPECT_EQ(flat, j);

  // Same seed, same record (times aside).
  const nlohmann::json again = nlohmann::json::parse(run(args).out);
  EXPECT_EQ(untimed(again), untimed(j));
}

// A wall that closes while the robot explores: drawn over the map, and the closed prior charted.
TEST_F(CliErrors, ExploreDrawsADoorThatClosed) {
  const RunResult r = run("explore " + data("explore_door.yaml") + " --steps 3000 --queries 1 -o out");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(read_file(dir_ / "out" / "figure1.svg"), HasSubstr("class=\"appeared\""));
  const nlohmann::json record = nlohmann::json::parse(read_file(dir_ / "out" / "record.json"));
  double closed = 0.0;
  for (const auto& c : record.at("curves")) closed = std::max(closed, c.at("closed_prior").get<double>());
  EXPECT_EQ(read_file(dir_ / "out" / "curves.svg").find("closed prior") != std::string::npos, closed > 0.0);
}

}  // namespace
