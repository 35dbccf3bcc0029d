// `hybrid-prm` (Hsu, Sanchez-Ante & Sun 2005, with UAS's reward) and `uas` (the unsupervised
// adaptive strategy: regions by clustering a training roadmap, a Hybrid PRM per region).
#include <memory>

#include "amp/roadmap/catalog/planner_registry.hpp"
#include "amp/roadmap/uas/hybrid_prm.hpp"
#include "amp/roadmap/uas/uas.hpp"

namespace amp::roadmap {

void register_uas_planners(PlannerRegistry& registry) {
  registry.add({{"hybrid-prm",
                "Hybrid PRM (Hsu, Sanchez-Ante & Sun 2005) over uniform, Gaussian r and 2r, OBPRM (+ bridge, "
                "expansion) samplers, with UAS's structural reward",
                HybridPrmSettings::schema().specs()}},
               [](const core::Params& p) -> std::unique_ptr<Planner> {
                 return make_hybrid_prm(HybridPrmSettings::schema().read(p));
               });
  registry.add({{"uas",
                "UAS (unsupervised adaptive strategy): regions by clustering a training roadmap, Hybrid PRM per "
                "region in round robin",
                UasSettings::schema().specs()}},
               [](const core::Params& p) -> std::unique_ptr<Planner> {
                 return std::make_unique<Uas>(UasSettings::schema().read(p));
               });
}

}  // namespace amp::roadmap
