#pragma once
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "amp/core/halton_sequence.hpp"
#include "amp/core/rng.hpp"
#include "amp/core/settings_schema.hpp"
#include "amp/core/space.hpp"
#include "amp/core/state.hpp"

namespace amp::world {
class PlanningFeatures;
}

namespace amp::roadmap {

// How a domain draws its states (beyond the papers): independent random states, or a randomised Halton
// sequence through Space::from_unit, which covers the domain evenly, so the number of draws before
// a small passage is hit varies far less from run to run (docs/uas.md).
enum class DrawSequence : std::uint8_t { kRandom = 0, kHalton = 1 };
DrawSequence parse_draw_sequence(const std::string& name);  // "random" | "halton"; throws ParameterError

// The `sequence` parameter of a planner whose Settings S have a DrawSequence `sequence`.
template <class S>
core::SettingsField<S> sequence_field(std::string help) {
  return core::enum_field<S>(
      "sequence", &S::sequence,
      std::vector<std::pair<std::string, DrawSequence>>{{"random", DrawSequence::kRandom}, {"halton", DrawSequence::kHalton}},
      std::move(help));
}

// Uniform states of a space, random or from a Halton sequence made on first use from the run's Rng.
class StateDrawer {
 public:
  StateDrawer(const core::Space& space, DrawSequence sequence) : space_(&space), sequence_(sequence) {}
  void draw(core::Rng& rng, State& out);

 private:
  const core::Space* space_;
  DrawSequence sequence_;
  std::optional<core::HaltonSequence> halton_;
  std::vector<double> u_;
};

// Where a sampler draws its uniform states: the whole space, or a region of it (UAS runs one Hybrid
// PRM per region, each sampling inside the region's box). Drawing costs no CD call.
class SamplingDomain {
 public:
  virtual ~SamplingDomain() = default;
  // A state uniform in the domain (and in the space's bounds), or false after a bounded number of
  // rejected draws (a region may be a thin sliver of the space). Not const in effect: a Halton
  // domain advances its sequence (a domain belongs to one run).
  virtual bool sample(core::Rng& rng, State& out) const = 0;
  virtual bool contains(const State& s) const = 0;
};

// The whole space.
class WholeSpaceDomain final : public SamplingDomain {
 public:
  explicit WholeSpaceDomain(const core::Space& space, DrawSequence sequence = DrawSequence::kRandom)
      : space_(&space), drawer_(space, sequence) {}
  bool sample(core::Rng& rng, State& out) const override;
  bool contains(const State& s) const override { return space_->in_bounds(s); }

 private:
  const core::Space* space_;
  mutable StateDrawer drawer_;
};

// A box over the robot's reference point (Environment::reference_point: the position of a rigid
// body, the end effector of an arm), the form UAS regions take. Rejection sampling from the space:
// exact for every robot, and cheap because drawing needs forward kinematics only, never a CD call.
class ReferencePointBoxDomain final : public SamplingDomain {
 public:
  // Draws before sample() gives up.
  static constexpr int kMaxDraws = 10000;

  // Planar worlds: the box's z range is ignored. Throws ParameterError for an empty box.
  ReferencePointBoxDomain(const core::Space& space, const world::PlanningFeatures& features, Eigen::AlignedBox3d box,
                          DrawSequence sequence = DrawSequence::kRandom);
  bool sample(core::Rng& rng, State& out) const override;
  bool contains(const State& s) const override;
  const Eigen::AlignedBox3d& box() const { return box_; }

 private:
  const core::Space* space_;
  const world::PlanningFeatures* features_;
  Eigen::AlignedBox3d box_;
  bool planar_;
  // Rejection keeps a low-discrepancy sequence low-discrepancy inside the box: the accepted points
  // are the sequence's points that fall in it.
  mutable StateDrawer drawer_;
};

// The domain a null pointer stands for: the whole space.
std::shared_ptr<const SamplingDomain> domain_or_whole(std::shared_ptr<const SamplingDomain> domain,
                                                      const core::Space& space,
                                                      DrawSequence sequence = DrawSequence::kRandom);

}  // namespace amp::roadmap
