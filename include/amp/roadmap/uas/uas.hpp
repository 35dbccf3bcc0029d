#pragma once
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "amp/roadmap/uas/hybrid_sampler.hpp"
#include "amp/roadmap/uas/regional_sampler.hpp"
#include "amp/roadmap/planner.hpp"
#include "amp/roadmap/uas/sampler_bandit.hpp"
#include "amp/roadmap/samplers/sampling_domain.hpp"
#include "amp/roadmap/uas/uas_regions.hpp"

namespace amp::roadmap {

struct UasSettings {
  RegionSettings regions;  // training roadmap, clustering, region growth
  int m = 10;              // samples per region per round
  // Weighted by default: with the paper's equal turns, open regions took as many samples as narrow
  // ones and UAS was no cheaper than global Hybrid PRM on the Maze (docs/uas.md).
  RegionSchedule schedule = RegionSchedule::kWeighted;
  int k = 20;              // neighbours tried per new node, in the whole roadmap
  HybridSettings hybrid;   // each region's Hybrid PRM
  bool bridge = false;     // the bridge test as a fifth sampler in every region
  bool expansion = false;  // PRM's expansion step as one more sampler in every region
  // Start the planning roadmap from the training roadmap (its nodes and checked edges), so the
  // training CD calls also buy roadmap. Off: the paper's separate training and planning roadmaps.
  bool reuse_training = true;
  // Beyond the paper: the whole space takes its turn in the round robin as one more region. Boxes of
  // training nodes need not cover every passage; without this, a passage outside every box is never
  // sampled and the run cannot finish (seen on the Maze, 2 of 100 runs stuck at 50000 nodes).
  bool whole_space_region = true;
  // How every region (and the whole-space region) draws its states; see DrawSequence.
  DrawSequence sequence = DrawSequence::kRandom;
  static const core::SettingsSchema<UasSettings>& schema();
  void validate() const;  // throws ParameterError
};

// UAS, the unsupervised adaptive strategy (docs/uas.md; Algorithm 2.1): a training roadmap (Phase
// kTraining), regions by clustering its nodes' visibility and positions, then PRM whose samples come
// from a Hybrid PRM per region in round robin, connected to the k nearest in the whole roadmap,
// until the seeds are connected or the run's limits. One cluster: one region, the whole space, i.e.
// global Hybrid PRM (extra uas_fallback_global = 1).
class Uas final : public Planner {
 public:
  explicit Uas(UasSettings settings = {});
  PlanResult plan(const PlanningContext& ctx, const core::StopCondition& stop, core::Rng& rng) override;

 private:
  UasSettings settings_;
};


}  // namespace amp::roadmap
