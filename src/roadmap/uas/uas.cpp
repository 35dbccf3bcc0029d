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
    parts.observed_sampler = [s, whole, figures](const PlanningContext& c) {
      return with_hybrid_observer(
          std::make_unique<HybridSampler>(make_uas_samplers(c, nullptr, whole), c.checker, s.hybrid), figures);
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
    parts.observed_sampler = [s, boxes, weights, whole, figures](const PlanningContext& c) {
      std::vector<std::unique_ptr<HybridSampler>> regions;
      for (const auto& box : boxes) {
        auto domain = std::make_shared<ReferencePointBoxDomain>(c.space, c.environment, box, s.sequence);
        regions.push_back(std::make_unique<HybridSampler>(make_uas_samplers(c, domain, whole), c.checker, s.hybrid));
      }
      if (s.whole_space_region) {  // the last region: keeps every part of the space reachable
        regions.push_back(
            std::make_unique<HybridSampler>(make_uas_samplers(c, nullptr, whole), c.checker, s.hybrid));
      }
      return with_hybrid_observer(
          std::make_unique<RegionalSampler>(std::move(regions), s.m, s.schedule, s.hybrid.gamma, weights), figures);
    };
  }
  PlanResult result = Prm(prm, std::move(parts)).plan(ctx, stop, rng);
  const double reused = settings_.reuse_training ? static_cast<double>(model.training.size()) : 0.0;
  result.extra["planning_nodes"] = static_cast<double>(result.nodes) - reused;
  return result;
}

}  // namespace amp::roadmap
