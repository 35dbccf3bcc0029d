#include "amp/roadmap/local_planners/edge_certifier.hpp"

#include <cmath>

namespace amp::roadmap {

namespace {
// Steps take 0.99 of the proven distance, so that a free radius that is exact only to rounding
// (FCL's GJK on primitives) still leaves the stepped-to state strictly free.
constexpr double kStepShare = 0.99;
// Below this share of the segment per step the robot is touching an obstacle along the edge:
// a billion steps would not finish the proof, so the segment is refused.
constexpr double kMinStep = 1e-9;
// The stop condition is read every so many steps.
constexpr unsigned kPollEvery = 64;
}  // namespace

EdgeCertifier::EdgeCertifier(const core::Space& space, const world::ValidityChecker& checker,
                             const core::StopCondition* stop)
    : space_(&space), checker_(&checker), stop_(stop) {}

bool EdgeCertifier::certify(const State& a, const State& b) {
  const double bound = checker_->motion_bound(a, b);
  if (!std::isfinite(bound)) {
    ++refused_;
    return false;
  }
  if (bound <= 0.0) {  // nothing moves: the endpoints' validity is the segment's
    ++certified_;
    return true;
  }
  const bool proven = prove(a, b);
  ++(proven ? certified_ : refused_);
  return proven;
}

double EdgeCertifier::proven_share(const State& a, const State& b, double t) {
  space_->interpolate(a, b, t, scratch_);
  return kStepShare * checker_->free_share(scratch_, a, b);
}

// Each state proves a share on both of its sides; the ends first, then the centre of each gap left
// between proven stretches, until none is left. A centre's share covers as much behind it as ahead,
// where stepping from a front uses only what lies ahead: about half the states for the same
// clearance. Gaps at least halve at each split, and one under 2 * kMinStep is closed by any state
// that is not refused, so at most ~30 are pending at once.
bool EdgeCertifier::prove(const State& a, const State& b) {
  const double s0 = proven_share(a, b, 0.0);
  if (!(s0 >= kMinStep)) return false;
  const double s1 = proven_share(a, b, 1.0);
  if (!(s1 >= kMinStep)) return false;
  std::size_t pending = 0;
  if (s0 < 1.0 - s1) gaps_[pending++] = {s0, 1.0 - s1};
  for (unsigned step = 0; pending > 0; ++step) {
    if (stop_ != nullptr && step % kPollEvery == kPollEvery - 1 && stop_->should_stop(0)) return false;
    const Gap g = gaps_[--pending];
    const double t = 0.5 * (g.lo + g.hi);
    const double s = proven_share(a, b, t);
    if (!(s >= kMinStep)) return false;
    if (pending + 2 > gaps_.size()) return false;  // cannot happen (see above); refusing is safe
    if (t - s > g.lo) gaps_[pending++] = {g.lo, t - s};
    if (t + s < g.hi) gaps_[pending++] = {t + s, g.hi};
  }
  return true;
}

void EdgeCertifier::report(std::map<std::string, double>& extra) const {
  extra["certified_segments"] += static_cast<double>(certified_);
  extra["refused_segments"] += static_cast<double>(refused_);
}

}  // namespace amp::roadmap
