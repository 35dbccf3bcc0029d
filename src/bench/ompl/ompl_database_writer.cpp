#include "amp/bench/ompl_database_writer.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <system_error>

#include <sqlite3.h>

#include "amp/core/error.hpp"
#include "bench/ompl/ompl_properties.hpp"

namespace amp::bench {

namespace {

// The schema exactly as readBenchmarkLog() in ompl_benchmark_statistics.py creates it.
constexpr const char* kSchema = R"(CREATE TABLE IF NOT EXISTS experiments
    (id INTEGER PRIMARY KEY AUTOINCREMENT, name VARCHAR(512),
    totaltime REAL, timelimit REAL, memorylimit REAL, runcount INTEGER,
    version VARCHAR(128), hostname VARCHAR(1024), cpuinfo TEXT,
    date DATETIME, seed VARCHAR(24), setup TEXT);
    CREATE TABLE IF NOT EXISTS plannerConfigs
    (id INTEGER PRIMARY KEY AUTOINCREMENT,
    name VARCHAR(512) NOT NULL, settings TEXT);
    CREATE TABLE IF NOT EXISTS enums
    (name VARCHAR(512), value INTEGER, description TEXT,
    PRIMARY KEY (name, value));
    CREATE TABLE IF NOT EXISTS runs
    (id INTEGER PRIMARY KEY AUTOINCREMENT, experimentid INTEGER, plannerid INTEGER,
    FOREIGN KEY (experimentid) REFERENCES experiments(id) ON DELETE CASCADE,
    FOREIGN KEY (plannerid) REFERENCES plannerConfigs(id) ON DELETE CASCADE);
    CREATE TABLE IF NOT EXISTS progress
    (runid INTEGER, time REAL, PRIMARY KEY (runid, time),
    FOREIGN KEY (runid) REFERENCES runs(id) ON DELETE CASCADE);)";

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s;
}

std::string quoted(const std::string& identifier) { return '"' + identifier + '"'; }

}  // namespace

void OmplDatabaseWriter::StatementDeleter::operator()(sqlite3_stmt* s) const { sqlite3_finalize(s); }

OmplDatabaseWriter::OmplDatabaseWriter(std::filesystem::path db, const Experiment& e, const RunInfo& info)
    : path_(std::move(db)), experiment_(e) {
  std::error_code ec;
  if (std::filesystem::exists(path_, ec)) {
    throw FileError(path_.string() + ": the OMPL database already exists (remove it or choose another name)");
  }
  if (sqlite3_open_v2(path_.string().c_str(), &db_, SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE, nullptr) !=
      SQLITE_OK) {
    const std::string msg = db_ ? sqlite3_errmsg(db_) : "out of memory";
    close();
    throw FileError(path_.string() + ": cannot create the OMPL database: " + msg);
  }
  try {
    create_schema(info);
    exec("BEGIN");
  } catch (...) {
    // A half-made database would make the next attempt refuse the path.
    close();
    std::filesystem::remove(path_, ec);
    throw;
  }
}

OmplDatabaseWriter::~OmplDatabaseWriter() { close(); }

void OmplDatabaseWriter::close() noexcept {
  inserts_.clear();
  if (db_) sqlite3_close_v2(db_);  // rolls back an open transaction
  db_ = nullptr;
}

void OmplDatabaseWriter::fail(const std::string& what) const {
  throw FileError(path_.string() + ": " + what + ": " + (db_ ? sqlite3_errmsg(db_) : "database closed"));
}

void OmplDatabaseWriter::exec(const std::string& sql) {
  char* err = nullptr;
  if (sqlite3_exec(db_, sql.c_str(), nullptr, nullptr, &err) != SQLITE_OK) {
    const std::string msg = err ? err : "unknown error";
    sqlite3_free(err);
    throw FileError(path_.string() + ": SQL '" + sql.substr(0, 60) + "' failed: " + msg);
  }
}

OmplDatabaseWriter::Statement OmplDatabaseWriter::prepare(const std::string& sql) {
  sqlite3_stmt* s = nullptr;
  if (sqlite3_prepare_v2(db_, sql.c_str(), -1, &s, nullptr) != SQLITE_OK) fail("cannot prepare '" + sql + "'");
  return Statement(s);
}

void OmplDatabaseWriter::step_done(sqlite3_stmt* s, const char* what) {
  if (sqlite3_step(s) != SQLITE_DONE) fail(std::string("cannot write ") + what);
  sqlite3_reset(s);
  sqlite3_clear_bindings(s);
}

void OmplDatabaseWriter::ensure_column(const std::string& table, const std::string& column, const std::string& type) {
  exec("ALTER TABLE " + table + " ADD COLUMN " + quoted(column) + " " + type);
}

namespace {

void bind_value(sqlite3_stmt* s, int index, const ompl::SqlValue& v) {
  if (const auto* d = std::get_if<double>(&v)) {
    if (std::isfinite(*d)) {
      sqlite3_bind_double(s, index, *d);
    } else {
      sqlite3_bind_null(s, index);  // as the log parser reads "nan" and "inf"
    }
  } else if (const auto* i = std::get_if<std::int64_t>(&v)) {
    sqlite3_bind_int64(s, index, *i);
  } else if (const auto* t = std::get_if<std::string>(&v)) {
    sqlite3_bind_text(s, index, t->c_str(), static_cast<int>(t->size()), SQLITE_TRANSIENT);
  } else {
    sqlite3_bind_null(s, index);
  }
}

}  // namespace

