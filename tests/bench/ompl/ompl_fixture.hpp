#pragma once
// A hand-made experiment and its trials for the OMPL writer tests (ompl_*_test.cpp), and helpers
// to run OMPL's own checker and read SQLite tables back.
#include <sqlite3.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include "amp/core/version.hpp"
#include "amp/bench/experiment.hpp"
#include "amp/bench/trial_sink.hpp"
#include "support/source_tree.hpp"

namespace amp::bench::test {

inline const char* kCorridorText = "world: corridor\nstart: [0, 0]\n|>>> not the end\ngoal: [1, 1]";
inline const char* kMazeText = "world: maze # semi;colon\ngoal: [2, 2]\n";

// A fresh directory per test, removed at the end.
struct TempDir {
  std::filesystem::path path;
  explicit TempDir(const std::string& name) {
    path = std::filesystem::temp_directory_path() / ("amp_ompl_" + name + "_" + std::to_string(::getpid()));
    std::filesystem::remove_all(path);
    std::filesystem::create_directories(path);
  }
  ~TempDir() {
    if (!std::getenv("AMP_KEEP_TEST_FILES")) std::filesystem::remove_all(path);
  }
};

inline void write_text(const std::filesystem::path& p, const std::string& text) {
  std::ofstream(p, std::ios::binary) << text;
}

// 2 problems x 2 configurations x 3 runs; the second configuration draws k from {5, 10}.
inline Experiment make_experiment(const std::filesystem::path& dir) {
  write_text(dir / "corridor.yaml", kCorridorText);
  write_text(dir / "maze.yaml", kMazeText);
  Experiment e;
  e.name = "ompl_writer_test";
  e.file = dir / "experiment.yaml";
  e.seed = 42;
  e.runs = 3;
  e.time_limit_s = 5.0;
  e.node_limit = 1000;
  e.fingerprint = "abc123";
  e.problems = {{"corridor", dir / "corridor.yaml", nullptr, {}}, {"maze", dir / "maze.yaml", nullptr, {}}};
  PlannerConfig fixed{"prm_k5", "prm", {{"k", 5}}, {}};
  PlannerConfig drawn{"prm_draw", "prm", {{"lazy", "true"}}, {{"k", {"5", "10"}}}};
  e.planners = {fixed, drawn};
  return e;
}

// Run r of every (problem, planner): runs 0 and 2 solve, run 1 times out, except that problem 1,
// planner 1, run 1 hits the node limit and problem 0, planner 1, run 2 fails with an error.
inline core::PlanStatus expected_status(std::size_t problem, std::size_t planner, int run) {
  if (problem == 1 && planner == 1 && run == 1) return core::PlanStatus::kNodeLimit;
  if (problem == 0 && planner == 1 && run == 2) return core::PlanStatus::kError;
  return run == 1 ? core::PlanStatus::kTimeout : core::PlanStatus::kSolved;
}

inline double expected_time(std::size_t index) { return 0.125 * static_cast<double>(index + 1); }

inline Trial make_trial(const Experiment& e, std::size_t index) {
  Trial t;
  const std::size_t per_problem = e.planners.size() * static_cast<std::size_t>(e.runs);
  t.id.index = index;
  t.id.problem = index / per_problem;
  t.id.planner = (index % per_problem) / static_cast<std::size_t>(e.runs);
  t.id.run = static_cast<int>(index % static_cast<std::size_t>(e.runs));
  t.seed = index == 0 ? 18446744073709551615ULL : 1000 + index;  // the largest seed must stay exact
  core::RunRecord& r = t.record;
  r.planner = e.planners[t.id.planner].label;
  r.problem = e.problems[t.id.problem].label;
  r.seed = t.seed;
  r.status = expected_status(t.id.problem, t.id.planner, t.id.run);
  if (r.status == core::PlanStatus::kError) r.message = "bad thing; on\nline two";
  r.wall_time_s = expected_time(index);
  r.cd_calls_training = 100 + index;
  r.cd_calls_planning = 10 + index;
  r.cd_calls_query = 1;
  r.nodes = 50 + index;
  r.edges = 70 + index;
  r.components = 2;
  r.lp_calls = 8;
  r.lp_successes = 6;
  if (r.status == core::PlanStatus::kSolved) {
    r.path_states = 5;
    r.path_length = 1.5 + static_cast<double>(index);
    r.path_clearance = 0.25;
  }
  if (t.id.planner == 0) {
    r.extra["node type A"] = 3.0;   // sanitised to node_type_A
    r.extra["nodes"] = 7.0;         // clashes with AMP's nodes: extra_nodes
  } else {
    t.drawn["k"] = t.id.run % 2 == 0 ? "5" : "10";
    if (t.id.run == 2) r.extra["regions"] = 4.0 + static_cast<double>(t.id.problem);  // first seen in run 2
  }
  return t;
}

inline RunInfo fixed_run_info() {
  RunInfo info;
  info.hostname = "testhost";
  info.cpu_info = "Test CPU @ 1 GHz (2 logical cores)";
  info.date = "2024-01-02T03:04:05Z";
  info.version = std::string("AMP ") + core::kVersion;
  info.threads = 2;
  return info;
}

// OMPL's checker: AMP_OMPL_DB_CHECK, tools/ in the repository, or ../shared/tools beside the source
// tree (as CI lays it out: nothing else is promised). Empty when none exists: the tests skip.
inline std::filesystem::path ompl_db_check() {
  if (const char* env = std::getenv("AMP_OMPL_DB_CHECK")) return env;
  const std::filesystem::path vendored = std::filesystem::path(AMP_SOURCE_DIR) / "tools" / "ompl-db-check";
  if (std::filesystem::exists(vendored)) return vendored;
  const std::filesystem::path beside = std::filesystem::path(AMP_SOURCE_DIR) / ".." / "shared" / "tools" / "ompl-db-check";
  if (std::filesystem::exists(beside)) return beside;
  return {};
}

// Skips the calling test, with the places looked at, when OMPL's checker is absent.
#define AMP_SKIP_WITHOUT_OMPL_DB_CHECK()                                                                    \
  if (::amp::bench::test::ompl_db_check().empty())                                                                \
  GTEST_SKIP() << "ompl-db-check not found (AMP_OMPL_DB_CHECK, tools/ or ../shared/tools beside the source " \
                  "tree): OMPL's benchmark-database check skipped"

// Runs the checker with `args`, its output going to `output`; returns its exit status.
inline int run_ompl_db_check(const std::string& args, const std::filesystem::path& output) {
  const std::string cmd = "python3 '" + ompl_db_check().string() + "' " + args + " > '" + output.string() + "' 2>&1";
  const int rc = std::system(cmd.c_str());
  return rc == -1 ? -1 : WEXITSTATUS(rc);
}

inline std::string read_text(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

// A typed SQLite value as text: "i:3", "r:0.5" (round-trip precision), "t:abc", "null".
inline std::string cell(sqlite3_stmt* s, int col) {
  switch (sqlite3_column_type(s, col)) {
    case SQLITE_INTEGER: return "i:" + std::to_string(sqlite3_column_int64(s, col));
    case SQLITE_FLOAT: {
      char buf[40];
      std::snprintf(buf, sizeof buf, "r:%.17g", sqlite3_column_double(s, col));
      return buf;
    }
    case SQLITE_TEXT: return "t:" + std::string(reinterpret_cast<const char*>(sqlite3_column_text(s, col)));
    case SQLITE_NULL: return "null";
    default: return "blob";
  }
}

// The rows of a query, each as column name -> cell (NULL cells left out, so that a column
// missing from one database equals a NULL in the other).
inline std::vector<std::map<std::string, std::string>> query(const std::filesystem::path& db, const std::string& sql) {
  sqlite3* c = nullptr;
  std::vector<std::map<std::string, std::string>> rows;
  if (sqlite3_open_v2(db.string().c_str(), &c, SQLITE_OPEN_READONLY, nullptr) != SQLITE_OK) {
    sqlite3_close(c);
    return rows;
  }
  sqlite3_stmt* s = nullptr;
  if (sqlite3_prepare_v2(c, sql.c_str(), -1, &s, nullptr) == SQLITE_OK) {
    while (sqlite3_step(s) == SQLITE_ROW) {
      std::map<std::string, std::string> row;
      for (int i = 0; i < sqlite3_column_count(s); ++i) {
        const std::string v = cell(s, i);
        if (v != "null") row[sqlite3_column_name(s, i)] = v;
      }
      rows.push_back(std::move(row));
    }
  } else {
    rows.push_back({{"error", sqlite3_errmsg(c)}});
  }
  sqlite3_finalize(s);
  sqlite3_close(c);
  return rows;
}

}  // namespace amp::bench::test
