#include "amp/bench/runs_csv.hpp"

#include <charconv>
#include <cmath>
#include <set>

#include "amp/core/error.hpp"
#include "amp/core/number_text.hpp"

namespace amp::bench {

namespace {

constexpr const char* kFixedColumns[] = {
    "trial", "problem", "planner", "planner_type", "run", "seed", "status", "wall_time_s", "cd_calls",
    "cd_calls_training", "cd_calls_planning", "cd_calls_query", "clearance_calls", "nodes", "edges", "components",
    "lp_calls", "lp_successes", "path_states", "path_length", "path_clearance"};
constexpr std::size_t kFixedCount = std::size(kFixedColumns);

std::vector<std::string> drawn_names(const Experiment& e) {
  std::set<std::string> names;
  for (const auto& c : e.planners) {
    for (const auto& [k, v] : c.draws) names.insert(k);
  }
  return {names.begin(), names.end()};
}

std::string quoted(const std::string& s) {
  if (s.find_first_of(",\"\n\r") == std::string::npos) return s;
  std::string out = "\"";
  for (char c : s) {
    if (c == '"') out += '"';
    out += c;
  }
  return out + '"';
}

// Splits one CSV record; `line` may hold quoted newlines already joined by the caller.
std::vector<std::string> split_record(const std::string& line) {
  std::vector<std::string> fields(1);
  bool in_quotes = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (in_quotes) {
      if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
        fields.back() += '"';
        ++i;
      } else if (c == '"') {
        in_quotes = false;
      } else {
        fields.back() += c;
      }
    } else if (c == '"') {
      in_quotes = true;
    } else if (c == ',') {
      fields.emplace_back();
    } else {
      fields.back() += c;
    }
  }
  return fields;
}

bool quotes_balanced(const std::string& s) {
  std::size_t n = 0;
  for (char c : s) n += c == '"';
  return n % 2 == 0;
}

template <class T>
T parse_number(const std::string& s, const std::filesystem::path& file, std::size_t row, const char* column) {
  T v{};
  const auto r = std::from_chars(s.data(), s.data() + s.size(), v);
  if (r.ec != std::errc() || r.ptr != s.data() + s.size()) {
    throw FileError(file.string() + ": row " + std::to_string(row) + ": column " + column + ": not a number '" + s + "'");
  }
  return v;
}

}  // namespace

std::vector<std::string> runs_csv_header(const Experiment& e) {
  std::vector<std::string> h(std::begin(kFixedColumns), std::end(kFixedColumns));
  for (const auto& n : drawn_names(e)) h.push_back("param." + n);
  h.emplace_back("extra");
  h.emplace_back("message");
  return h;
}

RunsCsvWriter::RunsCsvWriter(const std::filesystem::path& file, const Experiment& e, bool append)
    : file_(file), experiment_(e), drawn_names_(drawn_names(e)) {
  out_.open(file, append ? std::ios::app | std::ios::binary : std::ios::trunc | std::ios::binary);
  if (!out_) throw FileError(file.string() + ": cannot open for writing");
  if (!append) {
    const auto h = runs_csv_header(e);
    for (std::size_t i = 0; i < h.size(); ++i) out_ << (i ? "," : "") << h[i];
    out_ << '\n';
  }
}

void RunsCsvWriter::add(const Trial& t) {
  const core::RunRecord& r = t.record;
  std::string row;
  row.reserve(256);
  auto put = [&](const std::string& s) {
    if (!row.empty()) row += ',';
    row += quoted(s);
  };
  put(std::to_string(t.id.index));
  put(experiment_.problems[t.id.problem].label);
  put(experiment_.planners[t.id.planner].label);
  put(experiment_.planners[t.id.planner].planner);
  put(std::to_string(t.id.run));
  put(std::to_string(t.seed));
  put(std::string(core::to_string(r.status)));
  put(core::number_text(r.wall_time_s));
  for (std::uint64_t v : {r.cd_calls(), r.cd_calls_training, r.cd_calls_planning, r.cd_calls_query, r.clearance_calls,
                          r.nodes, r.edges, r.components, r.lp_calls, r.lp_successes, r.path_states}) {
    put(std::to_string(v));
  }
  put(core::number_text(r.path_length));
  put(core::number_text(r.path_clearance));
  for (const auto& n : drawn_names_) {
    const auto it = t.drawn.find(n);
    put(it == t.drawn.end() ? "" : it->second);
  }
  std::string extra;
  for (const auto& [k, v] : r.extra) extra += (extra.empty() ? "" : ";") + k + "=" + core::number_text(v);
  put(extra);
  put(r.message);
  row += '\n';
  out_ << row;
  // Flush per row: an interrupted run keeps every finished trial (rows are short; cost is negligible
  // against a planner run).
  out_.flush();
  if (!out_) throw FileError(file_.string() + ": write failed");
}

void RunsCsvWriter::finish() {
  out_.close();
  if (out_.fail()) throw FileError(file_.string() + ": write failed");
}

