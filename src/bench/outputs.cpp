#include "amp/bench/outputs.hpp"

#include <fstream>
#include <memory>
#include <vector>

#include <nlohmann/json.hpp>

#include "amp/bench/ompl_database_writer.hpp"
#include "amp/bench/ompl_log_writer.hpp"
#include "amp/bench/report.hpp"
#include "amp/bench/runs_csv.hpp"
#include "amp/bench/summary.hpp"
#include "amp/core/error.hpp"

namespace amp::bench {

void write_outputs(const Experiment& e, const std::filesystem::path& dir, const RunInfo& info, bool ompl_log) {
  const auto db = dir / "results.db";
  std::error_code ec;
  std::filesystem::remove(db, ec);  // derived from runs.csv, which is the record; remade every time
  std::vector<std::unique_ptr<TrialSink>> sinks;
  sinks.push_back(std::make_unique<OmplDatabaseWriter>(db, e, info));
  if (ompl_log) {
    std::filesystem::create_directories(dir / "ompl-logs", ec);
    sinks.push_back(std::make_unique<OmplLogWriter>(dir / "ompl-logs", e, info));
  }
  ExperimentMetrics metrics = empty_metrics(e);
  for_each_trial(dir / "runs.csv", e, [&](const Trial& t) {
    metrics[t.id.problem][t.id.planner].add(t);
    for (auto& s : sinks) s->add(t);
  });
  for (auto& s : sinks) s->finish();

  const nlohmann::json summary = summarize(e, metrics);
  std::ofstream out(dir / "summary.json");
  out << summary.dump(2) << '\n';
  if (!out) throw FileError((dir / "summary.json").string() + ": write failed");
  write_report(e, summary, info, dir);
}

}  // namespace amp::bench
