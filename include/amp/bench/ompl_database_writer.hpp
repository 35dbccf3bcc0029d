#pragma once
#include <cstddef>
#include <filesystem>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "amp/bench/trial_sink.hpp"

struct sqlite3;
struct sqlite3_stmt;

namespace amp::bench {

// Writes an experiment as OMPL's benchmark database (the SQLite schema ompl_benchmark_statistics.py
// creates), so that Planner Arena and OMPL's scripts read AMP's results:
//  - `experiments`: one row per problem (OMPL's experiment is one problem), name = problem label,
//    setup = the problem file's text, seed = the master seed, runcount = runs per planner, plus the
//    columns amp_experiment, experiment_file, fingerprint, problem_file, node_limit (when the
//    experiment sets one), threads;
//  - `plannerConfigs`: one row per configuration, "geometric_<label>", settings = its parameters;
//  - `runs`: OMPL's standard properties (time, status, solved, solution length, graph states, ...),
//    AMP's record fields, param_<name> per drawn parameter and the planner's extras, columns being
//    added as they first appear;
//  - `enums`: OMPL's PlannerStatus names (see ompl_status() in src/bench/ompl/ompl_properties.hpp
//    for how AMP's statuses map onto them); `progress`: empty.
// Rows are committed every kRowsPerTransaction, so memory does not grow with the run count.
class OmplDatabaseWriter final : public TrialSink {
 public:
  static constexpr std::size_t kRowsPerTransaction = 1000;

  // Throws FileError if `db` exists (the caller decides whether to remove it), cannot be created, or
  // a problem file cannot be read.
  OmplDatabaseWriter(std::filesystem::path db, const Experiment& e, const RunInfo& info);
  ~OmplDatabaseWriter() override;
  OmplDatabaseWriter(const OmplDatabaseWriter&) = delete;
  OmplDatabaseWriter& operator=(const OmplDatabaseWriter&) = delete;

  void add(const Trial& trial) override;
  void finish() override;

 private:
  struct StatementDeleter {
    void operator()(sqlite3_stmt* s) const;
  };
  using Statement = std::unique_ptr<sqlite3_stmt, StatementDeleter>;

  void exec(const std::string& sql);
  Statement prepare(const std::string& sql);
  void step_done(sqlite3_stmt* s, const char* what);
  [[noreturn]] void fail(const std::string& what) const;
  void create_schema(const RunInfo& info);
  void ensure_column(const std::string& table, const std::string& column, const std::string& type);
  void close() noexcept;

  std::filesystem::path path_;
  Experiment experiment_;  // a copy: the caller's may not outlive the writer
  sqlite3* db_ = nullptr;
  std::vector<long long> experiment_ids_;  // by problem index
  std::vector<long long> planner_ids_;     // by planner index
  std::vector<double> total_time_s_;       // per problem: sum of its runs' wall times
  std::set<std::string> run_columns_;      // lower case, as SQLite compares them
  std::map<std::string, Statement> inserts_;  // by the row's column list
  std::size_t rows_in_transaction_ = 0;
  bool finished_ = false;
};

}  // namespace amp::bench