RunsCsvReader::RunsCsvReader(const std::filesystem::path& file, const Experiment& e)
    : file_(file), experiment_(e), in_(file, std::ios::binary), header_(runs_csv_header(e)) {
  if (!in_) throw FileError(file.string() + ": cannot open");
  std::string line;
  if (!std::getline(in_, line) || in_.eof()) throw FileError(file.string() + ": empty or without a header");
  consumed_ = line.size() + 1;
  if (split_record(line) != header_) {
    throw FileError(file.string() + ": its columns are not those of experiment '" + e.name +
                    "' (results of another experiment?)");
  }
  for (std::size_t i = kFixedCount; i + 2 < header_.size(); ++i) drawn_.push_back(header_[i].substr(6));
}

bool RunsCsvReader::next(Trial& t) {
  const std::filesystem::path& file = file_;
  const Experiment& e = experiment_;
  std::string line;
  if (!std::getline(in_, line) || in_.eof()) return false;  // no newline: a row cut short
  std::uintmax_t bytes = line.size() + 1;
  std::string record = line;
  while (!quotes_balanced(record)) {  // a quoted field with newlines
    if (!std::getline(in_, line) || in_.eof()) return false;
    record += '\n' + line;
    bytes += line.size() + 1;
  }
  const std::size_t row = ++row_;
  const std::vector<std::string> f = split_record(record);
  if (f.size() != header_.size()) {
    throw FileError(file.string() + ": row " + std::to_string(row) + ": expected " + std::to_string(header_.size()) +
                    " fields, got " + std::to_string(f.size()));
  }
  t = Trial{};
  const auto index = parse_number<std::size_t>(f[0], file, row, "trial");
  if (index >= e.trial_count()) throw FileError(file.string() + ": row " + std::to_string(row) + ": trial out of range");
  t.id = trial_id(e, index);
  if (f[1] != e.problems[t.id.problem].label || f[2] != e.planners[t.id.planner].label) {
    throw FileError(file.string() + ": row " + std::to_string(row) + ": trial " + f[0] +
                    " does not belong to this experiment");
  }
  t.seed = parse_number<std::uint64_t>(f[5], file, row, "seed");
  core::RunRecord& r = t.record;
  r.problem = f[1];
  r.planner = f[2];
  r.seed = t.seed;
  try {
    r.status = core::plan_status_from_string(f[6]);
  } catch (const Error&) {
    throw FileError(file.string() + ": row " + std::to_string(row) + ": unknown status '" + f[6] + "'");
  }
  r.wall_time_s = parse_number<double>(f[7], file, row, "wall_time_s");
  r.cd_calls_training = parse_number<std::uint64_t>(f[9], file, row, "cd_calls_training");
  r.cd_calls_planning = parse_number<std::uint64_t>(f[10], file, row, "cd_calls_planning");
  r.cd_calls_query = parse_number<std::uint64_t>(f[11], file, row, "cd_calls_query");
  r.clearance_calls = parse_number<std::uint64_t>(f[12], file, row, "clearance_calls");
  r.nodes = parse_number<std::uint64_t>(f[13], file, row, "nodes");
  r.edges = parse_number<std::uint64_t>(f[14], file, row, "edges");
  r.components = parse_number<std::uint64_t>(f[15], file, row, "components");
  r.lp_calls = parse_number<std::uint64_t>(f[16], file, row, "lp_calls");
  r.lp_successes = parse_number<std::uint64_t>(f[17], file, row, "lp_successes");
  r.path_states = parse_number<std::uint64_t>(f[18], file, row, "path_states");
  r.path_length = parse_number<double>(f[19], file, row, "path_length");
  r.path_clearance = parse_number<double>(f[20], file, row, "path_clearance");
  for (std::size_t i = 0; i < drawn_.size(); ++i) {
    if (!f[kFixedCount + i].empty()) t.drawn[drawn_[i]] = f[kFixedCount + i];
  }
  const std::string& extra = f[header_.size() - 2];
  std::size_t pos = 0;
  while (pos < extra.size()) {
    const std::size_t end = std::min(extra.find(';', pos), extra.size());
    const std::string item = extra.substr(pos, end - pos);
    const std::size_t eq = item.find('=');
    if (eq == std::string::npos) {
      throw FileError(file.string() + ": row " + std::to_string(row) + ": bad extra '" + item + "'");
    }
    r.extra[item.substr(0, eq)] = parse_number<double>(item.substr(eq + 1), file, row, "extra");
    pos = end + 1;
  }
  r.message = f.back();
  consumed_ += bytes;
  return true;
}

void for_each_trial(const std::filesystem::path& file, const Experiment& e, const std::function<void(const Trial&)>& fn,
                    std::uintmax_t* complete_bytes) {
  RunsCsvReader reader(file, e);
  Trial t;
  while (reader.next(t)) fn(t);
  if (complete_bytes != nullptr) *complete_bytes = reader.complete_bytes();
}

}  // namespace amp::bench
