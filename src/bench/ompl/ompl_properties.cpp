#include "bench/ompl/ompl_properties.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "amp/core/error.hpp"
#include "amp/core/number_text.hpp"

namespace amp::bench::ompl {

namespace {

// Columns every run row may have, whether or not this run has them, so that an extra is renamed
// the same way in every row (lower case: SQLite compares column names without case).
const std::set<std::string>& reserved_columns() {
  static const std::set<std::string> kReserved = {
      "id", "experimentid", "plannerid", "time", "memory", "status", "solved", "approximate_solution",
      "solution_length", "solution_clearance", "solution_segments", "graph_states", "graph_motions",
      "valid_segment_fraction", "collision_checks", "amp_status", "message", "run", "seed",
      "cd_calls_training", "cd_calls_planning", "cd_calls_query", "clearance_calls", "nodes", "edges",
      "components", "lp_calls", "lp_successes", "path_states"};
  return kReserved;
}

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s;
}

// A name usable as one log word and one SQL column: letters, digits and '_', not starting with a digit.
std::string identifier(std::string_view s) {
  std::string out;
  for (unsigned char c : s) out += std::isalnum(c) ? static_cast<char>(c) : '_';
  if (out.empty() || std::isdigit(static_cast<unsigned char>(out.front()))) out.insert(out.begin(), '_');
  return out;
}

bool parse_double(std::string_view s, double& x) {
  const char* end = s.data() + s.size();
  auto [ptr, ec] = std::from_chars(s.data(), end, x);
  return ec == std::errc() && ptr == end && !s.empty();
}

std::int64_t as_int(std::uint64_t v) { return static_cast<std::int64_t>(v); }

// Drawn parameters come from YAML as text; a column is REAL when every value it can take is a number.
SqlType draw_type(const PlannerConfig& c, const std::string& name) {
  auto it = c.draws.find(name);
  if (it == c.draws.end()) return SqlType::kText;
  double x = 0.0;
  for (const auto& v : it->second) {
    if (!v.is_number() && !parse_double(v.string(), x)) return SqlType::kText;
  }
  return SqlType::kReal;
}

}  // namespace

std::string_view to_string(SqlType t) {
  switch (t) {
    case SqlType::kReal: return "REAL";
    case SqlType::kInteger: return "INTEGER";
    case SqlType::kBoolean: return "BOOLEAN";
    case SqlType::kEnum: return "ENUM";
    case SqlType::kText: return "TEXT";
  }
  return "TEXT";
}

std::string column_name(const Property& p) {
  std::string c = p.words;
  std::replace(c.begin(), c.end(), ' ', '_');
  return c;
}

std::string log_key(const Property& p) { return p.words + " " + std::string(to_string(p.type)); }

std::string log_value(const SqlValue& v) {
  if (const auto* d = std::get_if<double>(&v)) return std::isfinite(*d) ? core::number_text(*d) : std::string();
  if (const auto* i = std::get_if<std::int64_t>(&v)) return std::to_string(*i);
  if (const auto* s = std::get_if<std::string>(&v)) return field_text(*s);
  return {};
}

int ompl_status(core::PlanStatus s) {
  constexpr int kTimeout = 4, kExactSolution = 6, kCrash = 7, kAbort = 8, kInfeasible = 9;
  switch (s) {
    case core::PlanStatus::kSolved: return kExactSolution;
    case core::PlanStatus::kTimeout: return kTimeout;
    case core::PlanStatus::kNodeLimit: return kAbort;
    case core::PlanStatus::kUnsolvable: return kInfeasible;
    case core::PlanStatus::kError: return kCrash;
  }
  return kCrash;
}

std::vector<Property> run_properties(const Experiment& e, const Trial& t) {
  const core::RunRecord& r = t.record;
  const bool solved = r.status == core::PlanStatus::kSolved;
  std::vector<Property> p;
  auto add = [&p](std::string words, SqlType type, SqlValue v) { p.push_back({std::move(words), type, std::move(v)}); };
  // OMPL's standard properties (Benchmark.cpp); memory is not measured per run, so it is NULL.
  add("time", SqlType::kReal, r.wall_time_s);
  add("memory", SqlType::kReal, std::monostate{});
  add("status", SqlType::kEnum, std::int64_t{ompl_status(r.status)});
  add("solved", SqlType::kBoolean, std::int64_t{solved});
  // As OMPL, the solution's properties exist only for runs that found one.
  if (solved) {
    add("approximate solution", SqlType::kBoolean, std::int64_t{0});
    add("solution length", SqlType::kReal, r.path_length);
    add("solution clearance", SqlType::kReal, r.path_clearance);
    add("solution segments", SqlType::kInteger, as_int(r.path_states > 0 ? r.path_states - 1 : 0));
  }
  add("graph states", SqlType::kInteger, as_int(r.nodes));
  add("graph motions", SqlType::kInteger, as_int(r.edges));
  // OMPL's MotionValidator::getValidMotionFraction(): 0 when no motion was checked.
  add("valid segment fraction", SqlType::kReal,
      r.lp_calls == 0 ? 0.0 : static_cast<double>(r.lp_successes) / static_cast<double>(r.lp_calls));
  add("collision checks", SqlType::kInteger, as_int(r.cd_calls()));
  // AMP's own record.
  add("amp_status", SqlType::kText, std::string(core::to_string(r.status)));
  if (!r.message.empty()) add("message", SqlType::kText, field_text(r.message));
  add("run", SqlType::kInteger, std::int64_t{t.id.run});
  add("seed", SqlType::kText, std::to_string(t.seed));  // text: a uint64 does not fit SQLite's INTEGER
  add("cd_calls_training", SqlType::kInteger, as_int(r.cd_calls_training));
  add("cd_calls_planning", SqlType::kInteger, as_int(r.cd_calls_planning));
  add("cd_calls_query", SqlType::kInteger, as_int(r.cd_calls_query));
  add("clearance_calls", SqlType::kInteger, as_int(r.clearance_calls));
  add("nodes", SqlType::kInteger, as_int(r.nodes));
  add("edges", SqlType::kInteger, as_int(r.edges));
  add("components", SqlType::kInteger, as_int(r.components));
  add("lp_calls", SqlType::kInteger, as_int(r.lp_calls));
  add("lp_successes", SqlType::kInteger, as_int(r.lp_successes));
  add("path_states", SqlType::kInteger, as_int(r.path_states));

  std::set<std::string> used;
  for (const auto& q : p) used.insert(lower(column_name(q)));
  const PlannerConfig& config = e.planners.at(t.id.planner);
  for (const auto& [name, value] : t.drawn) {
    const std::string col = "param_" + identifier(name);
    if (!used.insert(lower(col)).second) continue;  // two names that sanitise alike: keep the first
    const SqlType type = draw_type(config, name);
    double x = 0.0;
    if (type == SqlType::kReal && parse_double(value, x)) {
      add(col, type, x);
    } else {
      add(col, type, field_text(value));
    }
  }
  for (const auto& [name, value] : t.record.extra) {
    std::string col = identifier(name);
    if (reserved_columns().count(lower(col)) || used.count(lower(col))) col = "extra_" + col;
    if (!used.insert(lower(col)).second) continue;
    add(col, SqlType::kReal, value);
  }
  return p;
}

