// `prm`, with Lazy PRM as its `lazy` switch.
#include <memory>

#include "amp/roadmap/catalog/planner_registry.hpp"
#include "amp/roadmap/prm/prm.hpp"

namespace amp::roadmap {

void register_prm(PlannerRegistry& registry) {
  registry.add({{"prm", "probabilistic roadmap (Kavraki et al. 1996); lazy=true gives Lazy PRM (Bohlin & Kavraki 2000)",
                PrmSettings::schema().specs()}},
               [](const core::Params& p) { return std::make_unique<Prm>(PrmSettings::schema().read(p)); });
}

}  // namespace amp::roadmap
