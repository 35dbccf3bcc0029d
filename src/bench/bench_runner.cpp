#include "amp/core/version.hpp"
#include "amp/bench/bench_runner.hpp"

#include <chrono>
#include <condition_variable>
#include <fstream>
#include <map>
#include <mutex>
#include <thread>

#include <nlohmann/json.hpp>

#include "amp/bench/method_runner.hpp"
#include "amp/bench/outputs.hpp"
#include "amp/bench/runs_csv.hpp"
#include "amp/core/error.hpp"

namespace amp::bench {

namespace {

constexpr const char* kManifest = "manifest.json";
constexpr const char* kRunsCsv = "runs.csv";

nlohmann::json manifest_of(const Experiment& e, const Shard& shard) {
  return {{"experiment", e.name},
          {"experiment_file", std::filesystem::absolute(e.file).lexically_normal().string()},
          {"fingerprint", e.fingerprint},
          {"shard", shard.to_string()},
          {"trials", e.trial_count()},
          {"runs", e.runs},
          {"time_limit_s", e.time_limit_s},
          {"version", std::string("AMP ") + core::kVersion}};
}

// Checks that `dir` may receive this run's outputs, and creates it.
void prepare_directory(const Experiment& e, const BenchOptions& o) {
  const auto& dir = o.out_dir;
  std::error_code ec;
  if (std::filesystem::exists(dir, ec) && !std::filesystem::is_directory(dir, ec)) {
    throw Error("--out: '" + dir.string() + "' is a file, expected a directory");
  }
  const bool non_empty = std::filesystem::is_directory(dir, ec) && !std::filesystem::is_empty(dir, ec);
  if (o.resume) {
    const auto m = dir / kManifest;
    if (!std::filesystem::is_regular_file(m)) {
      throw Error("--resume: '" + dir.string() + "' holds no earlier run of an experiment (no " + kManifest + ")");
    }
    nlohmann::json j;
    try {
      std::ifstream(m) >> j;
    } catch (const std::exception&) {
      throw Error("--resume: " + m.string() + " is not valid JSON");
    }
    if (j.value("fingerprint", "") != e.fingerprint) {
      throw Error("--resume: '" + dir.string() + "' holds results of another experiment (or the experiment or its "
                  "problem files changed since)");
    }
    if (j.value("shard", "") != o.shard.to_string()) {
      throw Error("--resume: '" + dir.string() + "' holds shard " + j.value("shard", "?") + ", not " +
                  o.shard.to_string());
    }
    return;
  }
  if (non_empty && !o.force) {
    throw Error("--out: directory '" + dir.string() + "' is not empty (use --resume to finish an interrupted run, "
                "or --force to overwrite)");
  }
  std::filesystem::create_directories(dir, ec);
  if (ec) throw Error("--out: cannot create '" + dir.string() + "': " + ec.message());
  std::ofstream(dir / kManifest) << manifest_of(e, o.shard).dump(2) << '\n';
}

// Trials already in runs.csv (resume); cuts a row left half-written by a kill.
std::size_t completed_trials(const Experiment& e, const BenchOptions& o, const std::vector<std::size_t>& mine) {
  const auto csv = o.out_dir / kRunsCsv;
  if (!std::filesystem::is_regular_file(csv)) return 0;
  std::size_t n = 0;
  std::uintmax_t complete = 0;
  for_each_trial(csv, e, [&](const Trial& t) {
    if (n >= mine.size() || t.id.index != mine[n]) {
      throw Error("--resume: " + csv.string() + " is not a prefix of this shard's trials (edited by hand?)");
    }
    ++n;
  }, &complete);
  std::filesystem::resize_file(csv, complete);
  return n;
}

}  // namespace

Trial run_trial(const Experiment& e, std::size_t index, const std::atomic<bool>* cancel, std::vector<State>* path) {
  Trial t;
  t.id = trial_id(e, index);
  t.seed = trial_seed(e, t.id);
  const ExperimentProblem& problem = e.problems[t.id.problem];
  const PlannerConfig& config = e.planners[t.id.planner];
  const core::ParamMap params = trial_params(e, t.id, &t.drawn);
  try {
    MethodRun run = run_method(*problem.problem, config.kind, config.planner, params, t.seed, e.time_limit_s,
                               e.node_limit, cancel);
    t.record = std::move(run.record);
    if (path != nullptr) *path = std::move(run.path);
  } catch (const std::exception& ex) {
    // The experiment goes on: a run that fails is a result too (status error with its message).
    t.record.status = core::PlanStatus::kError;
    t.record.message = ex.what();
    t.record.seed = t.seed;
  }
  t.record.problem = problem.label;
  t.record.planner = config.label;
  for (const auto& [k, v] : t.drawn) t.record.extra.erase(k);  // drawn values have their own columns
  return t;
}

BenchResult run_experiment(const Experiment& e, const BenchOptions& o) {
  const auto start = std::chrono::steady_clock::now();
  prepare_directory(e, o);
  std::vector<std::size_t> mine;
  for (std::size_t i = 0; i < e.trial_count(); ++i) {
    if (o.shard.owns(i)) mine.push_back(i);
  }
  const std::size_t already = o.resume ? completed_trials(e, o, mine) : 0;
  RunsCsvWriter csv(o.out_dir / kRunsCsv, e, o.resume && already > 0);

  BenchResult result;
  result.total = mine.size();
  result.written = already;
  const int threads = o.threads > 0 ? o.threads : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));

  // Workers take trials in order and park results here; this thread writes them in trial order.
  std::mutex mutex;
  std::condition_variable ready;
  std::map<std::size_t, Trial> finished;  // position in `mine` -> trial
  std::size_t next = already;
  std::size_t abandoned = mine.size();  // first position whose trial was cut short by a cancel
  int running = threads;

  auto cancelled = [&] { return o.cancel != nullptr && o.cancel->load(std::memory_order_relaxed); };
  auto worker = [&] {
    for (;;) {
      std::size_t pos;
      {
        std::lock_guard lock(mutex);
        if (next >= mine.size() || cancelled()) break;
        pos = next++;
      }
      Trial t = run_trial(e, mine[pos], o.cancel);
      std::lock_guard lock(mutex);
      if (cancelled()) {
        abandoned = std::min(abandoned, pos);  // its result may be cut short: never written
      } else {
        finished.emplace(pos, std::move(t));
      }
      ready.notify_one();
    }
    std::lock_guard lock(mutex);
    --running;
    ready.notify_one();
  };
  std::vector<std::thread> pool;
  pool.reserve(threads);
  for (int i = 0; i < threads; ++i) pool.emplace_back(worker);

  auto report = [&] {
    if (o.on_progress) {
      o.on_progress({result.written, result.total,
                     std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()});
    }
  };
  report();
  std::size_t write_pos = already;
  std::exception_ptr failure;
  {
    std::unique_lock lock(mutex);
    for (;;) {
      ready.wait(lock, [&] { return finished.count(write_pos) != 0 || running == 0; });
      while (!finished.empty() && finished.begin()->first == write_pos && write_pos < abandoned) {
        Trial t = std::move(finished.begin()->second);
        finished.erase(finished.begin());
        lock.unlock();
        try {
          csv.add(t);
        } catch (...) {
          failure = std::current_exception();
        }
        lock.lock();
        if (failure) break;
        ++write_pos;
        ++result.written;
        lock.unlock();
        report();
        lock.lock();
      }
      if (failure || (running == 0 && finished.count(write_pos) == 0)) break;
    }
  }
  if (failure) {
    // Stop the pool before rethrowing: workers must not outlive the objects they use.
    {
      std::lock_guard lock(mutex);
      next = mine.size();
    }
    for (auto& t : pool) t.join();
    std::rethrow_exception(failure);
  }
  for (auto& t : pool) t.join();
  csv.finish();
  result.interrupted = result.written < result.total;
  result.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!result.interrupted) {
    RunInfo info = current_run_info(threads);
    info.total_time_s = result.wall_time_s;
    const auto outputs_start = std::chrono::steady_clock::now();
    write_outputs(e, o.out_dir, info, o.ompl_log);
    result.outputs_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - outputs_start).count();
    result.wall_time_s += result.outputs_time_s;
  }
  return result;
}

}  // namespace amp::bench
