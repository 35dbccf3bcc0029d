#include "amp/roadmap/planner.hpp"

#include <string>

namespace amp::roadmap {

namespace {
std::string seed_name(std::size_t i, std::size_t count) {
  std::string name = "seed " + std::to_string(i);
  if (count == 2) name += i == 0 ? " (start)" : " (goal)";
  return name;
}
}  // namespace

void check_seeds(const PlanningContext& ctx) {
  if (ctx.seeds.empty()) throw InvalidSeedError("no seed configurations to connect (need a start and a goal)");
  for (std::size_t i = 0; i < ctx.seeds.size(); ++i) {
    const State& s = ctx.seeds[i];
    if (s.size() != ctx.space.dimension()) {
      throw InvalidSeedError(seed_name(i, ctx.seeds.size()) + " has " + std::to_string(s.size()) +
                             " coordinates, the " + std::string(ctx.space.kind()) + " space needs " +
                             std::to_string(ctx.space.dimension()));
    }
    if (!ctx.space.in_bounds(s)) throw InvalidSeedError(seed_name(i, ctx.seeds.size()) + " is out of bounds");
    if (!ctx.checker.is_valid(s)) throw InvalidSeedError(seed_name(i, ctx.seeds.size()) + " is in collision");
  }
}

core::PlanStatus status_for(core::StopReason reason) {
  switch (reason) {
    case core::StopReason::kNodeLimit: return core::PlanStatus::kNodeLimit;
    case core::StopReason::kTimeLimit:
    case core::StopReason::kCancelled: return core::PlanStatus::kTimeout;
    case core::StopReason::kNone: break;
  }
  return core::PlanStatus::kError;
}

}  // namespace amp::roadmap
