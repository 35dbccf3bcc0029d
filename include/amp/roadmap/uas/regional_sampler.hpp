#pragma once
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "amp/roadmap/uas/hybrid_sampler.hpp"
#include "amp/roadmap/samplers/sampler.hpp"
#include "amp/roadmap/uas/sample_learner.hpp"
#include "amp/roadmap/uas/sampler_bandit.hpp"

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

// Samples region by region, m at a time, each region by its own Hybrid PRM (sampler set restricted to
// the region's box); the reward of a sample goes to the region that drew it. The next region is the
// next in turn (round robin) or drawn by a bandit over regions (adaptive).
class RegionalSampler final : public Sampler, public SampleLearner {
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

}  // namespace amp::roadmap
