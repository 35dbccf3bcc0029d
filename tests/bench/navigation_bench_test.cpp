// `amp bench` with a navigation method (pgcs) beside a planner: threads, shards + merge and resume
// give the same runs.csv and summary as one uninterrupted run; the method's metrics reach runs.csv,
// summary.json (descriptive statistics, and the tests when named as `cost:`) and results.db; a problem
// a navigator cannot take fails at load time. Skipped while no navigation method `pgcs` is registered.
#include <sqlite3.h>

#include <algorithm>
#include <atomic>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "amp/bench/bench_runner.hpp"
#include "amp/bench/merge.hpp"
#include "amp/core/error.hpp"
#include "amp/nav/navigator_catalog.hpp"
#include "support/sanitizer_build.hpp"
#include "support/source_tree.hpp"

namespace amp::bench {
namespace {

namespace fs = std::filesystem;

// Extras that measure time (explore_time_s, query_time_median_s, ...): like wall_time_s, the only
// numbers that legitimately differ between two runs of one trial.
bool is_timing(const std::string& name) { return name.size() > 2 && name.ends_with("_s"); }

// Runs per planner and pgcs's exploration steps: 2 runs of 750 steps under the sanitizers (the same
// threads, shards, merge and resume on fewer, shorter runs), 3 of 3000 otherwise.
constexpr int kRuns = test::kSanitizerBuild ? 2 : 3;
constexpr int kPgcsSteps = test::kSanitizerBuild ? 750 : 3000;
constexpr unsigned kTrials = 2 * kRuns;  // prm and pgcs

class NavigationBenchTest : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!nav::builtin_navigators().contains("pgcs")) GTEST_SKIP() << "no navigation method 'pgcs' registered yet";
    root_ = fs::temp_directory_path() / ("amp-nav-bench-" + std::to_string(::getpid()) + "-" +
                                         ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(root_);
    fs::create_directories(root_);
    const fs::path office = fs::path(AMP_SOURCE_DIR) / "problems" / "office-map.yaml";
    // A time limit that never binds, so results do not depend on the machine's load.
    std::ofstream(root_ / "exp.yaml") << "name: nav\nseed: 17\nruns: " << kRuns
                                      << "\ntime_limit: 600\nnode_limit: 20000\n"
                                      << "cost: replans\nproblems: [" << office.string() << "]\nplanners:\n"
                                      << "  - prm\n  - {name: pgcs-small, planner: pgcs, params: {steps: " << kPgcsSteps
                                      << ", queries: 3}}\n";
  }
  void TearDown() override {
    if (!root_.empty()) fs::remove_all(root_);
  }

  BenchResult run(const fs::path& out, int threads, Shard shard = {}, const std::atomic<bool>* cancel = nullptr,
                  std::function<void(const Progress&)> progress = {}, bool resume = false) {
    BenchOptions o;
    o.out_dir = out;
    o.threads = threads;
    o.shard = shard;
    o.cancel = cancel;
    o.on_progress = std::move(progress);
    o.resume = resume;
    return run_experiment(load_experiment(root_ / "exp.yaml"), o);
  }

  // runs.csv without wall_time_s and without timing extras.
  static std::string csv_without_time(const fs::path& dir) {
    std::ifstream in(dir / "runs.csv");
    std::string line, out;
    std::size_t extra_column = 0;
    for (bool header = true; std::getline(in, line); header = false) {
      std::vector<std::string> f;
      std::stringstream ss(line);
      for (std::string cell; std::getline(ss, cell, ',');) f.push_back(cell);
      if (header) extra_column = static_cast<std::size_t>(std::find(f.begin(), f.end(), "extra") - f.begin());
      if (!header && extra_column < f.size()) {
        std::string kept;
        std::stringstream items(f[extra_column]);
        for (std::string item; std::getline(items, item, ';');) {
          if (!is_timing(item.substr(0, item.find('=')))) kept += item + ";";
        }
        f[extra_column] = kept;
      }
      f.erase(f.begin() + 7);  // wall_time_s
      for (const auto& c : f) out += c + ",";
      out += "\n";
    }
    return out;
  }

  static nlohmann::json cost_summary(const fs::path& dir) {
    nlohmann::json j = nlohmann::json::parse(std::ifstream(dir / "summary.json"));
    nlohmann::json out;
    for (auto& p : j["problems"]) {
      for (auto& c : p["planners"]) {
        nlohmann::json metrics = c.value("metrics", nlohmann::json::object());
        for (auto it = metrics.begin(); it != metrics.end();) it = is_timing(it.key()) ? metrics.erase(it) : ++it;
        out.push_back({c["name"], c["cd_calls"], c["cost"], c["statuses"], metrics});
      }
      out.push_back(p["tests"]);
    }
    return out;
  }

