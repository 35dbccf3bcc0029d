#include "amp/roadmap/uas/hybrid_prm.hpp"

#include <string>

#include "amp/roadmap/uas/hybrid_observer.hpp"
#include "amp/core/error.hpp"
#include "amp/roadmap/samplers/bridge_sampler.hpp"
#include "amp/roadmap/samplers/gaussian_sampler.hpp"
#include "amp/roadmap/samplers/obprm_sampler.hpp"
#include "amp/roadmap/samplers/random_offset.hpp"
#include "amp/roadmap/samplers/uniform_domain_sampler.hpp"

namespace amp::roadmap {

const core::SettingsSchema<HybridPrmSettings>& HybridPrmSettings::schema() {
  using S = HybridPrmSettings;
  static const core::SettingsSchema<S> schema("hybrid-prm", [] {
    std::vector<core::SettingsField<S>> f = core::nested_fields<S>(HybridSettings::schema(), &S::hybrid);
    f.push_back(core::integer_field<S>("k", &S::k, 1, kMaxNeighbours, "neighbours tried per new node"));
    f.push_back(core::bool_field<S>("bridge", &S::bridge, "add the bridge test as a fifth sampler"));
    f.push_back(core::bool_field<S>(
        "expansion", &S::expansion,
        "add PRM's expansion step (a step from a node chosen by its failure ratio) as one more sampler"));
    f.push_back(sequence_field<S>("how the samplers draw their start states: independent random, or a randomised "
                                  "Halton sequence"));
    return f;
  }());
  return schema;
}

std::vector<HybridSampler::Arm> make_uas_samplers(const PlanningContext& ctx,
                                                  std::shared_ptr<const SamplingDomain> domain,
                                                  const SamplerSetOptions& options) {
  domain = domain_or_whole(std::move(domain), ctx.space, options.sequence);
  const double r = sampler_distance(ctx.environment, ctx.space, 1.0).d;
  std::vector<HybridSampler::Arm> arms;
  arms.push_back({"uniform", std::make_unique<UniformDomainSampler>(domain, ctx.checker)});
  arms.push_back({"gaussian_r", std::make_unique<GaussianSampler>(ctx.space, ctx.checker,
                                                                  GaussianSamplerSettings{r, 100}, domain)});
  arms.push_back({"gaussian_2r", std::make_unique<GaussianSampler>(ctx.space, ctx.checker,
                                                                   GaussianSamplerSettings{2 * r, 100}, domain)});
  arms.push_back({"obprm", std::make_unique<ObprmSampler>(ctx.space, ctx.checker, ObprmSamplerSettings{}, domain, ctx.stop)});
  if (options.bridge) {
    BridgeSamplerSettings b;
    b.d = 2 * r;
    arms.push_back({"bridge", std::make_unique<BridgeSampler>(ctx.space, ctx.checker, b, domain)});
  }
  if (options.expansion) {
    auto expansion = std::make_unique<ExpansionSampler>(ctx.space, ctx.checker, ExpansionSamplerSettings{2 * r, 20}, domain);
    if (options.known != nullptr) expansion->add(*options.known);
    InsertionObserver* observer = expansion.get();
    arms.push_back({"expansion", std::move(expansion), observer});
  }
  return arms;
}

std::unique_ptr<Prm> make_hybrid_prm(const HybridPrmSettings& settings) {
  settings.validate();
  PrmSettings prm;
  prm.k = settings.k;
  PrmParts parts;
  parts.observed_sampler = [settings](const PlanningContext& ctx) {
    const SamplerSetOptions options{settings.bridge, settings.expansion, settings.sequence, nullptr};
    auto sampler = std::make_unique<HybridSampler>(make_uas_samplers(ctx, nullptr, options), ctx.checker, settings.hybrid);
    const bool fallback = sampler_distance(ctx.environment, ctx.space, 1.0).fallback;
    return with_hybrid_observer(std::move(sampler), {{"sampler_distance_fallback", fallback}});
  };
  return std::make_unique<Prm>(prm, std::move(parts));
}

}  // namespace amp::roadmap
