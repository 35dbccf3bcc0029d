#pragma once
#include <string_view>

#include "amp/learn/splitting_cases.hpp"
#include "amp/nav/sins/parameter_policy.hpp"

namespace amp::nav {

// sins-plus (docs/sins.md, "sins-plus"): the schema parameters chosen every control interval by a
// learn::SplittingCaseLibrary, an AMP system beyond Ram & Santamaria (1993). An interval's reward is
// its progress toward the goal, 2 Motion-Towards-Goal - 1 in [-1, 1] (the distance gained over the
// distance the robot could drive); a choice's credit is the mean reward over `horizon` intervals
// from it, so a pull that ends in a trap is paid for; a solved world fills the horizons it cut short
// with 1 (nothing is faster than arriving), a world at its step limit with the mean seen. Each world
// starts from the case retrieved for the empty interval's inputs (EnvironmentTrends: density 0,
// motion 0, relative motion and progress 0.5); the cases carry over from world to world, the first
// recommending `initial` (the middle of the ranges by default). No rule is written in: what each
// situation gets is learned from the sequence.
class SplittingCaseParameters final : public ParameterPolicy {
 public:
  // Throws ParameterError for bad settings or parameters.
  explicit SplittingCaseParameters(learn::SplittingCaseSettings settings = {},
                                   SchemaParameters initial = SchemaParameters::middle());
  std::string_view name() const override { return "sins-plus"; }
  SchemaParameters begin_world(core::Rng& rng) override;
  SchemaParameters end_interval(const learn::CaseInputs& inputs, core::Rng& rng) override;
  void end_world(bool solved, double steps_fraction) override;
  int cases() const override { return library_.size(); }
  const learn::SplittingCaseLibrary& library() const { return library_; }

  // What EnvironmentTrends::close_interval reports for an interval of no steps: a world's first choice.
  static constexpr learn::CaseInputs kStartInputs{0.0, 0.0, 0.5, 0.5};

 private:
  learn::SplittingCaseLibrary library_;
};

}  // namespace amp::nav
