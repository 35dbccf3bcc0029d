#pragma once
// What OMPL's benchmark formats record about an experiment, a planner configuration and a run,
// shared by OmplDatabaseWriter and OmplLogWriter so that writing the database directly and
// writing a log that ompl_benchmark_statistics.py parses give the same rows.
#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

#include "amp/bench/experiment.hpp"
#include "amp/bench/trial_sink.hpp"

namespace amp::bench::ompl {

// The SQL types OMPL's log names after a property ("time REAL", "status ENUM"). TEXT, not OMPL's
// STRING: SQLite gives a STRING column numeric affinity, which would turn a 20-digit seed into a REAL.
enum class SqlType { kReal, kInteger, kBoolean, kEnum, kText };
std::string_view to_string(SqlType t);

using SqlValue = std::variant<std::monostate, double, std::int64_t, std::string>;  // monostate = NULL

// One property. `words` is the name as OMPL writes it in the log ("solution length"); the database
// column is the words joined by '_' ("solution_length"), as OMPL's log parser makes it.
struct Property {
  std::string words;
  SqlType type = SqlType::kReal;
  SqlValue value;
};

std::string column_name(const Property& p);
// "solution length REAL": the line naming the property in a log.
std::string log_key(const Property& p);
// The value as a log field: "" for NULL and for non-finite numbers (the parser's NULL).
std::string log_value(const SqlValue& v);

// OMPL's PlannerStatus::asString() names, in StatusType order (the `enums` table, name "status").
inline constexpr std::array<std::string_view, 10> kStatusNames = {
    "Unknown status", "Invalid start", "Invalid goal", "Unrecognized goal type", "Timeout",
    "Approximate solution", "Exact solution", "Crash", "Abort", "Infeasible"};
// solved -> EXACT_SOLUTION, timeout -> TIMEOUT, node_limit -> ABORT (a budget other than time),
// unsolvable -> INFEASIBLE, error -> CRASH. The AMP status is also kept in `amp_status`.
int ompl_status(core::PlanStatus s);

// The run's row: OMPL's standard properties, AMP's record fields, the drawn parameters (param_<name>)
// and the planner's extras (sanitised names; extra_<name> where one would clash with another column).
std::vector<Property> run_properties(const Experiment& e, const Trial& t);

// Experiment-level properties beyond OMPL's fixed columns (the log's "experiment properties").
std::vector<Property> experiment_properties(const Experiment& e, std::size_t problem, const RunInfo& info);

// OMPL's unit of an experiment is one problem; its name is the problem label (no blanks, since the
// log parser keeps only the last word of "Experiment <name>").
std::string experiment_name(const ExperimentProblem& p);
// "geometric_" + label, as OMPL names a geometric planner.
std::string planner_name(const PlannerConfig& c);
// The configuration as OMPL's "common properties": sorted "key", "value" pairs.
std::vector<std::pair<std::string, std::string>> common_properties(const PlannerConfig& c);
// The settings text OMPL's log parser stores for those properties: "key = value\n;" per property.
std::string settings_text(const PlannerConfig& c);
// The problem file's text, made safe for a <<<| ... |>>> block. Throws FileError if unreadable.
std::string setup_text(const ExperimentProblem& p);
// The library name and version number, as the log's "<library> version <number>" line gives them
// (the database stores "<library> <number>").
std::pair<std::string, std::string> version_words(const RunInfo& info);
// Text made safe for a <<<| ... |>>> block: ends in a newline, no line starts with "|>>>".
std::string block_text(std::string_view s);
// Text made safe for a one-line log field: no control characters, no ';'.
std::string field_text(std::string_view s);

}  // namespace amp::bench::ompl
