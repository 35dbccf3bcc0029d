// The harness gives the same results whatever the threads, shards or interruptions: runs.csv (but for
// the wall-time column) and the run-cost summary are equal byte for byte.
#include "amp/bench/bench_runner.hpp"

#include <atomic>
#include <fstream>
#include <set>
#include <sstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "amp/bench/merge.hpp"
#include "amp/core/error.hpp"
#include "amp/core/rng.hpp"
#include "support/source_tree.hpp"

namespace amp::bench {
namespace {

namespace fs = std::filesystem;

class BenchRunnerTest : public ::testing::Test {
 protected:
  void SetUp() override {
    root_ = fs::temp_directory_path() / ("amp-bench-test-" + std::to_string(::getpid()) + "-" +
                                         ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(root_);
    fs::create_directories(root_);
    experiment_file_ = write_experiment("exp.yaml", "tiny", 4);
  }
  void TearDown() override { fs::remove_all(root_); }

  fs::path write_experiment(const std::string& file, const std::string& name, int runs) {
    const fs::path problems = fs::path(AMP_SOURCE_DIR) / "problems";
    // Small problems, and a time limit that never binds (only node limits may end a run), so that
    // results are the same under a sanitizer or a loaded machine.
    std::ofstream(root_ / file) << "name: " << name << "\nseed: 11\nruns: " << runs
                                << "\ntime_limit: 600\nnode_limit: 20000\nproblems:\n  - "
                                << (problems / "office-map.yaml").string() << "\n  - " << (problems / "linkage.yaml").string()
                                << "\nplanners:\n  - prm\n  - {name: prm-meta, planner: prm, draw: {k: [5, 15]}}\n";
    return root_ / file;
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
    return run_experiment(load_experiment(experiment_file_), o);
  }

  // runs.csv without the wall-time column (the only field that legitimately differs between runs).
  static std::string csv_without_time(const fs::path& dir) {
    std::ifstream in(dir / "runs.csv");
    std::string line, out;
    while (std::getline(in, line)) {
      std::vector<std::string> f;
      std::stringstream ss(line);
      std::string cell;
      while (std::getline(ss, cell, ',')) f.push_back(cell);
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
      for (auto& c : p["planners"]) out.push_back({c["name"], c["cd_calls"], c["nodes"], c["statuses"]});
      out.push_back(p["tests"]);
    }
    return out;
  }

  fs::path root_;
  fs::path experiment_file_;
};

TEST_F(BenchRunnerTest, ResultsDoNotDependOnTheThreadCount) {
  const BenchResult a = run(root_ / "one", 1);
  const BenchResult b = run(root_ / "two", 2);
  EXPECT_EQ(a.written, 16u);
  EXPECT_EQ(b.written, 16u);
  EXPECT_FALSE(a.interrupted);
  EXPECT_EQ(csv_without_time(root_ / "one"), csv_without_time(root_ / "two"));
  EXPECT_EQ(cost_summary(root_ / "one"), cost_summary(root_ / "two"));
  for (const char* f : {"runs.csv", "summary.json", "results.db", "report.html", "manifest.json"}) {
    EXPECT_TRUE(fs::is_regular_file(root_ / "one" / f)) << f;
  }
}

TEST_F(BenchRunnerTest, MergedShardsEqualTheSingleProcessRun) {
  run(root_ / "single", 2);
  std::vector<fs::path> shards;
  for (std::size_t i = 0; i < 3; ++i) {
    shards.push_back(root_ / ("shard" + std::to_string(i)));
    const BenchResult r = run(shards.back(), 1, Shard{i, 3});
    EXPECT_EQ(r.total, i == 0 ? 6u : 5u);  // 16 trials: 0, 3, ... go to shard 0
  }
  EXPECT_EQ(merge_results({shards[2], shards[0], shards[1]}, root_ / "merged", false, false), 16u);
  EXPECT_EQ(csv_without_time(root_ / "single"), csv_without_time(root_ / "merged"));
  EXPECT_EQ(cost_summary(root_ / "single"), cost_summary(root_ / "merged"));
}

TEST_F(BenchRunnerTest, ResumeAfterAnInterruptionFinishesOnlyTheMissingRuns) {
  run(root_ / "whole", 2);
  std::atomic<bool> cancel{false};
  const BenchResult cut = run(root_ / "resumed", 2, {}, &cancel, [&](const Progress& p) {
    if (p.done >= 5) cancel = true;  // as Ctrl-C after five runs
  });
  EXPECT_TRUE(cut.interrupted);
  EXPECT_GE(cut.written, 5u);
  EXPECT_LT(cut.written, 16u);
  EXPECT_FALSE(fs::exists(root_ / "resumed" / "summary.json"));
  // A half-written last row, as a kill during a write leaves it, is dropped on resume.
  std::ofstream(root_ / "resumed" / "runs.csv", std::ios::app) << "99,Office,pr";
  const BenchResult rest = run(root_ / "resumed", 1, {}, nullptr, {}, true);
  EXPECT_EQ(rest.written, 16u);
  EXPECT_FALSE(rest.interrupted);
  EXPECT_EQ(csv_without_time(root_ / "whole"), csv_without_time(root_ / "resumed"));
  EXPECT_EQ(cost_summary(root_ / "whole"), cost_summary(root_ / "resumed"));
}

TEST_F(BenchRunnerTest, RefusesBadOutputDirectoriesAndForeignShards) {
  std::ofstream(root_ / "a-file") << "x";
  EXPECT_THROW(run(root_ / "a-file", 1), Error);
  run(root_ / "done", 1);
  EXPECT_THROW(run(root_ / "done", 1), Error);  // not empty, neither --force nor --resume
  EXPECT_THROW(parse_shard("3/2"), ParameterError);
  EXPECT_THROW(parse_shard("1/0"), ParameterError);
  EXPECT_THROW(parse_shard("x"), ParameterError);

  // Shards of different experiments are not merged.
  experiment_file_ = write_experiment("other.yaml", "other", 3);
  run(root_ / "other0", 1, Shard{0, 2});
  experiment_file_ = root_ / "exp.yaml";
  run(root_ / "mine1", 1, Shard{1, 2});
  EXPECT_THROW(merge_results({root_ / "other0", root_ / "mine1"}, root_ / "m", false, false), Error);
  // A missing shard is named.
  try {
    merge_results({root_ / "mine1"}, root_ / "m2", false, false);
    FAIL() << "merge of one shard of two did not throw";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("shard 0/2 is missing"), std::string::npos) << e.what();
  }
}

TEST_F(BenchRunnerTest, TrialSeedsDependOnIdentityNotOrder) {
  const Experiment e = load_experiment(experiment_file_);
  // Swapping the problems in the file changes the trial numbers but not the seed of (problem, planner, run).
  const fs::path problems = fs::path(AMP_SOURCE_DIR) / "problems";
  std::ofstream(root_ / "swapped.yaml") << "name: tiny\nseed: 11\nruns: 4\ntime_limit: 600\nnode_limit: 20000\n"
                                        << "problems:\n  - " << (problems / "linkage.yaml").string() << "\n  - "
                                        << (problems / "office-map.yaml").string()
                                        << "\nplanners:\n  - prm\n  - {name: prm-meta, planner: prm, draw: {k: [5, 15]}}\n";
  const Experiment s = load_experiment(root_ / "swapped.yaml");
  const TrialId a = trial_id(e, 0);       // Office, prm, run 0
  const TrialId b = trial_id(s, 8);       // Office is second now
  ASSERT_EQ(s.problems[b.problem].label, e.problems[a.problem].label);
  EXPECT_EQ(trial_seed(e, a), trial_seed(s, b));
  EXPECT_NE(trial_seed(e, trial_id(e, 0)), trial_seed(e, trial_id(e, 1)));
}

// common_seeds: run i of every planner on a problem shares its seed (and no other trial does), the
// same identity as the SplitMix64 formula of docs/experiment-format.md, and the fingerprint changes.
TEST_F(BenchRunnerTest, CommonSeedsGiveEveryPlannerTheSameSeedPerRun) {
  const fs::path problems = fs::path(AMP_SOURCE_DIR) / "problems";
  const std::string body = "seed: 11\nruns: 3\nproblems:\n  - " + (problems / "linkage.yaml").string() + "\n  - " +
                           (problems / "office-map.yaml").string() + "\nplanners:\n  - prm\n  - hybrid-prm\n";
  std::ofstream(root_ / "common.yaml") << "name: common\ncommon_seeds: true\n" << body;
  std::ofstream(root_ / "own.yaml") << "name: common\n" << body;
  const Experiment c = load_experiment(root_ / "common.yaml");
  const Experiment o = load_experiment(root_ / "own.yaml");
  EXPECT_TRUE(c.common_seeds);
  EXPECT_FALSE(o.common_seeds);
  EXPECT_NE(c.fingerprint, o.fingerprint);
  std::set<std::uint64_t> distinct;
  for (std::size_t t = 0; t < c.trial_count(); ++t) {
    const TrialId id = trial_id(c, t);
    TrialId other = id;
    other.planner = 1 - id.planner;
    EXPECT_EQ(trial_seed(c, id), trial_seed(c, other));
    EXPECT_NE(trial_seed(o, id), trial_seed(o, other));
    distinct.insert(trial_seed(c, id));
    const std::uint64_t problem_hash = [&] {
      std::uint64_t h = 0xcbf29ce484222325ULL;  // FNV-1a of "<problem>\x1f"
      for (const char ch : c.problems[id.problem].label + '\x1f') {
        h ^= static_cast<unsigned char>(ch);
        h *= 0x100000001b3ULL;
      }
      return h;
    }();
    EXPECT_EQ(trial_seed(c, id), core::derive_seed(core::derive_seed(11, problem_hash), static_cast<std::uint64_t>(id.run)));
  }
  EXPECT_EQ(distinct.size(), 6u);  // 2 problems x 3 runs
}

TEST_F(BenchRunnerTest, ExperimentErrorsNameTheField) {
  std::ofstream(root_ / "bad.yaml") << "name: bad\nproblems: [nope.yaml]\nplanners: [prm]\n";
  EXPECT_THROW(load_experiment(root_ / "bad.yaml"), FileError);
  const fs::path walls = fs::path(AMP_SOURCE_DIR) / "problems" / "walls.yaml";
  std::ofstream(root_ / "bad2.yaml") << "problems: [" << walls.string() << "]\nplanners: [nope]\n";
  try {
    load_experiment(root_ / "bad2.yaml");
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("planners[0]"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("prm"), std::string::npos) << "lists the valid planners: " << e.what();
  }
  std::ofstream(root_ / "bad3.yaml") << "problems: [" << walls.string() << "]\nplanners: [{planner: prm, params: {k: 0}}]\n";
  EXPECT_THROW(load_experiment(root_ / "bad3.yaml"), FileError);
  std::ofstream(root_ / "bad4.yaml") << "problems: [" << walls.string() << "]\nplanners: [prm]\nruns: 0\n";
  EXPECT_THROW(load_experiment(root_ / "bad4.yaml"), FileError);
}

}  // namespace
}  // namespace amp::bench
