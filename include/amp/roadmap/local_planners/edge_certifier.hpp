#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <map>
#include <string>

#include "amp/core/space.hpp"
#include "amp/core/stop_condition.hpp"
#include "amp/roadmap/local_planners/local_planner.hpp"
#include "amp/world/validity_checker.hpp"

namespace amp::roadmap {

// Proves that the whole segment a -> b of the space's interpolation is free, not only its sample
// points, by conservative advancement: at parameter t the robot is free by at least
// r = checker.free_radius(q(t)), and no robot point moves by more than L = checker.motion_bound(a, b)
// over the whole segment (t in [0, 1]), so every t' with |t' - t| * L < r is free as well. The
// checker gives that share (ValidityChecker::free_share): an arm's checker weighs each part's
// distance against that part's own motion, a larger share. The ends are measured first, then the
// centre of every stretch not yet proven, whose share proves as much on either side, until the
// proven stretches cover the segment. A share below a billionth of the segment (the robot is
// touching or almost touching) ends the proof: the segment is refused, a conservative answer. Each
// state costs one counted clearance call, no CD call.
class EdgeCertifier {
 public:
  // stop (optional) is polled between steps so that a long proof cannot run past a run's limits;
  // a stopped proof refuses the segment.
  EdgeCertifier(const core::Space& space, const world::ValidityChecker& checker,
                const core::StopCondition* stop = nullptr);

  // a and b are assumed valid states of the space.
  bool certify(const State& a, const State& b);

  std::uint64_t segments_certified() const { return certified_; }
  std::uint64_t segments_refused() const { return refused_; }
  // Adds certified_segments and refused_segments to a run's extra figures.
  void report(std::map<std::string, double>& extra) const;

 private:
  struct Gap {
    double lo, hi;  // a stretch of the segment not yet proven free
  };
  bool prove(const State& a, const State& b);
  // The share proven on either side of the state at t (with a safety factor).
  double proven_share(const State& a, const State& b, double t);

  const core::Space* space_;
  const world::ValidityChecker* checker_;
  const core::StopCondition* stop_;
  State scratch_;
  std::array<Gap, 64> gaps_{};  // pending stretches, depth first
  std::uint64_t certified_ = 0;
  std::uint64_t refused_ = 0;
};

// A local planner whose straight edges are also certified: `inner` checks first (a blocked edge is
// usually refused after a few CD calls), then the certifier proves what passed. For planners whose
// edges are straight segments (shortcuts, RRT extensions).
class CertifiedLocalPlanner final : public LocalPlanner {
 public:
  CertifiedLocalPlanner(LocalPlanner& inner, EdgeCertifier& certifier) : inner_(&inner), certifier_(&certifier) {}
  bool connect(const State& a, const State& b) override { return inner_->connect(a, b) && certifier_->certify(a, b); }

 private:
  LocalPlanner* inner_;
  EdgeCertifier* certifier_;
};

}  // namespace amp::roadmap
