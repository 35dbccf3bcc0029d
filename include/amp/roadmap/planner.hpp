#pragma once
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "amp/core/edge_check_mode.hpp"
#include "amp/core/error.hpp"
#include "amp/core/rng.hpp"
#include "amp/core/run_record.hpp"
#include "amp/core/space.hpp"
#include "amp/core/stop_condition.hpp"
#include "amp/roadmap/roadmap.hpp"
#include "amp/world/environment.hpp"
#include "amp/world/validity_checker.hpp"

namespace amp::roadmap {

// What a planner works on. The checker counts into the run's counters; `seeds` are the
// configurations to connect ({start, goal} for a query, more for section 3's tasks).
struct PlanningContext {
  const core::Space& space;
  const world::Environment& environment;
  const world::ValidityChecker& checker;
  const std::vector<State>& seeds;
  // How edges are checked (a path reported solved is certified either way).
  core::EdgeCheckMode edge_check = core::EdgeCheckMode::kDiscrete;
  // The run's stop condition, for work that can be long inside one planner iteration (an edge at a
  // very fine resolution, an A* search, a certification); null when the caller has none.
  const core::StopCondition* stop = nullptr;
};

struct PlanResult {
  core::PlanStatus status = core::PlanStatus::kError;
  // Through every seed in order (seed 0 -> seed 1 -> ...); empty unless solved.
  std::vector<State> path;
  std::uint64_t nodes = 0;
  std::uint64_t edges = 0;
  std::uint64_t components = 0;
  std::map<std::string, double> extra;  // planner-specific figures, sorted by name
  std::shared_ptr<const Roadmap> roadmap;  // for drawing; may be null
};

// A seed configuration that is out of bounds, of the wrong dimension or in collision: the user's
// error, so execute_run() passes it on rather than recording a failed run.
class InvalidSeedError : public Error {
 public:
  using Error::Error;
};

// A motion planner: a function of explicit inputs (no hidden state). All randomness comes from `rng`;
// `stop` is polled once per iteration with the roadmap size, so every planner ends with status
// kTimeout or kNodeLimit when it fires. Planners hold no state between calls that changes results.
class Planner {
 public:
  virtual ~Planner() = default;
  virtual PlanResult plan(const PlanningContext& ctx, const core::StopCondition& stop, core::Rng& rng) = 0;
};

// Throws InvalidSeedError naming the first seed (by position; 0 = start, last = goal) that is missing,
// of the wrong dimension, out of bounds or in collision. Costs one counted CD call per seed.
void check_seeds(const PlanningContext& ctx);

// The status a planner reports when `reason` stopped it (cancelled runs count as timeouts).
core::PlanStatus status_for(core::StopReason reason);

}  // namespace amp::roadmap
