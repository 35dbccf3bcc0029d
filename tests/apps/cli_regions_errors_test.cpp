// `amp regions` (UAS region identification) and its errors, and uas's clustering parameter via `amp plan`.
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

// ---- amp regions

TEST_F(CliErrors, RegionsPrintsClusterStatisticsAndDrawsThem) {
  const RunResult r = run("regions " + bundled("maze.yaml") + " --json --seed 2 -o out.svg");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j.at("training_nodes"), 200);
  EXPECT_EQ(j.at("method"), "kmeans");
  EXPECT_GT(j.at("training_cd_calls").get<long long>(), 0);
  const int c = j.at("clusters").get<int>();
  ASSERT_EQ(j.at("regions").size(), static_cast<std::size_t>(c));
  double percent = 0.0;
  for (const auto& region : j.at("regions")) {
    percent += region.at("size_percent").get<double>();
    EXPECT_LE(region.at("visibility_min").get<double>(), region.at("visibility_mean").get<double>());
    EXPECT_LE(region.at("visibility_mean").get<double>(), region.at("visibility_max").get<double>());
  }
  EXPECT_NEAR(percent, 100.0, 1e-9);
  // The maze's tunnels make one cluster of low visibility (the paper's Table 1: about 0.2).
  double lowest = 1.0;
  for (const auto& region : j.at("regions")) lowest = std::min(lowest, region.at("visibility_mean").get<double>());
  EXPECT_LT(lowest, 0.4);
  const std::string svg = read_file(dir_ / "out.svg");
  EXPECT_THAT(svg, HasSubstr("class=\"regions\""));
  // The same seed gives the same table; several sizes give a picture each.
  EXPECT_EQ(run("regions " + bundled("maze.yaml") + " --json --seed 2").out, r.out);
  const RunResult sizes = run("regions " + bundled("walls.yaml") + " --training-nodes 50 100 -o w.svg --clustering auto");
  ASSERT_EQ(sizes.exit_code, 0) << sizes.err;
  EXPECT_THAT(sizes.out, HasSubstr("<- chosen"));
  EXPECT_TRUE(fs::exists(dir_ / "w-50.svg"));
  EXPECT_TRUE(fs::exists(dir_ / "w-100.svg"));
}

TEST_F(CliErrors, RegionsUnknownClustering) {
  expect_input_error(run("regions " + data("ok.yaml") + " --clustering dbscan -o out.svg"), {"--clustering", "dbscan"});
}

TEST_F(CliErrors, RegionsTrainingNodesTooFew) {
  expect_input_error(run("regions " + data("ok.yaml") + " --training-nodes 1 -o out.svg"), {"--training-nodes"});
}

TEST_F(CliErrors, RegionsRefusesToOverwriteWithoutForce) {
  { std::ofstream(dir_ / "mine.svg") << "keep"; }
  const RunResult r = run("regions " + data("ok.yaml") + " -o mine.svg");
  EXPECT_EQ(r.exit_code, kExitError);
  EXPECT_THAT(r.err, HasSubstr("--force"));
  EXPECT_EQ(read_file(dir_ / "mine.svg"), "keep");
}

TEST_F(CliErrors, UasWithAnUnknownClusteringParam) {
  expect_input_error(plan(data("ok.yaml"), "--planner uas --param clustering=dbscan"), {"clustering", "dbscan"});
}

}  // namespace
