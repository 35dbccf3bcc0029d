// `amp bench` (run an experiment) and `amp merge` (combine shards).
#include <unistd.h>

#include <csignal>
#include <cstdio>
#include <iostream>
#include <memory>

#include "amp/bench/bench_runner.hpp"
#include "amp/bench/experiment.hpp"
#include "amp/bench/merge.hpp"
#include "amp/bench/method_listing.hpp"
#include "amp/core/error.hpp"
#include "cli_util.hpp"
#include "commands.hpp"
#include "mpi_session.hpp"

namespace amp::cli {

namespace {

// Set by SIGINT/SIGTERM; a signal handler can only touch a lock-free atomic, hence this one static.
std::atomic<bool> g_interrupted{false};

extern "C" void on_interrupt(int) { g_interrupted.store(true); }

struct BenchOptions {
  std::string experiment;
  std::string out;
  int threads = 0;
  std::string shard = "0/1";
  bool resume = false;
  bool force = false;
  bool ompl_log = false;
  bool list = false;
  int runs = 0;
  double time_limit = 0.0;
};

std::string format_duration(double s) {
  char buf[32];
  const long t = static_cast<long>(s + 0.5);
  std::snprintf(buf, sizeof buf, "%02ld:%02ld:%02ld", t / 3600, (t / 60) % 60, t % 60);
  return buf;
}

// A progress bar on a terminal; plain lines (every 10 %) when stderr is a file or a pipe.
std::function<void(const bench::Progress&)> progress_printer() {
  const bool tty = isatty(STDERR_FILENO) != 0;
  auto last_decile = std::make_shared<int>(-1);
  return [tty, last_decile](const bench::Progress& p) {
    const double frac = p.total ? static_cast<double>(p.done) / p.total : 1.0;
    const double eta = p.done > 0 ? p.elapsed_s * (p.total - p.done) / std::max<double>(p.done, 1) : 0.0;
    if (tty) {
      constexpr int kWidth = 30;
      const int fill = static_cast<int>(frac * kWidth);
      std::fprintf(stderr, "\r[%s%s] %zu/%zu runs  elapsed %s  remaining %s ", std::string(fill, '#').c_str(),
                   std::string(kWidth - fill, '.').c_str(), p.done, p.total, format_duration(p.elapsed_s).c_str(),
                   p.done > 0 ? format_duration(eta).c_str() : "--:--:--");
      if (p.done == p.total) std::fputc('\n', stderr);
    } else {
      const int decile = static_cast<int>(frac * 10);
      if (decile != *last_decile) {
        *last_decile = decile;
        std::fprintf(stderr, "amp bench: %zu/%zu runs, elapsed %s, remaining %s\n", p.done, p.total,
                     format_duration(p.elapsed_s).c_str(), p.done > 0 ? format_duration(eta).c_str() : "?");
      }
    }
    std::fflush(stderr);
  };
}

int run_bench(const BenchOptions& o) {
  if (o.list) {
    bench::list_methods(std::cout);
    return kExitOk;
  }
  if (o.experiment.empty()) throw Error("bench: give an experiment file (or --list)");
  bench::Experiment e = bench::load_experiment(o.experiment);
  if (o.runs > 0) e.runs = o.runs;
  if (o.time_limit > 0.0) e.time_limit_s = o.time_limit;
  e.fingerprint = bench::experiment_fingerprint(e);

  bench::BenchOptions b;
  b.out_dir = o.out.empty() ? std::filesystem::path("out/bench") / e.name : std::filesystem::path(o.out);
  b.threads = o.threads;
  b.shard = bench::parse_shard(o.shard);
  b.resume = o.resume;
  b.force = o.force;
  b.ompl_log = o.ompl_log;
  b.cancel = &g_interrupted;
  std::signal(SIGINT, on_interrupt);
  std::signal(SIGTERM, on_interrupt);

  const MpiSession mpi;
  const std::filesystem::path out = b.out_dir;
  if (mpi.active()) {
    // Rank r runs shard r/P into out/shards/r; rank 0 merges them into out once all have finished.
    if (b.shard.count != 1) throw Error("--shard: not with mpirun, which shards by rank");
    std::error_code ec;
    const bool non_empty = std::filesystem::is_directory(out, ec) && !std::filesystem::is_empty(out, ec);
    const bool refuse = (std::filesystem::exists(out, ec) && !std::filesystem::is_directory(out, ec)) ||
                        (non_empty && !o.force && !o.resume);
    if (mpi.any(refuse)) {
      throw Error("--out: '" + out.string() + "' is a file or not empty (use --resume or --force)");
    }
    mpi.barrier();  // every rank has looked before any rank writes
    b.shard = bench::Shard{mpi.rank(), mpi.size()};
    b.out_dir = out / "shards" / std::to_string(mpi.rank());
    b.resume = o.resume && std::filesystem::is_directory(b.out_dir, ec);
  }
  if (mpi.rank() == 0) b.on_progress = progress_printer();

  if (mpi.rank() == 0) {
    std::cout << "amp bench: " << e.name << ": " << e.problems.size() << " problems x " << e.planners.size()
              << " planners x " << e.runs << " runs (" << (mpi.active() ? std::to_string(mpi.size()) + " MPI ranks"
                                                                           : "shard " + b.shard.to_string())
              << ") -> " << out.string() << '\n';
  }
  const bench::BenchResult r = bench::run_experiment(e, b);
  if (mpi.any(r.interrupted)) {
    std::cerr << "\namp bench: interrupted: " << r.written << " of " << r.total << " runs written to "
              << (b.out_dir / "runs.csv").string() << "; finish with: amp bench " << o.experiment << " --out "
              << out.string() << " --resume\n";
    return 130;
  }
  if (mpi.active()) {
    mpi.barrier();
    if (mpi.rank() == 0) {
      std::vector<std::filesystem::path> shards;
      for (std::size_t i = 0; i < mpi.size(); ++i) shards.push_back(out / "shards" / std::to_string(i));
      bench::merge_results(shards, out, /*force=*/true, o.ompl_log);  // out holds the shards themselves
    }
    mpi.barrier();
  }
  if (mpi.rank() == 0) {
    char times[96];
    std::snprintf(times, sizeof times, "%.2f s (runs %.2f s, outputs %.2f s)", r.wall_time_s,
                  r.wall_time_s - r.outputs_time_s, r.outputs_time_s);
    std::cout << "wrote " << (mpi.active() ? e.trial_count() : r.written) << " runs in " << times << ": "
              << (out / "runs.csv").string()
              << ", summary.json, results.db, report.html" << (o.ompl_log ? ", ompl-logs/" : "") << '\n';
  }
  return kExitOk;
}

struct MergeOptions {
  std::vector<std::string> dirs;
  std::string out;
  bool force = false;
  bool ompl_log = false;
};

}  // namespace

void add_bench_command(CLI::App& app, int& exit_code) {
  auto o = std::make_shared<BenchOptions>();
  CLI::App* cmd = app.add_subcommand("bench", "Run an experiment (problems x planners x runs) and write its results");
  cmd->add_option("experiment", o->experiment, "Experiment file (docs/experiment-format.md)");
  cmd->add_option("-j,--threads", o->threads, "Worker threads [all cores]")->check(CLI::Range(1, 1024));
  cmd->add_option("--out", o->out, "Output directory [out/bench/<experiment name>]");
  cmd->add_option("--shard", o->shard, "Run only shard i/N of the trials (for clusters) [0/1]");
  cmd->add_flag("--resume", o->resume, "Finish an interrupted run in --out");
  cmd->add_flag("--force", o->force, "Overwrite the outputs in a non-empty --out");
  cmd->add_flag("--ompl-log", o->ompl_log, "Also write OMPL's text benchmark logs");
  cmd->add_option("--runs", o->runs, "Override the file's runs per planner (a quick look)")->check(positive_integer());
  cmd->add_option("--time-limit", o->time_limit, "Override the file's time limit per run, seconds")
      ->check(positive_number());
  cmd->add_flag("--list", o->list, "List the planners and navigation methods with their parameters");
  cmd->callback([o, &exit_code] { exit_code = run_bench(*o); });

  auto m = std::make_shared<MergeOptions>();
  CLI::App* merge = app.add_subcommand("merge", "Combine the shards of an experiment into one result directory");
  merge->add_option("dirs", m->dirs, "Shard result directories")->required();
  merge->add_option("--out", m->out, "Output directory")->required();
  merge->add_flag("--force", m->force, "Overwrite the outputs in a non-empty --out");
  merge->add_flag("--ompl-log", m->ompl_log, "Also write OMPL's text benchmark logs");
  merge->callback([m, &exit_code] {
    std::vector<std::filesystem::path> dirs(m->dirs.begin(), m->dirs.end());
    const std::size_t n = bench::merge_results(dirs, m->out, m->force, m->ompl_log);
    std::cout << "merged " << n << " runs from " << dirs.size() << " shards into " << m->out << '\n';
    exit_code = kExitOk;
  });
}

}  // namespace amp::cli
