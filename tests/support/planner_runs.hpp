#pragma once
// Planner runs for the property tests (issue 17): drawn cases, parameters and limits, timed runs, a
// shard of runs checked and run again on two threads, and a directory for the problem files that
// outlives a failing test.
#include <chrono>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <iostream>
#include <map>
#include <string>
#include <system_error>
#include <thread>
#include <utility>
#include <vector>

#include <unistd.h>

#include <gtest/gtest.h>

#include "amp/core/parameters.hpp"
#include "amp/core/rng.hpp"
#include "amp/core/run_record.hpp"
#include "amp/roadmap/catalog/planner_registry.hpp"
#include "amp/roadmap/run.hpp"
#include "amp/world/problem.hpp"
#include "support/random_problems.hpp"  // num: run arguments print numbers as the problem files do
#include "support/time_allowance.hpp"

namespace amp::test {

// Drawn values for a planner's numeric parameters, kept small so that every run is quick; booleans
// and choices are drawn from their whole range, other numbers keep their defaults.
inline core::ParamMap random_params(const roadmap::PlannerInfo& info, core::Rng& rng) {
  static const std::map<std::string, std::pair<double, double>> kRanges = {
      {"k", {1, 20}},        {"training_nodes", {10, 100}}, {"training_k", {1, 10}}, {"m", {1, 20}},
      {"steps", {8, 128}},   {"max_cells", {100, 1e5}},     {"o", {1, 32}},          {"s", {10, 5000}},
      {"n", {0.01, 10}},     {"a", {0, 6}},                 {"b", {1, 8}},           {"gamma", {0.05, 1}},
      {"alpha", {0.5, 10}},  {"d_scale", {0.2, 5}},         {"uniform_mix", {0, 1}}, {"max_attempts", {1, 200}},
      {"max_steps", {10, 2000}}, {"region_margin", {0, 2}}, {"smooth_attempts", {0, 200}},
      {"inflation_radius", {0, 1}}, {"cost_scaling_factor", {0, 20}}, {"penalty", {0, 5}}};
  core::ParamMap out;
  for (const core::ParamSpec& s : info.params) {
    if (rng.uniform01() >= 0.3) continue;
    if (s.type == core::ParamType::kBool) out.emplace(s.name, rng.uniform01() < 0.5);
    if (s.type == core::ParamType::kChoice) out.emplace(s.name, s.choices[rng.uniform_index(s.choices.size())]);
    const auto r = kRanges.find(s.name);
    if (r == kRanges.end() || s.type == core::ParamType::kBool || s.type == core::ParamType::kChoice) continue;
    const double v = rng.uniform(r->second.first, r->second.second);
    out.emplace(s.name, s.type == core::ParamType::kInteger ? std::round(v) : v);
  }
  return out;
}

// Mostly short time limits (a run that times out costs all of it), some longer ones.
inline double random_time_limit(core::Rng& rng) { return rng.uniform01() < 0.85 ? rng.uniform(0.05, 0.1) : rng.uniform(0.1, 0.5); }
// A node limit in [20, max]; for uas, a quarter of the time right at its training roadmap's size.
inline std::size_t random_node_limit(const std::string& planner, const core::ParamMap& params, std::size_t max, core::Rng& rng) {
  const std::size_t limit = 20 + rng.uniform_index(max - 19);
  if (planner != "uas" || rng.uniform01() >= 0.25) return limit;
  double training = 0.0;
  for (const core::ParamSpec& s : roadmap::builtin_planners().info("uas").params) {
    if (s.name == "training_nodes") training = s.default_value.number();
  }
  if (const auto given = params.find("training_nodes"); given != params.end()) training = given->second.number();
  return static_cast<std::size_t>(training) + rng.uniform_index(2);
}

// One planner run and its wall and CPU times, measured around execute_run as a caller sees it.
struct TimedRun {
  roadmap::RunOutcome out;
  double wall_s = -1.0;  // < 0: not run
  double cpu_s = -1.0;   // this thread's CPU time: what the limit check uses (support/time_allowance.hpp)
};
inline TimedRun timed_run(const world::Problem& p, const std::string& planner, const core::ParamMap& params,
                          std::uint64_t seed, double time_limit_s, std::size_t node_limit) {
  TimedRun r;
  const auto t0 = std::chrono::steady_clock::now();
  const double cpu0 = thread_cpu_seconds();
  r.out = roadmap::execute_run(p, planner, params, seed, time_limit_s, node_limit);
  r.cpu_s = thread_cpu_seconds() - cpu0;
  r.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  r.out.roadmap.reset();  // thousands of runs are kept for the thread comparison
  return r;
}

// A run whose result depends on its seed alone: it ended well inside its time limit, not on it.
inline bool seed_determined(const TimedRun& r, double time_limit_s) {
  return r.wall_s >= 0.0 && r.out.record.status != core::PlanStatus::kTimeout && r.wall_s < 0.5 * time_limit_s;
}

// Runs job(i) for every i in `indices` on two threads at once (each takes every other index).
template <class Job>
void on_two_threads(const std::vector<std::size_t>& indices, Job job) {
  auto half = [&](std::size_t first) {
    for (std::size_t k = first; k < indices.size(); k += 2) job(indices[k]);
  };
  std::thread other(half, 1);
  half(0);
  other.join();
}

// The same seed run alone and beside another run: the same record (but wall time) and path.
inline void expect_same_run(const TimedRun& a, const TimedRun& b, const std::string& what) {
  const core::RunRecord &x = a.out.record, &y = b.out.record;
  EXPECT_EQ(x.status, y.status) << what;
  EXPECT_EQ(x.cd_calls(), y.cd_calls()) << what;
  EXPECT_EQ(x.clearance_calls, y.clearance_calls) << what;
  EXPECT_EQ(x.nodes, y.nodes) << what;
  EXPECT_EQ(x.edges, y.edges) << what;
  EXPECT_EQ(x.path_length, y.path_length) << what;
  EXPECT_EQ(x.extra, y.extra) << what;
  ASSERT_EQ(a.out.path.size(), b.out.path.size()) << what;
  for (std::size_t i = 0; i < a.out.path.size(); ++i) ASSERT_EQ(a.out.path[i], b.out.path[i]) << what << ": state " << i;
}

// `amp plan` arguments that repeat a run.
inline std::string plan_arguments(const std::string& planner, const core::ParamMap& params, std::uint64_t seed,
                                  double time_limit_s, std::size_t node_limit) {
  std::string a = "--planner " + planner + " --seed " + std::to_string(seed) + " --time-limit " + num(time_limit_s) +
                  " --node-limit " + std::to_string(node_limit);
  for (const auto& [k, v] : params) a += " --param " + k + "=" + v.to_string();
  return a;
}

// A case drawn from its own seed: its model, written to `file` and loaded as `amp plan` loads it,
// and the run's parameters, seed and time limit.
template <class Model>
struct DrawnCase {
  int index = 0;
  Model model;
  std::filesystem::path file;
  world::Problem problem;
  core::ParamMap params;
  std::uint64_t seed = 0;
  double time_limit_s = 0.0;
};

template <class Model>
struct PlannerCase : DrawnCase<Model> {
  std::string planner;
  std::size_t node_limit = 0;