std::vector<Property> experiment_properties(const Experiment& e, std::size_t problem, const RunInfo& info) {
  // The log parser cannot read an empty value, so an empty property is left out (in both formats).
  std::vector<Property> p;
  auto text = [&p](std::string words, std::string v) {
    v = field_text(v);
    // The parser splits "name TYPE = value" at " = ".
    for (std::size_t at = v.find(" = "); at != std::string::npos; at = v.find(" = ", at)) v.erase(at + 2, 1);  // " ="
    if (!v.empty()) p.push_back({std::move(words), SqlType::kText, std::move(v)});
  };
  text("amp_experiment", e.name);
  text("experiment_file", e.file.string());
  text("fingerprint", e.fingerprint);
  text("problem_file", e.problems.at(problem).file.string());
  // Left out when not given: the limit is then the problem's or each planner's own.
  if (e.node_limit) p.push_back({"node_limit", SqlType::kInteger, static_cast<std::int64_t>(*e.node_limit)});
  p.push_back({"threads", SqlType::kInteger, std::int64_t{info.threads}});
  return p;
}

std::string experiment_name(const ExperimentProblem& p) {
  std::string s = field_text(p.label);
  for (char& c : s) {
    if (std::isspace(static_cast<unsigned char>(c))) c = '_';
  }
  return s.empty() ? std::string("NO_NAME") : s;
}

std::string planner_name(const PlannerConfig& c) { return "geometric_" + field_text(c.label); }

std::vector<std::pair<std::string, std::string>> common_properties(const PlannerConfig& c) {
  std::map<std::string, std::string> m;
  m["amp_planner"] = c.planner;
  for (const auto& [name, value] : c.params) m[name] = value.to_string();
  for (const auto& [name, values] : c.draws) {
    std::string list = "drawn from {";
    for (std::size_t i = 0; i < values.size(); ++i) list += (i ? ", " : "") + values[i].to_string();
    m[name] = list + "}";
  }
  std::vector<std::pair<std::string, std::string>> out;
  for (const auto& [k, v] : m) out.emplace_back(field_text(k), field_text(v));
  return out;
}

std::string settings_text(const PlannerConfig& c) {
  std::string s;
  for (const auto& [k, v] : common_properties(c)) s += k + " = " + v + "\n;";
  return s;
}

std::string setup_text(const ExperimentProblem& p) {
  std::ifstream in(p.file, std::ios::binary);
  if (!in) throw FileError(p.file.string() + ": cannot read the problem file of problem '" + p.label + "'");
  std::stringstream ss;
  ss << in.rdbuf();
  return block_text(ss.str());
}

std::pair<std::string, std::string> version_words(const RunInfo& info) {
  std::istringstream in(field_text(info.version));
  std::vector<std::string> words;
  for (std::string w; in >> w;) words.push_back(w);
  if (words.empty()) return {"AMP", "0.0.0"};
  if (words.size() == 1) return {"AMP", words.front()};
  return {words.front(), words.back()};
}

std::string block_text(std::string_view s) {
  std::string out;
  std::size_t start = 0;
  while (start < s.size()) {
    std::size_t end = s.find('\n', start);
    if (end == std::string_view::npos) end = s.size();
    std::string_view line = s.substr(start, end - start);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    if (line.starts_with("|>>>")) out += ' ';  // would end the block early
    out.append(line);
    out += '\n';
    start = end + 1;
  }
  return out;
}

std::string field_text(std::string_view s) {
  std::string out;
  for (unsigned char c : s) out += (c < 0x20 || c == 0x7f) ? ' ' : (c == ';' ? ',' : static_cast<char>(c));
  while (!out.empty() && out.back() == ' ') out.pop_back();  // the parser strips lines
  const std::size_t first = out.find_first_not_of(' ');
  return first == std::string::npos ? std::string() : out.substr(first);
}

}  // namespace amp::bench::ompl
