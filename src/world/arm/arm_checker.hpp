#pragma once
// Private: the ValidityChecker of an ArmEnvironment.
#include <memory>
#include <string>

#include "amp/world/arm_environment.hpp"
#include "amp/world/validity_checker.hpp"

namespace amp::world::detail {

// FCL on the posed link geometry: self pairs first (cheap, no broad phase), then each part against
// the scene's broad phase. Distances for certification: the scene clearance, and half the
// distance of each self pair (both links may move toward each other). Scratch buffers are made
// once, so a check allocates nothing.
class ArmChecker final : public ValidityChecker {
 public:
  ArmChecker(const ArmEnvironment& env, core::Counters& counters);
  ~ArmChecker() override;
  // ArmEnvironment::first_contact: the first colliding pair in check()'s order, named. Counts nothing.
  std::string first_contact(const State& s) const;

 private:
  struct Scratch;
  bool check(const State& s) const override;
  Clearance compute_clearance(const State& s) const override;
  double compute_free_radius(const State& s) const override;
  double compute_motion_bound(const State& a, const State& b) const override;
  double compute_free_share(const State& s, const State& a, const State& b) const override;
  // Joint steps from a to b, absolute (continuous joints the short way), into the scratch buffer.
  const double* joint_steps(const State& a, const State& b) const;
  // free_share's two halves: the scene's parts and the self pairs, each lowering `share`;
  // false when s is not valid.
  bool scene_share(const double* steps, double& share) const;
  bool self_share(const double* steps, double& share) const;
  void place(const State& s) const;
  bool touches_scene(std::size_t part) const;

  const ArmEnvironment& env_;
  std::unique_ptr<Scratch> scratch_;
};

}  // namespace amp::world::detail
