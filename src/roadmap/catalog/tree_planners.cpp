// `rrt-connect` (Kuffner & LaValle 2000).
#include <memory>

#include "amp/roadmap/catalog/planner_registry.hpp"
#include "amp/roadmap/trees/rrt_connect.hpp"

namespace amp::roadmap {

void register_rrt_connect(PlannerRegistry& registry) {
  registry.add({{"rrt-connect", "bidirectional RRT, EXTEND one tree and CONNECT the other (Kuffner & LaValle 2000)",
                RrtConnectSettings::schema().specs()}},
               [](const core::Params& p) { return std::make_unique<RrtConnect>(RrtConnectSettings::schema().read(p)); });
}

}  // namespace amp::roadmap