  fs::path root_;
};

TEST_F(NavigationBenchTest, ThreadsDoNotChangeTheResultsAndMetricsReachEveryOutput) {
  const BenchResult a = run(root_ / "one", 1);
  run(root_ / "two", 2);
  EXPECT_EQ(a.written, kTrials);
  EXPECT_EQ(csv_without_time(root_ / "one"), csv_without_time(root_ / "two"));
  EXPECT_EQ(cost_summary(root_ / "one"), cost_summary(root_ / "two"));

  const nlohmann::json s = nlohmann::json::parse(std::ifstream(root_ / "one" / "summary.json"));
  const auto& problem = s["problems"][0];
  const auto& pgcs = problem["planners"][1];
  EXPECT_EQ(pgcs["planner"], "pgcs");
  ASSERT_TRUE(pgcs.contains("metrics")) << pgcs.dump();
  for (const char* m : {"replans", "queries", "queries_solved", "solved_fraction", "coverage"}) {
    EXPECT_TRUE(pgcs["metrics"].contains(m)) << m;
  }
  EXPECT_EQ(pgcs["metrics"]["queries"]["mean"], 3.0);
  EXPECT_EQ(pgcs["cost"]["metric"], "replans");
  EXPECT_EQ(pgcs["cost"]["n"], kRuns);
  // prm reports no replans: the tests say so instead of comparing a part of the runs.
  EXPECT_EQ(problem["tests"]["skipped"],
            "metric 'replans' missing in runs (" + std::to_string(kRuns) + " of 'prm')");

  // results.db: the extras are per-run properties (columns of `runs`), NULL for the planner's rows.
  sqlite3* db = nullptr;
  ASSERT_EQ(sqlite3_open_v2((root_ / "one" / "results.db").c_str(), &db, SQLITE_OPEN_READONLY, nullptr), SQLITE_OK);
  sqlite3_stmt* st = nullptr;
  ASSERT_EQ(sqlite3_prepare_v2(db, "SELECT COUNT(replans), COUNT(*) FROM runs", -1, &st, nullptr), SQLITE_OK)
      << sqlite3_errmsg(db);
  ASSERT_EQ(sqlite3_step(st), SQLITE_ROW);
  EXPECT_EQ(sqlite3_column_int(st, 0), kRuns);
  EXPECT_EQ(sqlite3_column_int(st, 1), static_cast<int>(kTrials));
  sqlite3_finalize(st);
  sqlite3_close(db);
}

TEST_F(NavigationBenchTest, MergedShardsAndAResumedRunEqualTheSingleProcessRun) {
  run(root_ / "single", 2);
  std::vector<fs::path> shards;
  for (std::size_t i = 0; i < 2; ++i) {
    shards.push_back(root_ / ("shard" + std::to_string(i)));
    run(shards.back(), 1, Shard{i, 2});
  }
  EXPECT_EQ(merge_results({shards[1], shards[0]}, root_ / "merged", false, false), kTrials);
  EXPECT_EQ(csv_without_time(root_ / "single"), csv_without_time(root_ / "merged"));
  EXPECT_EQ(cost_summary(root_ / "single"), cost_summary(root_ / "merged"));

  std::atomic<bool> cancel{false};
  const BenchResult cut = run(root_ / "resumed", 1, {}, &cancel, [&](const Progress& p) {
    // As Ctrl-C after the planner's runs and one navigation run.
    if (p.done >= static_cast<std::size_t>(kRuns) + 1) cancel = true;
  });
  EXPECT_TRUE(cut.interrupted);
  const BenchResult rest = run(root_ / "resumed", 2, {}, nullptr, {}, true);
  EXPECT_EQ(rest.written, kTrials);
  EXPECT_EQ(csv_without_time(root_ / "single"), csv_without_time(root_ / "resumed"));
  EXPECT_EQ(cost_summary(root_ / "single"), cost_summary(root_ / "resumed"));
}

TEST_F(NavigationBenchTest, AProblemANavigatorCannotTakeFailsAtLoadTime) {
  const fs::path walls = fs::path(AMP_SOURCE_DIR) / "problems" / "walls.yaml";  // an SE(2) polygon robot
  std::ofstream(root_ / "bad.yaml") << "problems: [" << walls.string() << "]\nplanners: [prm, pgcs]\n";
  try {
    load_experiment(root_ / "bad.yaml");
    FAIL() << "walls.yaml has no disc robot";
  } catch (const FileError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find((root_ / "bad.yaml").string() + ": planners[1]: problem 'Walls'"), std::string::npos) << m;
    EXPECT_EQ(m.find('\n'), std::string::npos) << m;
  }
}

}  // namespace
}  // namespace amp::bench
