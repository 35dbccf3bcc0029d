#include "amp/roadmap/uas/hybrid_prm.hpp"

#include <string>

#include "amp/core/error.hpp"
#include "amp/roadmap/samplers/bridge_sampler.hpp"
#include "amp/roadmap/samplers/gaussian_sampler.hpp"
#include "amp/roadmap/samplers/obprm_sampler.hpp"
#include "amp/roadmap/planner_registry.hpp"
#include "amp/roadmap/samplers/random_offset.hpp"
#include "amp/roadmap/samplers/uniform_domain_sampler.hpp"

namespace amp::roadmap {

namespace {
constexpr int kMaxK = 1000;
constexpr double kMaxAlpha = 1000.0;
}  // namespace

void HybridPrmSettings::validate() const {
  hybrid.validate();
  if (k < 1 || k > kMaxK) throw ParameterError("hybrid-prm: k must be in [1, 1000], got " + std::to_string(k));
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
  arms.push_back({"obprm", std::make_unique<ObprmSampler>(ctx.space, ctx.checker, ObprmSamplerSettings{}, domain)});
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
  parts.sampler = [settings](const PlanningContext& ctx) -> std::unique_ptr<Sampler> {
    const SamplerSetOptions options{settings.bridge, settings.expansion, settings.sequence, nullptr};
    return std::make_unique<HybridSampler>(make_uas_samplers(ctx, nullptr, options), ctx.checker, settings.hybrid);
  };
  parts.observer = [](const PlanningContext& ctx, Sampler& sampler) -> std::unique_ptr<InsertionObserver> {
    const bool fallback = sampler_distance(ctx.environment, ctx.space, 1.0).fallback;
    // parts.sampler above made it: the cast is to the type this very function pair creates.
    return std::make_unique<HybridObserver>(static_cast<HybridSampler&>(sampler),
                                            std::map<std::string, double>{{"sampler_distance_fallback", fallback}});
  };
  return std::make_unique<Prm>(prm, std::move(parts));
}

void register_hybrid_prm(PlannerRegistry& registry) {
  const HybridPrmSettings d;
  PlannerInfo info{
      "hybrid-prm",
      "Hybrid PRM (Hsu, Sanchez-Ante & Sun 2005) over uniform, Gaussian r and 2r, OBPRM (+ bridge, expansion) "
      "samplers, with UAS's structural reward",
      {
          {"gamma", ParamType::kReal, d.hybrid.gamma, 1e-6, 1, {}, "share of random sampler selection"},
          {"alpha", ParamType::kReal, d.hybrid.alpha, 1e-6, kMaxAlpha, {}, "reward exp(-alpha v^2) of non-structural nodes"},
          {"cost", ParamType::kChoice, "node", 0, 0, {"node", "sampling"},
           "a sample's cost: CD calls to sample and connect it (node) or to sample it only"},
          {"k", ParamType::kInteger, d.k, 1, kMaxK, {}, "neighbours tried per new node"},
          {"bridge", ParamType::kBool, d.bridge, 0, 1, {}, "add the bridge test as a fifth sampler"},
          {"expansion", ParamType::kBool, d.expansion, 0, 1, {},
           "add PRM's expansion step (a step from a node chosen by its failure ratio) as one more sampler"},
          {"sequence", ParamType::kChoice, "random", 0, 0, {"random", "halton"},
           "how the samplers draw their start states: independent random, or a randomised Halton sequence"},
      }};
  registry.add(std::move(info), [](const Params& p) -> std::unique_ptr<Planner> {
    HybridPrmSettings s;
    s.hybrid.gamma = p.real("gamma");
    s.hybrid.alpha = p.real("alpha");
    s.hybrid.cost = p.choice("cost") == "node" ? SampleCost::kNode : SampleCost::kSampling;
    s.k = static_cast<int>(p.integer("k"));
    s.bridge = p.boolean("bridge");
    s.expansion = p.boolean("expansion");
    s.sequence = parse_draw_sequence(p.choice("sequence"));
    return make_hybrid_prm(s);
  });
}

}  // namespace amp::roadmap
