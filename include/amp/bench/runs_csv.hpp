#pragma once
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include "amp/bench/trial_sink.hpp"

namespace amp::bench {

// The columns of runs.csv for an experiment: trial identity, seed, every RunRecord field, one
// `param.<name>` column per drawn parameter, the extras as `name=value;...`, and the message.
std::vector<std::string> runs_csv_header(const Experiment& e);

// Writes runs.csv (RFC 4180 quoting; doubles in shortest round-trip form, so the file read back
// gives the same numbers). Opens in append mode when `append` (resume): then no header is written.
class RunsCsvWriter final : public TrialSink {
 public:
  RunsCsvWriter(const std::filesystem::path& file, const Experiment& e, bool append);
  void add(const Trial& trial) override;
  void finish() override;

 private:
  std::filesystem::path file_;
  const Experiment& experiment_;
  std::vector<std::string> drawn_names_;
  std::ofstream out_;
};

// Reads the trials of a runs.csv written for `e`, one at a time, in file order. Throws FileError when
// the header is not the experiment's (another experiment's results) or a row is malformed. A final
// line without its newline (a write cut short by a kill) is not a row.
class RunsCsvReader {
 public:
  RunsCsvReader(const std::filesystem::path& file, const Experiment& e);
  // The next trial into `out`; false at the end.
  bool next(Trial& out);
  // Bytes of the header and the complete rows read so far.
  std::uintmax_t complete_bytes() const { return consumed_; }

 private:
  std::filesystem::path file_;
  const Experiment& experiment_;
  std::ifstream in_;
  std::vector<std::string> header_;
  std::vector<std::string> drawn_;
  std::size_t row_ = 1;
  std::uintmax_t consumed_ = 0;
};

// Streams the trials of a runs.csv written for `e`, in file order (see RunsCsvReader). Throws FileError when the header
// is not the experiment's (another experiment's results) or a row is malformed. A final line without
// its newline (a write cut short by a kill) is ignored; `complete_bytes` receives the length of
// the complete part, so that a resumed run can cut the file there.
void for_each_trial(const std::filesystem::path& file, const Experiment& e, const std::function<void(const Trial&)>& fn,
                    std::uintmax_t* complete_bytes = nullptr);

}  // namespace amp::bench
