// `grid-dp`: the optimal grid path on a map world.
#include <memory>

#include "amp/roadmap/catalog/planner_registry.hpp"
#include "amp/roadmap/grid/grid_dp.hpp"

namespace amp::roadmap {

void register_grid_dp(PlannerRegistry& registry) {
  registry.add({"grid-dp", "optimal 8-connected grid path on a map world: value iteration from the goal, then descent",
                GridDpSettings::schema().specs()},
               [](const core::Params& p) { return std::make_unique<GridDp>(GridDpSettings::schema().read(p)); });
}

}  // namespace amp::roadmap
