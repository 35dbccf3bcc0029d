#pragma once
#include "amp/core/settings_schema.hpp"
#include "amp/core/space.hpp"
#include "amp/roadmap/planner.hpp"

namespace amp::roadmap {

struct RrtConnectSettings {
  // Longest extension step, in the space's metric; 0 takes OMPL's default (kDefaultRangeFraction of
  // the space's maximum extent).
  double range = 0.0;
  static const core::SettingsSchema<RrtConnectSettings>& schema();
  void validate() const { schema().validate(*this); }  // throws ParameterError unless range is in [0, 1e12]
};

// OMPL's default range: 0.2 x the space's maximum extent (RRTConnect::setup, maxDistance_).
inline constexpr double kDefaultRangeFraction = 0.2;

// The step a run takes with `settings` on `space`.
double effective_range(const RrtConnectSettings& settings, const core::Space& space);

// RRT-Connect (Kuffner & LaValle 2000, "RRT-Connect: An efficient approach to single-query path
// planning"), as OMPL's RRTConnect: two trees, rooted at the two ends of a leg, take turns to EXTEND
// one step of at most `range` towards a uniform sample; when that succeeds the other tree CONNECTs,
// extending greedily towards the new node until it reaches it (the trees meet) or is trapped. No goal
// bias. With more than two seeds, each consecutive pair is one leg, solved in order with fresh trees
// under the one StopCondition; the path runs seed 0 -> seed 1 -> ...
//
// Edges: a new state is checked with ValidityChecker::is_valid, then its edge from the tree node by
// StraightLinePlanner (kDiscrete) or EdgeCertifier (kCertified). In kDiscrete mode the path found
// when the trees meet is certified segment by segment; a refused tree edge is cut together with the
// subtree below it (whose nodes leave the trees and their KD-tree), a refused meeting edge is
// dropped, and the search goes on.
//
// PlanResult: `nodes` the live tree nodes of every leg tried (a seed shared by two legs counted once,
// so that it equals the drawn roadmap's vertices), `edges` their tree edges plus one meeting edge per
// solved leg, `components` the connected components of that forest (1 when solved, +1 for the
// unsolved leg's goal tree otherwise), `roadmap` the forest. Extra: range, legs_solved,
// certify_refused (meeting-time refusals), nodes_cut, and the certifier's report.
class RrtConnect final : public Planner {
 public:
  explicit RrtConnect(RrtConnectSettings settings = {});
  PlanResult plan(const PlanningContext& ctx, const core::StopCondition& stop, core::Rng& rng) override;
  const RrtConnectSettings& settings() const { return settings_; }

 private:
  RrtConnectSettings settings_;
};

}  // namespace amp::roadmap
