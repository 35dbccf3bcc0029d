// The PRM variants that differ from `prm` only by their sampler, each reporting its node classes
// (cc_create, cc_merge, cc_expand, cc_oversample), its distance `sampler_d` where it has one and
// `sampler_distance_fallback` (1 when the robot has no diameter and 1% of the space extent stood in).
#include <map>
#include <memory>
#include <string>

#include "amp/roadmap/samplers/bridge_sampler.hpp"
#include "amp/roadmap/samplers/gaussian_sampler.hpp"
#include "amp/roadmap/prm/node_classifier.hpp"
#include "amp/roadmap/samplers/obprm_sampler.hpp"
#include "amp/roadmap/catalog/planner_registry.hpp"
#include "amp/roadmap/prm/prm.hpp"
#include "amp/roadmap/prm/sampler_prm_settings.hpp"
#include "amp/roadmap/samplers/random_offset.hpp"

namespace amp::roadmap {

namespace {

// d as given, or d_scale * r (with the fallback flag) when d = 0 ("auto").
SamplerDistance resolve(const PlanningContext& ctx, double d, double d_scale) {
  if (d > 0.0) return {d, false};
  return sampler_distance(ctx.environment, ctx.space, d_scale);
}

template <class S>
PrmSettings prm_settings(const S& s) {
  PrmSettings prm;
  prm.k = s.k;
  return prm;
}

// The PRM's observer: node classes plus the sampler's distance figures.
std::function<std::unique_ptr<InsertionObserver>(const PlanningContext&)> observer(double d, double d_scale) {
  return [d, d_scale](const PlanningContext& ctx) -> std::unique_ptr<InsertionObserver> {
    std::map<std::string, double> constants;
    if (d >= 0.0) {
      const SamplerDistance sd = resolve(ctx, d, d_scale);
      constants = {{"sampler_d", sd.d}, {"sampler_distance_fallback", sd.fallback ? 1.0 : 0.0}};
    }
    return std::make_unique<NodeClassCounter>(std::move(constants));
  };
}

}  // namespace

void register_sampler_prms(PlannerRegistry& registry) {
  registry.add({{"gaussian-prm",
                "PRM with Gaussian sampling (Boor, Overmars & van der Stappen 1999): free samples near obstacles",
                GaussianPrmSettings::schema().specs()}},
               [](const core::Params& p) -> std::unique_ptr<Planner> {
                 const GaussianPrmSettings g = GaussianPrmSettings::schema().read(p);
                 PrmParts parts;
                 parts.sampler = [g](const PlanningContext& ctx) -> std::unique_ptr<Sampler> {
                   return std::make_unique<GaussianSampler>(
                       ctx.space, ctx.checker, GaussianSamplerSettings{resolve(ctx, g.d, g.d_scale).d, g.max_attempts});
                 };
                 parts.observer = observer(g.d, g.d_scale);
                 return std::make_unique<Prm>(prm_settings(g), std::move(parts));
               });

  registry.add({{"obprm",
                "obstacle-based PRM (Amato et al. 1998): walk from a colliding state along a random ray to the "
                "first free one",
                ObprmSettings::schema().specs()}},
               [](const core::Params& p) -> std::unique_ptr<Planner> {
                 const ObprmSettings s = ObprmSettings::schema().read(p);
                 ObprmSamplerSettings o;
                 o.max_attempts = s.max_attempts;
                 o.max_steps = s.max_steps;
                 PrmParts parts;
                 parts.sampler = [o](const PlanningContext& ctx) -> std::unique_ptr<Sampler> {
                   return std::make_unique<ObprmSampler>(ctx.space, ctx.checker, o, nullptr, ctx.stop);
                 };
                 parts.observer = observer(-1.0, 0.0);
                 return std::make_unique<Prm>(prm_settings(s), std::move(parts));
               });

  registry.add({{"bridge-prm",
                "PRM with the bridge test (Hsu, Jiang, Reif & Sun 2003): free midpoints of short colliding pairs",
                BridgePrmSettings::schema().specs()}},
               [](const core::Params& p) -> std::unique_ptr<Planner> {
                 const BridgePrmSettings s = BridgePrmSettings::schema().read(p);
                 BridgeSamplerSettings b;
                 b.max_attempts = s.max_attempts;
                 b.uniform_mix = s.uniform_mix;
                 PrmParts parts;
                 parts.sampler = [s, b](const PlanningContext& ctx) -> std::unique_ptr<Sampler> {
                   BridgeSamplerSettings run = b;  // a copy: the factory may serve several threads
                   run.d = resolve(ctx, s.d, s.d_scale).d;
                   return std::make_unique<BridgeSampler>(ctx.space, ctx.checker, run);
                 };
                 parts.observer = observer(s.d, s.d_scale);
                 return std::make_unique<Prm>(prm_settings(s), std::move(parts));
               });
}

}  // namespace amp::roadmap
