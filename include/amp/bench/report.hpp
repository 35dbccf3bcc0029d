#pragma once
#include <filesystem>

#include <nlohmann/json_fwd.hpp>

#include "amp/bench/experiment.hpp"
#include "amp/bench/trial_sink.hpp"

namespace amp::bench {

// Writes dir/report.html: one self-contained page (inline SVG and CSS, no network) with the
// experiment, per-problem tables in the style of the run-cost paper's Table 1, box plots and
// histograms of run cost per planner, the significance results in words, and each problem drawn with
// one solution path (the first solved trial, re-run from its seed; a navigation method's driven
// trace; none for a method whose run is a sequence of worlds, which the caption says). Every "best"
// follows e.cost_direction. `summary` is summarize()'s JSON.
void write_report(const Experiment& e, const nlohmann::json& summary, const RunInfo& info,
                  const std::filesystem::path& dir);

}  // namespace amp::bench
