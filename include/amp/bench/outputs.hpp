#pragma once
#include <filesystem>

#include "amp/bench/experiment.hpp"
#include "amp/bench/trial_sink.hpp"

namespace amp::bench {

// Writes the outputs derived from dir/runs.csv, streaming it once: summary.json, results.db
// (OMPL's benchmark-database schema), report.html and, with `ompl_log`, OMPL's text logs in
// dir/ompl-logs/. A single run, a resumed run and merged shards all end here, so their outputs agree.
void write_outputs(const Experiment& e, const std::filesystem::path& dir, const RunInfo& info, bool ompl_log);

}  // namespace amp::bench