void OmplDatabaseWriter::create_schema(const RunInfo& info) {
  exec("PRAGMA foreign_keys = ON");
  exec("BEGIN");
  exec(kSchema);
  for (const char* c : {"id", "experimentid", "plannerid"}) run_columns_.insert(c);

  Statement enums = prepare("INSERT INTO enums VALUES ('status', ?, ?)");
  for (std::size_t i = 0; i < ompl::kStatusNames.size(); ++i) {
    sqlite3_bind_int64(enums.get(), 1, static_cast<sqlite3_int64>(i));
    bind_value(enums.get(), 2, std::string(ompl::kStatusNames[i]));
    step_done(enums.get(), "the enums table");
  }

  const Experiment& e = experiment_;
  std::set<std::string> experiment_columns;
  for (std::size_t i = 0; i < e.problems.size(); ++i) {
    for (const auto& p : ompl::experiment_properties(e, i, info)) {
      if (experiment_columns.insert(ompl::column_name(p)).second) {
        ensure_column("experiments", ompl::column_name(p), std::string(ompl::to_string(p.type)));
      }
    }
  }
  const auto [library, version_number] = ompl::version_words(info);
  const std::string version = library + " " + version_number;
  for (std::size_t i = 0; i < e.problems.size(); ++i) {
    std::string cols = "name, totaltime, timelimit, memorylimit, runcount, version, hostname, cpuinfo, date, seed, setup";
    std::string marks = "?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?";
    const auto props = ompl::experiment_properties(e, i, info);
    for (const auto& p : props) {
      cols += ", " + quoted(ompl::column_name(p));
      marks += ", ?";
    }
    Statement s = prepare("INSERT INTO experiments (" + cols + ") VALUES (" + marks + ")");
    bind_value(s.get(), 1, ompl::experiment_name(e.problems[i]));
    bind_value(s.get(), 2, 0.0);  // set in finish()
    bind_value(s.get(), 3, e.time_limit_s);
    bind_value(s.get(), 4, 0.0);  // no memory limit
    bind_value(s.get(), 5, std::int64_t{e.runs});
    bind_value(s.get(), 6, version);
    bind_value(s.get(), 7, ompl::field_text(info.hostname.empty() ? "UNKNOWN" : info.hostname));
    bind_value(s.get(), 8, ompl::block_text(info.cpu_info));
    bind_value(s.get(), 9, ompl::field_text(info.date));
    bind_value(s.get(), 10, std::to_string(e.seed));
    bind_value(s.get(), 11, ompl::setup_text(e.problems[i]));
    int index = 12;
    for (const auto& p : props) bind_value(s.get(), index++, p.value);
    step_done(s.get(), "the experiments table");
    experiment_ids_.push_back(sqlite3_last_insert_rowid(db_));
  }
  total_time_s_.assign(e.problems.size(), 0.0);

  Statement planners = prepare("INSERT INTO plannerConfigs (name, settings) VALUES (?, ?)");
  for (const auto& c : e.planners) {
    bind_value(planners.get(), 1, ompl::planner_name(c));
    bind_value(planners.get(), 2, ompl::settings_text(c));
    step_done(planners.get(), "the plannerConfigs table");
    planner_ids_.push_back(sqlite3_last_insert_rowid(db_));
  }
  exec("COMMIT");
}

void OmplDatabaseWriter::add(const Trial& trial) {
  if (!db_ || finished_) throw Error(path_.string() + ": trial added after the OMPL database was finished");
  if (trial.id.problem >= experiment_ids_.size() || trial.id.planner >= planner_ids_.size()) {
    throw Error(path_.string() + ": trial " + std::to_string(trial.id.index) + " names problem " +
                std::to_string(trial.id.problem) + ", planner " + std::to_string(trial.id.planner) +
                ", outside the experiment");
  }
  const auto props = ompl::run_properties(experiment_, trial);
  std::string key = "experimentid, plannerid";
  for (const auto& p : props) {
    const std::string col = ompl::column_name(p);
    if (run_columns_.insert(lower(col)).second) ensure_column("runs", col, std::string(ompl::to_string(p.type)));
    key += ", " + quoted(col);
  }
  auto it = inserts_.find(key);
  if (it == inserts_.end()) {
    std::string marks = "?, ?";
    for (std::size_t i = 0; i < props.size(); ++i) marks += ", ?";
    it = inserts_.emplace(key, prepare("INSERT INTO runs (" + key + ") VALUES (" + marks + ")")).first;
  }
  sqlite3_stmt* s = it->second.get();
  sqlite3_bind_int64(s, 1, experiment_ids_[trial.id.problem]);
  sqlite3_bind_int64(s, 2, planner_ids_[trial.id.planner]);
  int index = 3;
  for (const auto& p : props) bind_value(s, index++, p.value);
  step_done(s, "a run");
  total_time_s_[trial.id.problem] += trial.record.wall_time_s;
  if (++rows_in_transaction_ >= kRowsPerTransaction) {
    exec("COMMIT");
    exec("BEGIN");
    rows_in_transaction_ = 0;
  }
}

void OmplDatabaseWriter::finish() {
  if (finished_) return;
  if (!db_) fail("cannot finish");
  // OMPL's totaltime is the time spent collecting one experiment's data; AMP runs problems
  // interleaved on several threads, so it is the sum of the problem's run times.
  Statement s = prepare("UPDATE experiments SET totaltime = ? WHERE id = ?");
  for (std::size_t i = 0; i < experiment_ids_.size(); ++i) {
    sqlite3_bind_double(s.get(), 1, total_time_s_[i]);
    sqlite3_bind_int64(s.get(), 2, experiment_ids_[i]);
    step_done(s.get(), "the experiments' total times");
  }
  s.reset();
  exec("COMMIT");
  inserts_.clear();
  if (sqlite3_close(db_) != SQLITE_OK) fail("cannot close");
  db_ = nullptr;
  finished_ = true;
}

}  // namespace amp::bench
