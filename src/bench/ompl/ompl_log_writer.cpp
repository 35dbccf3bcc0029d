#include "amp/bench/ompl_log_writer.hpp"

#include <cctype>
#include <map>
#include <system_error>

#include "amp/core/error.hpp"
#include "amp/core/number_text.hpp"
#include "bench/ompl/ompl_properties.hpp"

namespace amp::bench {

namespace {

// Separators of the temporary runs file; field_text() keeps control characters out of values.
constexpr char kKeyEnd = '\x1f';
constexpr char kFieldEnd = '\x1e';

std::string file_label(const std::string& label) {
  std::string s;
  for (unsigned char c : label) s += (std::isalnum(c) || c == '-' || c == '_' || c == '.') ? static_cast<char>(c) : '_';
  return s.empty() || s.front() == '.' ? "_" + s : s;
}

// A planner's name and configuration ("common properties"), which start its part of a log.
void write_planner_start(std::ostream& out, const PlannerConfig& c) {
  out << ompl::planner_name(c) << '\n';
  const auto common = ompl::common_properties(c);
  out << common.size() << " common properties\n";
  for (const auto& [k, v] : common) out << k << " = " << v << '\n';
}

void write_empty_section(std::ostream& out, const PlannerConfig& c) {
  write_planner_start(out, c);
  out << "0 properties for each run\n0 runs\n.\n";
}

}  // namespace

std::vector<std::filesystem::path> OmplLogWriter::log_paths(const std::filesystem::path& log_dir_or_file,
                                                            const Experiment& e) {
  std::vector<std::filesystem::path> paths;
  const bool single_file = log_dir_or_file.extension() == ".log";
  std::set<std::string> used;
  for (std::size_t i = 0; i < e.problems.size(); ++i) {
    std::string name = file_label(e.problems[i].label);
    // Labels are unique but may sanitise alike.
    for (int n = 2; !used.insert(name).second; ++n) name = file_label(e.problems[i].label) + "_" + std::to_string(n);
    if (single_file && e.problems.size() == 1) {
      paths.push_back(log_dir_or_file);
    } else if (single_file) {
      paths.push_back(log_dir_or_file.parent_path() / (log_dir_or_file.stem().string() + "_" + name + ".log"));
    } else {
      paths.push_back(log_dir_or_file / (name + ".log"));
    }
  }
  return paths;
}

OmplLogWriter::OmplLogWriter(std::filesystem::path log_dir_or_file, const Experiment& e, const RunInfo& info)
    : experiment_(e), info_(info), files_(log_paths(log_dir_or_file, e)) {
  std::error_code ec;
  for (const auto& f : files_) {
    if (std::filesystem::exists(f, ec)) fail(f, "the OMPL log already exists (remove it or choose another name)");
    const auto dir = f.parent_path();
    if (!dir.empty() && !std::filesystem::is_directory(dir, ec)) {
      std::filesystem::create_directories(dir, ec);
      if (ec) fail(dir, "cannot create the directory for OMPL logs: " + ec.message());
    }
  }
}

OmplLogWriter::~OmplLogWriter() { remove_temporaries(); }

void OmplLogWriter::fail(const std::filesystem::path& p, const std::string& what) const {
  throw FileError(p.string() + ": " + what);
}

void OmplLogWriter::remove_temporaries() noexcept {
  if (runs_.is_open()) runs_.close();
  if (body_.is_open()) body_.close();
  std::error_code ec;
  if (!runs_path_.empty()) std::filesystem::remove(runs_path_, ec);
  if (!body_path_.empty()) std::filesystem::remove(body_path_, ec);
}

void OmplLogWriter::add(const Trial& trial) {
  const TrialId& id = trial.id;
  if (finished_) throw Error("OMPL log: trial added after the logs were finished");
  if (id.problem >= experiment_.problems.size() || id.planner >= experiment_.planners.size()) {
    throw Error("OMPL log: trial " + std::to_string(id.index) + " names problem " + std::to_string(id.problem) +
                ", planner " + std::to_string(id.planner) + ", outside the experiment");
  }
  const bool earlier_problem = problem_ != kNone ? id.problem < problem_ : id.problem < next_problem_;
  if (earlier_problem || (id.problem == problem_ && id.planner < planner_)) {
    throw Error("OMPL log: trial " + std::to_string(id.index) + " arrived out of trial order");
  }
  if (id.problem != problem_) {
    if (problem_ != kNone) end_problem();
    start_problem(id.problem);
  }
  if (id.planner != planner_) {
    if (planner_ != kNone) end_planner();
    start_planner(id.planner);
  }
  for (const auto& p : ompl::run_properties(experiment_, trial)) {
    const std::string key = ompl::log_key(p);
    keys_.insert(key);
    runs_ << key << kKeyEnd << ompl::log_value(p.value) << kFieldEnd;
  }
  runs_ << '\n';
  if (!runs_) fail(runs_path_, "cannot write the temporary runs file");
  ++runs_in_block_;
  problem_time_s_ += trial.record.wall_time_s;
}

void OmplLogWriter::start_problem(std::size_t problem) {
  // Problems skipped by the trials still get a log, with no runs.
  for (; next_problem_ < problem; ++next_problem_) write_log(next_problem_, 0.0, false);
  problem_ = problem;
  next_planner_ = 0;
  problem_time_s_ = 0.0;
  body_path_ = files_[problem];
  body_path_ += ".body.tmp";
  runs_path_ = files_[problem];
  runs_path_ += ".runs.tmp";
  body_.open(body_path_, std::ios::binary | std::ios::trunc);
  if (!body_) fail(body_path_, "cannot create a temporary file");
}

void OmplLogWriter::start_planner(std::size_t planner) {
  for (; next_planner_ < planner; ++next_planner_) write_section(next_planner_, false);
  planner_ = planner;
  keys_.clear();
  runs_in_block_ = 0;
  runs_.open(runs_path_, std::ios::binary | std::ios::trunc);
  if (!runs_) fail(runs_path_, "cannot create a temporary file");
}

void OmplLogWriter::end_planner() {
  runs_.close();
  if (!runs_) fail(runs_path_, "cannot write the temporary runs file");
  write_section(planner_, true);
  next_planner_ = planner_ + 1;
  planner_ = kNone;
}

void OmplLogWriter::end_problem() {
  if (planner_ != kNone) end_planner();
  for (; next_planner_ < experiment_.planners.size(); ++next_planner_) write_section(next_planner_, false);
  body_.close();
  if (!body_) fail(body_path_, "cannot write a temporary file");
  write_log(problem_, problem_time_s_, true);
  remove_temporaries();
  next_problem_ = problem_ + 1;
  problem_ = kNone;
}

// One planner's part of the log, as Benchmark::saveResultsToStream writes it.
void OmplLogWriter::write_section(std::size_t planner, bool with_runs) {
  const PlannerConfig& c = experiment_.planners[planner];
  if (!with_runs) {
    write_empty_section(body_, c);
    return;
  }
  write_planner_start(body_, c);
  body_ << keys_.size() << " properties for each run\n";
  for (const auto& k : keys_) body_ << k << '\n';
  body_ << runs_in_block_ << " runs\n";
  std::ifstream in(runs_path_, std::ios::binary);
  if (!in) fail(runs_path_, "cannot read the temporary runs file");
  std::map<std::string, std::string> row;
  for (std::string line; std::getline(in, line);) {
    row.clear();
    std::size_t start = 0;
    while (start < line.size()) {
      const std::size_t key_end = line.find(kKeyEnd, start);
      const std::size_t field_end = line.find(kFieldEnd, key_end);
      row.emplace(line.substr(start, key_end - start), line.substr(key_end + 1, field_end - key_end - 1));
      start = field_end + 1;
    }
    for (const auto& k : keys_) {
      auto it = row.find(k);
      if (it != row.end()) body_ << it->second;
      body_ << "; ";
    }
    body_ << '\n';
  }
  body_ << ".\n";
  if (!body_) fail(body_path_, "cannot write a temporary file");
}

// The log's header (Benchmark::saveResultsToStream), then the planner sections from the body file.
void OmplLogWriter::write_log(std::size_t problem, double total_time_s, bool with_body) {
  const Experiment& e = experiment_;
  const std::filesystem::path& path = files_[problem];
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  if (!out) fail(path, "cannot create the OMPL log");
  const auto [library, version] = ompl::version_words(info_);
  out << library << " version " << version << '\n';
  out << "Experiment " << ompl::experiment_name(e.problems[problem]) << '\n';
  const auto props = ompl::experiment_properties(e, problem, info_);
  out << props.size() << " experiment properties\n";
  for (const auto& p : props) out << ompl::log_key(p) << " = " << ompl::log_value(p.value) << '\n';
  const std::string host = ompl::field_text(info_.hostname);
  out << "Running on " << (host.empty() ? "UNKNOWN" : host) << '\n';
  out << "Starting at " << ompl::field_text(info_.date) << '\n';
  out << "<<<|\n" << ompl::setup_text(e.problems[problem]) << "|>>>\n";
  out << "<<<|\n" << ompl::block_text(info_.cpu_info) << "|>>>\n";
  out << e.seed << " is the random seed\n";
  out << core::number_text(e.time_limit_s) << " seconds per run\n";
  out << "0 MB per run\n";
  out << e.runs << " runs per planner\n";
  out << core::number_text(total_time_s) << " seconds spent to collect the data\n";
  out << "1 enum type\nstatus";
  for (const auto& name : ompl::kStatusNames) out << '|' << name;
  out << '\n' << e.planners.size() << " planners\n";
  if (with_body) {
    std::ifstream body(body_path_, std::ios::binary);
    if (!body) fail(body_path_, "cannot read a temporary file");
    if (body.peek() != std::ifstream::traits_type::eof()) out << body.rdbuf();
  } else {
    for (const auto& c : e.planners) write_empty_section(out, c);
  }
  out.close();
  if (!out) fail(path, "cannot write the OMPL log");
}

void OmplLogWriter::finish() {
  if (finished_) return;
  if (problem_ != kNone) end_problem();
  for (; next_problem_ < experiment_.problems.size(); ++next_problem_) write_log(next_problem_, 0.0, false);
  finished_ = true;
}

}  // namespace amp::bench
