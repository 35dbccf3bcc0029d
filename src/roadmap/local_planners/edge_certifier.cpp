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
  // Advance alternately from both ends; [0, lo] and [hi, 1] are proven free.
  double lo = 0.0, hi = 1.0;
  for (unsigned step = 0;; ++step) {
    if (stop_ != nullptr && step % kPollEvery == kPollEvery - 1 && stop_->should_stop(0)) break;
    const bool from_start = step % 2 == 0;
    space_->interpolate(a, b, from_start ? lo : hi, scratch_);
    const double advance = kStepShare * checker_->free_share(scratch_, a, b);
    if (!(advance >= kMinStep)) break;
    if (from_start) {
      lo += advance;
    } else {
      hi -= advance;
    }
    if (lo >= hi) {
      ++certified_;
      return true;
    }
  }
  ++refused_;
  return false;
}

void EdgeCertifier::report(std::map<std::string, double>& extra) const {
  extra["certified_segments"] += static_cast<double>(certified_);
  extra["refused_segments"] += static_cast<double>(refused_);
}

}  // namespace amp::roadmap
