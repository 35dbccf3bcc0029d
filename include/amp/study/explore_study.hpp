#pragma once
#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>
#include <nlohmann/json.hpp>

#include "amp/core/parameters.hpp"
#include "amp/learn/pgcs.hpp"
#include "amp/nav/pgcs/pgcs_run.hpp"
#include "amp/world/problem.hpp"

namespace amp::study {

// One `amp explore` run, shared with `amp demo` and Python: nav::run_pgcs from the problem's start
// (exploration, then the queries), its summary as the flat record, and the pictures.
struct ExploreSetup {
  nav::PgcsRunSettings run;
  learn::PgcsSettings pgcs;
  std::uint64_t seed = 1;
  // The user's query pairs; empty: run.queries seeded random pairs reachable from the start.
  std::vector<std::pair<Eigen::Vector2d, Eigen::Vector2d>> queries;
  std::function<void(long done, long total)> progress;  // exploration steps done
};

struct ExploreResult {
  nav::PgcsRun run;               // the session, the queries and their times
  nav::PgcsSummary summary;       // nav::summarise_pgcs of the run
  nlohmann::ordered_json record;  // the flat record that `--json` prints (null: a median of no sample)
};

// The run's and PGCS's settings from parameters by their schema names (`amp explore --param`,
// Python's params=), through core::route_params; the rest of `setup` is left as it is. Throws
// ParameterError (one line, no option named) for an unknown name or a bad value.
void read_explore_params(const core::ParamMap& params, ExploreSetup& setup);

// Throws ParameterError naming the problem file (not a disc robot, a 3-D world, a start where the
// disc is not free) or the --query pair (outside the map, in an obstacle) before exploring.
ExploreResult run_exploration(const world::Problem& problem, const ExploreSetup& setup);

// The files `-o DIR` gets, in the order they are written.
const std::vector<std::string>& explore_output_files();
// Refuses (before any work) a DIR that is a file, or one of its files that exists, unless `force`.
void check_explore_dir(const std::filesystem::path& dir, bool force, const std::string& option);
// record.json: the flat record, the settings, each query's details and the curves.
nlohmann::ordered_json explore_record(const ExploreResult& result);
// Writes figure1.svg, curves.svg, queries.svg and record.json into `dir` (created if missing).
void write_explore_outputs(const world::Problem& problem, const ExploreResult& result,
                           const std::filesystem::path& dir);

// The flat record as a two-column table (what `amp explore` prints without --json).
std::string format_explore_table(const nlohmann::ordered_json& record);

}  // namespace amp::study
