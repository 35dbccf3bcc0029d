#include "amp/roadmap/uas/regional_sampler.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "amp/core/error.hpp"

namespace amp::roadmap {

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

}  // namespace amp::roadmap