  // Drawn in this order, which fixes every case's run for its index.
  void draw_run(core::Rng& rng, std::size_t max_nodes) {
    this->params = random_params(roadmap::builtin_planners().info(planner), rng);
    this->seed = rng.next_u64() >> 16;
    this->time_limit_s = random_time_limit(rng);
    node_limit = random_node_limit(planner, this->params, max_nodes, rng);
  }
  std::string describe() const {
    return "case " + std::to_string(this->index) + ": amp plan " + this->file.string() + " " +
           plan_arguments(planner, this->params, this->seed, this->time_limit_s, node_limit) + "\n" + this->model.yaml;
  }
};

// Every planner but grid-dp, which takes map worlds only.
inline std::vector<std::string> any_world_planners() {
  std::vector<std::string> out;
  for (const std::string& p : roadmap::builtin_planners().names()) {
    if (p != "grid-dp") out.push_back(p);
  }
  return out;
}

// One shard of a planner property test. Each case runs alone: it must end with a known status
// within its limits, and a solved run is checked by expect_solved(case, run). Then the runs that
// depend on their seed alone run again, two at a time, and must give the same record and path.
// Every planner of any_world_planners() must have run.
template <class Case, class ExpectSolved>
void run_shard(const std::string& name, const std::vector<Case>& cases, ExpectSolved expect_solved) {
  const auto run = [](const Case& c) { return timed_run(c.problem, c.planner, c.params, c.seed, c.time_limit_s, c.node_limit); };
  std::vector<TimedRun> alone;
  std::map<std::string, std::pair<int, int>> tally;  // planner: runs, solved
  for (const Case& c : cases) {
    const TimedRun& r = alone.emplace_back(run(c));
    const core::RunRecord& rec = r.out.record;
    const auto status = rec.status;
    EXPECT_TRUE(status == core::PlanStatus::kSolved || status == core::PlanStatus::kTimeout ||
                status == core::PlanStatus::kNodeLimit || status == core::PlanStatus::kUnsolvable)
        << core::to_string(status) << " " << rec.message << "\n" << c.describe();
    EXPECT_LE(r.cpu_s, c.time_limit_s + time_allowance(c.time_limit_s)) << core::to_string(status) << "\n" << c.describe();
    EXPECT_LE(rec.nodes, c.node_limit) << core::to_string(status) << "\n" << c.describe();
    if (status == core::PlanStatus::kSolved) {
      expect_solved(c, r);
    } else {
      EXPECT_TRUE(r.out.path.empty()) << c.describe();
    }
    auto& [runs, solved] = tally[c.planner];
    ++runs;
    solved += status == core::PlanStatus::kSolved ? 1 : 0;
  }
  std::vector<std::size_t> again;
  for (std::size_t k = 0; k < cases.size(); ++k) {
    if (seed_determined(alone[k], cases[k].time_limit_s)) again.push_back(k);
  }
  std::vector<TimedRun> paired(cases.size());
  on_two_threads(again, [&](std::size_t k) { paired[k] = run(cases[k]); });
  int compared = 0;
  for (std::size_t k : again) {
    if (!seed_determined(paired[k], cases[k].time_limit_s)) continue;  // a loaded machine
    ++compared;
    expect_same_run(alone[k], paired[k], "1 vs 2 threads, " + cases[k].describe());
  }
  EXPECT_GE(compared, cases.size() / (4 * kSanitizerSlowdown));  // instrumented runs near their limits are not compared
  std::string summary;
  for (const auto& [planner, n] : tally) summary += " " + planner + " " + std::to_string(n.second) + "/" + std::to_string(n.first);
  std::cout << name << ": solved/runs" << summary << "; compared on 2 threads: " << compared << "\n";
  for (const std::string& p : any_world_planners()) EXPECT_GT(tally[p].first, 0) << p << " never ran";
}

// A fresh directory for one test's problem files, left in place when the test failed, so that the
// printed `amp plan` arguments repeat a failing case.
class TempDir {
 public:
  explicit TempDir(const std::string& name)
      : path_(std::filesystem::temp_directory_path() / ("amp-property-" + name + "-" + std::to_string(::getpid()))) {
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ec;
    if (!::testing::Test::HasFailure()) std::filesystem::remove_all(path_, ec);
  }
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

}  // namespace amp::test
