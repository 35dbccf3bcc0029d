#include "amp/roadmap/uas/uas.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>

#include "amp/roadmap/uas/hybrid_observer.hpp"
#include "amp/core/error.hpp"
#include "amp/learn/clusterer_choice.hpp"
#include "amp/roadmap/uas/hybrid_prm.hpp"
#include "amp/roadmap/prm/prm.hpp"
#include "amp/roadmap/samplers/sampling_domain.hpp"

namespace amp::roadmap {

namespace {
constexpr int kMaxM = 100000;

double method_index(const std::string& method) {
  for (std::size_t i = 0; i < std::size(learn::kClusteringNames); ++i) {
    if (learn::kClusteringNames[i] == method) return static_cast<double>(i);
  }
  return -1.0;
}
}  // namespace

const core::SettingsSchema<UasSettings>& UasSettings::schema() {
  using S = UasSettings;
  static const core::SettingsSchema<S> schema("uas", [] {
    std::vector<core::SettingsField<S>> f = core::nested_fields<S>(RegionSettings::schema(), &S::regions);
    f.push_back(core::integer_field<S>("m", &S::m, 1, kMaxM, "samples per region per round"));
    f.push_back(core::enum_field<S>(
        "schedule", &S::schedule,
        std::vector<std::pair<std::string, RegionSchedule>>{{"weighted", RegionSchedule::kWeighted},
                                                            {"round-robin", RegionSchedule::kRoundRobin},
                                                            {"adaptive", RegionSchedule::kAdaptive}},
        "next region: weighted by narrow training nodes, in turn (the paper), or by a bandit over regions"));
    f.push_back(core::integer_field<S>("k", &S::k, 1, kMaxNeighbours, "neighbours tried per new node"));
    for (auto& h : core::nested_fields<S>(HybridSettings::schema(), &S::hybrid)) f.push_back(std::move(h));
    f.push_back(core::bool_field<S>("bridge", &S::bridge, "add the bridge test as a fifth sampler"));
    f.push_back(core::bool_field<S>(
        "expansion", &S::expansion,
        "add PRM's expansion step (a step from a node chosen by its failure ratio) to every region"));
    f.push_back(core::bool_field<S>("reuse_training", &S::reuse_training,
                                    "start the planning roadmap from the training roadmap"));
    f.push_back(core::bool_field<S>("whole_space_region", &S::whole_space_region,
                                    "the whole space takes a turn as one more region (keeps every passage reachable)"));
    f.push_back(sequence_field<S>(
        "how the regions draw their start states: independent random, or a randomised Halton sequence"));
    return f;
  }());
  return schema;
}

void UasSettings::validate() const {
  schema().validate(*this);
  regions.training.validate();  // attempts_per_node, which is not a parameter
}

namespace {
std::size_t region_count(const std::vector<std::unique_ptr<HybridSampler>>& regions) {
  if (regions.empty()) throw ParameterError("uas: no region to sample");
  return regions.size();
}
}  // namespace

RegionalSampler::RegionalSampler(std::vector<std::unique_ptr<HybridSampler>> regions, int m, RegionSchedule schedule,
                                 double gamma, std::vector<double> weights)
    : regions_(std::move(regions)),
      m_(m),
      schedule_(schedule),
      region_bandit_(region_count(regions_), gamma),
      rounds_(regions_.size(), 0),
      weights_(std::move(weights)),
      credit_(regions_.size(), 0.0) {
  if (m_ < 1) throw ParameterError("uas: m must be >= 1, got " + std::to_string(m_));
  if (schedule_ == RegionSchedule::kWeighted) {
    const bool ok = weights_.size() == regions_.size() &&
                    std::all_of(weights_.begin(), weights_.end(), [](double w) { return w > 0.0 && std::isfinite(w); });
    if (!ok) throw ParameterError("uas: the weighted schedule needs one positive weight per region");
  }
}

std::size_t RegionalSampler::next_weighted() {
  // Smooth weighted round robin: every region earns its weight, the richest is served and pays the
  // total. Deterministic, and each region's share of rounds is within one of weight / sum.
  double total = 0.0;
  std::size_t best = 0;
  for (std::size_t i = 0; i < credit_.size(); ++i) {
    credit_[i] += weights_[i];
    total += weights_[i];
    if (credit_[i] > credit_[best]) best = i;
  }
  credit_[best] -= total;
  return best;
}

bool RegionalSampler::sample(core::Rng& rng, State& out) {
  if (drawn_in_round_ == 0) {
    // A new round: round robin continues from the region after the last one (current_ starts at 0).
    if (schedule_ == RegionSchedule::kAdaptive) current_ = region_bandit_.choose(rng);
    if (schedule_ == RegionSchedule::kWeighted) current_ = next_weighted();
    ++rounds_[current_];
  }
  last_ = current_;
  // A failed draw counts towards the round too, so a region whose samplers keep failing (a box
  // that is nearly all obstacle) cannot hold up the others.
  if (++drawn_in_round_ == m_) {
    drawn_in_round_ = 0;
    if (schedule_ == RegionSchedule::kRoundRobin) current_ = (current_ + 1) % regions_.size();
  }
  pending_ = regions_[last_]->sample(rng, out);
  return pending_;
}

void RegionalSampler::reward_last(const Insertion& insertion) {
  if (!pending_) return;
  pending_ = false;
  HybridSampler& region = *regions_[last_];
  region.reward_last(insertion);
  if (schedule_ != RegionSchedule::kAdaptive) return;
  // The region's bandit learns from the same reward, its cost normalised by the running mean over
  // all regions (so regions compare on one scale).
  const std::uint64_t c = std::max<std::uint64_t>(region.last_cd_calls(), 1);
  total_cost_ += c;
  ++costed_;
  const double mean = static_cast<double>(total_cost_) / static_cast<double>(costed_);
  region_bandit_.update(last_, region.last_reward(), static_cast<double>(c) / mean);
}

void RegionalSampler::observe(const Roadmap& roadmap, const Insertion& insertion) {
  for (auto& r : regions_) r->observe(roadmap, insertion);
}

void RegionalSampler::report(std::map<std::string, double>& extra) const {
  for (std::size_t i = 0; i < regions_.size(); ++i) {
    const HybridSampler& h = *regions_[i];
    for (std::size_t s = 0; s < h.bandit().arms(); ++s) {
      extra["samples_" + h.arm_name(s)] += static_cast<double>(h.samples(s));
      extra["chosen_" + h.arm_name(s)] += static_cast<double>(h.chosen(s));
      extra["region" + std::to_string(i) + "_prob_" + h.arm_name(s)] = h.bandit().probabilities()[s];
    }
    extra["region" + std::to_string(i) + "_rounds"] = static_cast<double>(rounds_[i]);
  }
}

Uas::Uas(UasSettings settings) : settings_(std::move(settings)) { settings_.validate(); }

PlanResult Uas::plan(const PlanningContext& ctx, const core::StopCondition& stop, core::Rng& rng) {
  check_seeds(ctx);  // before training spends anything (Prm::plan checks them again: 2 CD calls)
  RegionModel model = [&] {
    const core::PhaseScope training(ctx.checker.counters(), core::Phase::kTraining);
    return identify_regions(ctx, settings_.regions, stop, rng);
  }();

  std::map<std::string, double> figures{
      {"training_nodes", static_cast<double>(model.training.size())},
      {"training_edges", static_cast<double>(model.training.roadmap->edge_count())},
      {"training_failed_samples", static_cast<double>(model.training.failed_samples)},
  };
  if (model.training.stopped != core::StopReason::kNone) {
    PlanResult result;
    result.status = status_for(model.training.stopped);
    result.nodes = model.training.size();
    result.edges = model.training.roadmap->edge_count();
    result.components = model.training.roadmap->component_count();
    result.extra = std::move(figures);
    result.roadmap = model.training.roadmap;
    return result;
  }
  const bool global = model.clustering.c < 2;
  figures["clusters"] = model.clustering.c;
  figures["uas_fallback_global"] = global ? 1.0 : 0.0;
  figures["clustering_method"] = method_index(model.method);  // index into kmeans, ward, pgmeans
  figures["region_seed_extensions"] = model.seed_extensions;
  figures["regions"] = global ? 1.0 : static_cast<double>(model.regions.size()) + (settings_.whole_space_region ? 1.0 : 0.0);
  for (std::size_t i = 0; i < model.auto_methods.size(); ++i) {
    figures["silhouette_" + model.auto_methods[i]] = model.auto_scores[i];
    figures["clusters_" + model.auto_methods[i]] = model.auto_clusters[i];
  }

  PrmSettings prm;
  prm.k = settings_.k;
  PrmParts parts;
  if (settings_.reuse_training) parts.initial = model.training.roadmap;
  const UasSettings s = settings_;
  // The reused training nodes are expansion candidates from the start (the observer is told only
  // about the planning phase's insertions).
  std::shared_ptr<const VisibleNodes> known;
  if (settings_.reuse_training) {
    known = std::make_shared<const VisibleNodes>(VisibleNodes{model.training.roadmap, model.training.visibility});
  }
  const SamplerSetOptions whole{s.bridge, s.expansion, s.sequence, known};
  if (global) {
    parts.sampler = [s, whole](const PlanningContext& c) -> std::unique_ptr<Sampler> {
      return std::make_unique<HybridSampler>(make_uas_samplers(c, nullptr, whole), c.checker, s.hybrid);
    };
  } else {
    std::vector<Eigen::AlignedBox3d> boxes;
    std::vector<double> weights;
    for (const Region& r : model.regions) {
      boxes.push_back(r.box);
      weights.push_back(narrow_weight(r, model.training));
    }
    // The whole space gets the regions' mean weight. Not less: boxes can leave gaps (PG-means split
    // the Maze into two halves with a gap between them), and with weight 1 one run needed ~100k
    // nodes, the gap being sampled in 1 % of the rounds only.
    if (settings_.whole_space_region) {
      weights.push_back(std::accumulate(weights.begin(), weights.end(), 0.0) / static_cast<double>(weights.size()));
    }
    for (std::size_t i = 0; i < weights.size() && settings_.schedule == RegionSchedule::kWeighted; ++i) {
      figures["region" + std::to_string(i) + "_weight"] = weights[i];
    }
    parts.sampler = [s, boxes, weights, whole](const PlanningContext& c) -> std::unique_ptr<Sampler> {
      std::vector<std::unique_ptr<HybridSampler>> regions;
      for (const auto& box : boxes) {
        auto domain = std::make_shared<ReferencePointBoxDomain>(c.space, c.environment, box, s.sequence);
        regions.push_back(std::make_unique<HybridSampler>(make_uas_samplers(c, domain, whole), c.checker, s.hybrid));
      }
      if (s.whole_space_region) {  // the last region: keeps every part of the space reachable
        regions.push_back(
            std::make_unique<HybridSampler>(make_uas_samplers(c, nullptr, whole), c.checker, s.hybrid));
      }
      return std::make_unique<RegionalSampler>(std::move(regions), s.m, s.schedule, s.hybrid.gamma, weights);
    };
  }
  parts.observer = [figures](const PlanningContext&, Sampler& sampler) -> std::unique_ptr<InsertionObserver> {
    // parts.sampler above made it, and both kinds are AdaptiveSamplers.
    return std::make_unique<HybridObserver>(static_cast<AdaptiveSampler&>(sampler), figures);
  };
  PlanResult result = Prm(prm, std::move(parts)).plan(ctx, stop, rng);
  const double reused = settings_.reuse_training ? static_cast<double>(model.training.size()) : 0.0;
  result.extra["planning_nodes"] = static_cast<double>(result.nodes) - reused;
  return result;
}

}  // namespace amp::roadmap
