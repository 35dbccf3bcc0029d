#pragma once
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "amp/roadmap/uas/hybrid_sampler.hpp"
#include "amp/roadmap/planner.hpp"
#include "amp/roadmap/uas/sampler_bandit.hpp"
#include "amp/roadmap/samplers/sampling_domain.hpp"
#include "amp/roadmap/uas/uas_regions.hpp"

namespace amp::roadmap {


// How UAS picks the region that draws the next m samples.
enum class RegionSchedule : std::uint8_t {
  kRoundRobin = 0,  // the paper: every region in turn
  // Beyond the paper: a bandit over regions with the same reward and cost as the samplers (EXP3,
  // gamma as theirs), so that regions already covered (their samples are all cc-oversample) get
  // fewer rounds; every region keeps at least gamma / |regions| of them.
  kAdaptive = 1,
  // Beyond the paper: a smooth weighted round robin (deterministic), region j weighted by 1 + the
  // number of its training nodes below visibility 1/2 (the cc-expand threshold): regions where the
  // training roadmap saw narrow space get more rounds, open regions fewer.
  kWeighted = 2,
};

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

// Samples region by region, m at a time, each region by its own Hybrid PRM (sampler set restricted to
// the region's box); the reward of a sample goes to the region that drew it. The next region is the
// next in turn (round robin) or drawn by a bandit over regions (adaptive).
class RegionalSampler final : public AdaptiveSampler {
 public:
  // Throws ParameterError for no regions or m < 1.
  // `weights` (kWeighted only): one positive weight per region.
  RegionalSampler(std::vector<std::unique_ptr<HybridSampler>> regions, int m,
                  RegionSchedule schedule = RegionSchedule::kRoundRobin, double gamma = 0.5,
                  std::vector<double> weights = {});
  bool sample(core::Rng& rng, State& out) override;
  void reward_last(const Insertion& insertion) override;
  void observe(const Roadmap& roadmap, const Insertion& insertion) override;  // tells every region
  // samples_/chosen_<sampler> summed over regions; region<i>_prob_<sampler> per region.
  void report(std::map<std::string, double>& extra) const override;
  std::size_t regions() const { return regions_.size(); }
  const HybridSampler& region(std::size_t i) const { return *regions_[i]; }

 private:
  std::size_t next_weighted();

  std::vector<std::unique_ptr<HybridSampler>> regions_;
  int m_;
  RegionSchedule schedule_;
  SamplerBandit region_bandit_;
  std::size_t current_ = 0;
  int drawn_in_round_ = 0;
  std::size_t last_ = 0;
  bool pending_ = false;
  std::uint64_t total_cost_ = 0, costed_ = 0;  // running mean of the rewarded samples' CD calls
  std::vector<std::uint64_t> rounds_;
  std::vector<double> weights_, credit_;  // smooth weighted round robin
};

// UAS, the unsupervised adaptive strategy (seed paper, Algorithm 2.1): a training roadmap (Phase
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
