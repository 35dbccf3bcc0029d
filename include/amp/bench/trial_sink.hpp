#pragma once
#include "amp/bench/experiment.hpp"

namespace amp::bench {

// Receives the trials of an experiment in trial order and writes them somewhere (runs.csv, OMPL's
// benchmark database, OMPL's text log). Streaming, so memory does not grow with the run count.
// Implementations: RunsCsvWriter, OmplDatabaseWriter, OmplLogWriter.
class TrialSink {
 public:
  virtual ~TrialSink() = default;
  virtual void add(const Trial& trial) = 0;
  // Flushes and closes; throws FileError when the output cannot be completed.
  virtual void finish() = 0;
};

// Facts about the machine and the run that OMPL's formats record.
struct RunInfo {
  std::string hostname;
  std::string cpu_info;
  std::string date;        // ISO 8601, UTC
  std::string version;     // "AMP 0.1.0"
  double total_time_s = 0.0;  // wall time of the whole experiment
  int threads = 1;
};

RunInfo current_run_info(int threads);

}  // namespace amp::bench
