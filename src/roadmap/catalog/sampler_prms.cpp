// The PRM variants that differ from `prm` only by their sampler, each reporting its node classes
// (cc_create, cc_merge, cc_expand, cc_oversample), its distance `sampler_d` where it has one and
// `sampler_distance_fallback` (1 when the robot has no diameter and 1% of the space extent stood in).
#include <map>
#include <memory>
#include <stdexcept>
#include <string>

#include "amp/roadmap/samplers/bridge_sampler.hpp"
#include "amp/roadmap/samplers/gaussian_sampler.hpp"
#include "amp/roadmap/prm/node_classifier.hpp"
#include "amp/roadmap/samplers/obprm_sampler.hpp"
#include "amp/roadmap/catalog/planner_registry.hpp"
#include "amp/roadmap/prm/prm.hpp"
#include "amp/roadmap/samplers/random_offset.hpp"

namespace amp::roadmap {

namespace {

constexpr double kMaxAttempts = 1e6;
constexpr double kMaxScale = 1e3;

// d as given, or d_scale * r (with the fallback flag) when d = 0 ("auto").
SamplerDistance resolve(const PlanningContext& ctx, double d, double d_scale) {
  if (d > 0.0) return {d, false};
  return sampler_distance(ctx.environment, ctx.space, d_scale);
}

ParamSpec k_spec() {  // prm's own
  for (const ParamSpec& s : PrmSettings::schema().specs()) {
    if (s.name == "k") return s;
  }
  throw std::logic_error("prm declares no k");
}
ParamSpec attempts_spec() {
  return {"max_attempts", ParamType::kInteger, 100, 1, kMaxAttempts, {}, "tries before a sample is given up"};
}
ParamSpec d_spec() {
  return {"d", ParamType::kReal, 0.0, 0, 1e12, {}, "sampler distance (space metric); 0 = d_scale * robot min diameter"};
}
ParamSpec d_scale_spec(double def) {
  return {"d_scale", ParamType::kReal, def, 1e-6, kMaxScale, {}, "d in robot min diameters when d = 0"};
}

PrmSettings prm_settings(const Params& p) {
  PrmSettings s;
  s.k = static_cast<int>(p.integer("k"));
  return s;
}

// The PRM's observer: node classes plus the sampler's distance figures.
std::function<std::unique_ptr<InsertionObserver>(const PlanningContext&, Sampler&)> observer(double d, double d_scale) {
  return [d, d_scale](const PlanningContext& ctx, Sampler&) -> std::unique_ptr<InsertionObserver> {
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
  registry.add({"gaussian-prm",
                "PRM with Gaussian sampling (Boor, Overmars & van der Stappen 1999): free samples near obstacles",
                {k_spec(), d_spec(), d_scale_spec(1.0), attempts_spec()}},
               [](const Params& p) -> std::unique_ptr<Planner> {
                 const double d = p.real("d"), scale = p.real("d_scale");
                 const int attempts = static_cast<int>(p.integer("max_attempts"));
                 PrmParts parts;
                 parts.sampler = [d, scale, attempts](const PlanningContext& ctx) -> std::unique_ptr<Sampler> {
                   return std::make_unique<GaussianSampler>(ctx.space, ctx.checker,
                                                            GaussianSamplerSettings{resolve(ctx, d, scale).d, attempts});
                 };
                 parts.observer = observer(d, scale);
                 return std::make_unique<Prm>(prm_settings(p), std::move(parts));
               });

  registry.add({"obprm",
                "obstacle-based PRM (Amato et al. 1998): walk from a colliding state along a random ray to the "
                "first free one",
                {k_spec(), attempts_spec(),
                 {"max_steps", ParamType::kInteger, 1000, 1, kMaxAttempts, {}, "resolution steps along one ray"}}},
               [](const Params& p) -> std::unique_ptr<Planner> {
                 ObprmSamplerSettings o;
                 o.max_attempts = static_cast<int>(p.integer("max_attempts"));
                 o.max_steps = static_cast<int>(p.integer("max_steps"));
                 o.validate();
                 PrmParts parts;
                 parts.sampler = [o](const PlanningContext& ctx) -> std::unique_ptr<Sampler> {
                   return std::make_unique<ObprmSampler>(ctx.space, ctx.checker, o);
                 };
                 parts.observer = observer(-1.0, 0.0);
                 return std::make_unique<Prm>(prm_settings(p), std::move(parts));
               });

  registry.add({"bridge-prm",
                "PRM with the bridge test (Hsu, Jiang, Reif & Sun 2003): free midpoints of short colliding pairs",
                {k_spec(), d_spec(), d_scale_spec(2.0), attempts_spec(),
                 {"uniform_mix", ParamType::kReal, 0.0, 0, 1, {}, "probability of a plain uniform sample instead"}}},
               [](const Params& p) -> std::unique_ptr<Planner> {
                 const double d = p.real("d"), scale = p.real("d_scale");
                 BridgeSamplerSettings b;
                 b.max_attempts = static_cast<int>(p.integer("max_attempts"));
                 b.uniform_mix = p.real("uniform_mix");
                 PrmParts parts;
                 parts.sampler = [d, scale, b](const PlanningContext& ctx) -> std::unique_ptr<Sampler> {
                   BridgeSamplerSettings run = b;  // a copy: the factory may serve several threads
                   run.d = resolve(ctx, d, scale).d;
                   return std::make_unique<BridgeSampler>(ctx.space, ctx.checker, run);
                 };
                 parts.observer = observer(d, scale);
                 return std::make_unique<Prm>(prm_settings(p), std::move(parts));
               });
}

}  // namespace amp::roadmap
