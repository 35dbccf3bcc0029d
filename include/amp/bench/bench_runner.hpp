#pragma once
#include <atomic>
#include <cstddef>
#include <filesystem>
#include <functional>

#include "amp/bench/experiment.hpp"
#include "amp/bench/shard.hpp"

namespace amp::bench {

struct Progress {
  std::size_t done = 0;   // trials finished in this shard (including those of an earlier, resumed run)
  std::size_t total = 0;  // trials of this shard
  double elapsed_s = 0.0;
};

struct BenchOptions {
  std::filesystem::path out_dir;
  int threads = 0;  // 0: all cores
  Shard shard;
  bool resume = false;  // finish the missing trials of an interrupted run in out_dir
  bool force = false;   // overwrite the outputs in a non-empty out_dir
  bool ompl_log = false;  // also write OMPL's text logs (out_dir/ompl-logs/<problem>.log)
  const std::atomic<bool>* cancel = nullptr;  // set by Ctrl-C: running trials stop, nothing partial is kept
  std::function<void(const Progress&)> on_progress;  // called from the writing thread
};

struct BenchResult {
  std::size_t written = 0;  // trials in runs.csv
  std::size_t total = 0;    // trials of this shard
  bool interrupted = false;
  double wall_time_s = 0.0;     // the whole call
  double outputs_time_s = 0.0;  // of which writing summary, database and report
};

// Runs an experiment's trials (this shard's, those not yet in runs.csv when resuming) on a pool of
// threads and streams them, in trial order, into out_dir/runs.csv; then writes the derived outputs
// (summary.json, results.db, report.html) from runs.csv. Every trial's result depends only on its
// seed, so the files are the same (but for timings) whatever the thread count, sharding or resume.
// Throws Error for a bad out_dir (a file; non-empty without force/resume; resume of another experiment).
BenchResult run_experiment(const Experiment& e, const BenchOptions& options);

// Runs one trial exactly as run_experiment does (also used by the report to redraw a solution).
Trial run_trial(const Experiment& e, std::size_t index, const std::atomic<bool>* cancel = nullptr,
                std::vector<State>* path = nullptr);

}  // namespace amp::bench
