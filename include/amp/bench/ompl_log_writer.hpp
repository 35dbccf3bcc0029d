#pragma once
#include <cstddef>
#include <filesystem>
#include <fstream>
#include <limits>
#include <set>
#include <string>
#include <vector>

#include "amp/bench/trial_sink.hpp"

namespace amp::bench {

// Writes an experiment as OMPL's text benchmark logs (the format of Benchmark::saveResultsToStream,
// which ompl_benchmark_statistics.py parses into OMPL's database): one log per problem, since
// OMPL's experiment is one problem. The properties are those of OmplDatabaseWriter, so parsing the
// logs gives the database that OmplDatabaseWriter writes.
//
// A log lists the properties of a planner's runs before its rows, and an extra may first appear in
// any run, so the runs of the current (problem, planner) are kept in a temporary file beside the
// log; trials arrive problem-major, so memory does not grow with the run count.
class OmplLogWriter final : public TrialSink {
 public:
  // `log_dir_or_file`: a path ending in ".log" names the log of a one-problem experiment (with more
  // problems, <stem>_<problem label>.log beside it); any other path is a directory (created if
  // missing) receiving <problem label>.log. Throws FileError if a log already exists or the
  // directory cannot be created.
  OmplLogWriter(std::filesystem::path log_dir_or_file, const Experiment& e, const RunInfo& info);
  ~OmplLogWriter() override;  // removes the temporary files
  OmplLogWriter(const OmplLogWriter&) = delete;
  OmplLogWriter& operator=(const OmplLogWriter&) = delete;

  // Trials must come in trial order (problem, then planner); throws Error otherwise.
  void add(const Trial& trial) override;
  // Writes the logs still open, including those of problems and planners with no trials (0 runs).
  void finish() override;

  // The log files, by problem index.
  const std::vector<std::filesystem::path>& files() const { return files_; }
  static std::vector<std::filesystem::path> log_paths(const std::filesystem::path& log_dir_or_file,
                                                      const Experiment& e);

 private:
  static constexpr std::size_t kNone = std::numeric_limits<std::size_t>::max();

  void start_problem(std::size_t problem);
  void end_problem();
  void start_planner(std::size_t planner);
  void end_planner();
  void write_section(std::size_t planner, bool with_runs);
  void write_log(std::size_t problem, double total_time_s, bool with_body);
  void remove_temporaries() noexcept;
  [[noreturn]] void fail(const std::filesystem::path& p, const std::string& what) const;

  Experiment experiment_;
  RunInfo info_;
  std::vector<std::filesystem::path> files_;
  std::filesystem::path runs_path_;  // the current planner's runs, one line each
  std::filesystem::path body_path_;  // the current problem's finished planner sections
  std::ofstream runs_;
  std::ofstream body_;
  std::size_t problem_ = kNone;       // the problem being written
  std::size_t planner_ = kNone;       // the planner being buffered
  std::size_t next_problem_ = 0;      // first problem whose log is not written yet
  std::size_t next_planner_ = 0;      // first planner of problem_ whose section is not written yet
  std::set<std::string> keys_;        // the buffered runs' property keys ("time REAL")
  std::size_t runs_in_block_ = 0;
  double problem_time_s_ = 0.0;
  bool finished_ = false;
};

}  // namespace amp::bench
