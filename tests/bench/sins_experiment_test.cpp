// A small SINS experiment through `amp bench`'s runner: the static, random and sins methods run their
// sequences, and runs.csv and summary.json carry the estimators as extras (solved_fraction the cost).
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "amp/bench/bench_runner.hpp"
#include "amp/bench/runs_csv.hpp"
#include "support/source_tree.hpp"

namespace amp::bench {
namespace {

namespace fs = std::filesystem;

TEST(SinsExperiment, RunsInBenchWithTheEstimatorsAsExtras) {
  const fs::path root = fs::temp_directory_path() / ("amp-sins-experiment-" + std::to_string(::getpid()));
  fs::remove_all(root);
  fs::create_directories(root);
  const fs::path arena = fs::path(AMP_SOURCE_DIR) / "problems" / "sins-arena.yaml";
  const std::string small = "params: {worlds: 3, step_limit: 200}}";
  std::ofstream(root / "exp.yaml") << "name: sins-tiny\nseed: 5\nruns: 2\ntime_limit: 600\ncommon_seeds: true\n"
                                   << "cost: solved_fraction\nproblems: [" << arena.string() << "]\nplanners:\n"
                                   << "  - {name: static, planner: static, " << small << "\n"
                                   << "  - {name: random, planner: random, " << small << "\n"
                                   << "  - {name: sins, planner: sins, " << small << "\n";
  const Experiment e = load_experiment(root / "exp.yaml");
  BenchOptions o;
  o.out_dir = root / "out";
  o.threads = 2;
  const BenchResult r = run_experiment(e, o);
  EXPECT_EQ(r.written, 6u);

  int rows = 0;
  std::map<int, double> rejected;  // by run: common seeds give every system the same worlds
  for_each_trial(o.out_dir / "runs.csv", e, [&](const Trial& t) {
    ++rows;
    SCOPED_TRACE(t.record.planner);
    EXPECT_EQ(t.record.status, core::PlanStatus::kSolved) << t.record.message;
    for (const char* key : {"worlds", "solved_fraction", "steps_mean", "distance_mean", "distance_ratio_mean",
                            "virtual_collisions_mean", "cases", "rejected_worlds"}) {
      ASSERT_EQ(t.record.extra.count(key), 1u) << key;
    }
    EXPECT_EQ(t.record.extra.at("worlds"), 3.0);
    const auto [it, fresh] = rejected.emplace(t.id.run, t.record.extra.at("rejected_worlds"));
    if (!fresh) {
      EXPECT_EQ(it->second, t.record.extra.at("rejected_worlds"));
    }
  });
  EXPECT_EQ(rows, 6);

  const nlohmann::json s = nlohmann::json::parse(std::ifstream(o.out_dir / "summary.json"));
  for (const auto& c : s["problems"][0]["planners"]) {
    EXPECT_EQ(c["cost"]["metric"], "solved_fraction") << c.dump();
    EXPECT_EQ(c["cost"]["missing"], 0) << c.dump();
    EXPECT_TRUE(c["metrics"].contains("distance_ratio_mean")) << c.dump();
  }
  fs::remove_all(root);
}

}  // namespace
}  // namespace amp::bench
