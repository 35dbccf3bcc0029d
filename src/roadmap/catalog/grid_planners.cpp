// `grid-dp`: the optimal grid path on a map world.
#include <memory>

#include "amp/roadmap/catalog/planner_registry.hpp"
#include "amp/roadmap/grid/grid_dp.hpp"
#include "amp/world/problem.hpp"

namespace amp::roadmap {

void register_grid_dp(PlannerRegistry& registry) {
  // No node limit of its own: the map bounds the cells the value iteration settles, and a
  // roadmap's 20000 would stop it short on any map over about 141 x 141 cells.
  registry.add({{"grid-dp", "optimal 8-connected grid path on a map world: value iteration from the goal, then descent",
                 GridDpSettings::schema().specs()},
                world::kNoNodeLimit},
               [](const core::Params& p) { return std::make_unique<GridDp>(GridDpSettings::schema().read(p)); });
}

}  // namespace amp::roadmap
