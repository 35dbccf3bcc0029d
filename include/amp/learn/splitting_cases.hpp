#pragma once
#include <vector>

#include "amp/core/settings_schema.hpp"
#include "amp/learn/case_library.hpp"

namespace amp::core {
class Rng;
}  // namespace amp::core

namespace amp::learn {

struct SplittingCaseSettings {
  int max_cases = 10;            // no case is split beyond this many
  int horizon = 8;               // choices a choice's credit looks ahead over (itself included)
  double exploration = 0.2;      // half-width of the uniform exploration around a case's outputs
  double step = 0.05;            // how far one fit moves each output whose slope is significant
  int window = 64;               // credited uses each case keeps for its fits
  int refit_every = 16;          // credited uses between two fits of a case
  double step_t = 1.0;           // |t| of an output's slope that moves it
  double split_t = 2.0;          // |t| the two halves' slopes must both reach, with opposite signs
  double prototype_rate = 0.05;  // how far a case's inputs move toward each situation it is used in
  static const core::SettingsSchema<SplittingCaseSettings>& schema();
  void validate() const;  // throws ParameterError naming the setting
};

// A least-squares fit of a use's credit G against the outputs it used and the situation's inputs,
// G ~ c + g . a + h . x: the outputs' slopes g and each one's t statistic (0 where the fit is not
// determined: an output that did not vary, or fewer uses than the coefficients and 5 more).
struct OutputSlopes {
  CaseOutputs slope{};
  CaseOutputs t{};
  int uses = 0;
};

// One credited use of a case: the situation it was retrieved for, the outputs installed, and the
// credit, the mean reward over the `horizon` choices from it on.
struct CaseUse {
  CaseInputs inputs{};
  CaseOutputs outputs{};
  double credit = 0.0;
};

// A situated case: a prototype situation, the outputs it recommends, and its last credited uses.
struct SplittingCase {
  CaseInputs prototype{};
  CaseOutputs outputs{};
  std::vector<CaseUse> uses;  // a ring of `window` uses, the oldest at `next` once full
  int next = 0;
  int since_fit = 0;
  int fits = 0;
};

// sins-plus's learner (docs/sins.md, "sins-plus"): an AMP method beyond Ram & Santamaria (1993),
// for their cases' two weaknesses measured there: a reward of one interval, which cannot see that
// pulling toward the goal leads into a trap, and a rule for new cases that never splits a case
// whose uses need opposite outputs.
//
// - Retrieve: the case whose prototype is nearest the perceived inputs (squared distance); the
//   prototype moves toward them by prototype_rate.
// - Adapt: the case's outputs plus exploration x u, u ~ U(-1, 1) per output, clamped to [0, 1].
// - Credit: every choice's credit is the mean of the rewards of the `horizon` intervals it starts
//   (the episode's end fills the rest: `terminal` when given, else the mean of those seen).
// - Learn: every refit_every credited uses, the case's window is fitted, G ~ c + g . a + h . x
//   (least squares: the policy gradient of its exploration, the situation x held apart). If some
//   input splits the window at its median into halves whose slopes on one output are both
//   significant (|t| >= split_t) and of opposite signs, the case becomes two, one per half
//   (prototype the half's mean inputs), each stepped along its own half's slopes: the situations
//   want opposite outputs. Otherwise every output whose slope has |t| >= step_t moves by `step` in
//   the slope's direction.
//
// choose and reward allocate nothing but when a split creates a case (its window is new, at most
// max_cases - 1 times): every other buffer is sized up front.
class SplittingCaseLibrary {
 public:
  // One case: prototype every input 0.5, outputs `initial`. Throws ParameterError.
  SplittingCaseLibrary(SplittingCaseSettings settings, const CaseOutputs& initial);

  // A new episode: uses not yet credited are dropped.
  void begin_episode() { pending_size_ = 0; }
  // The outputs for the situation `inputs`: retrieve, adapt, and remember the choice for credit.
  CaseOutputs choose(const CaseInputs& inputs, core::Rng& rng);
  // The reward of the interval the last choice ran (every choice still within its horizon gets it).
  void reward(double r);
  // The episode ended; `terminal` (when >= -1) fills what the uncredited choices' horizons miss.
  void end_episode(double terminal);
  static constexpr double kNoTerminal = -2.0;

  int size() const { return static_cast<int>(cases_.size()); }
  const SplittingCase& at(int j) const { return cases_.at(static_cast<std::size_t>(j)); }
  const SplittingCaseSettings& settings() const { return settings_; }
  int last_case() const { return last_case_; }
  int splits() const { return splits_; }

  // The fit of `uses` (exposed for tests): slopes and t statistics of G on the outputs.
  static OutputSlopes fit(const CaseUse* const* uses, int n);

 private:
  struct Pending {
    int case_index = 0;
    CaseUse use;
    int rewards = 0;
  };
  int nearest(const CaseInputs& inputs) const;
  void credit(const Pending& p);
  void credit_oldest(int rewards);  // pops the oldest choice, its credit the mean of `rewards` rewards
  void learn(int j);
  bool try_split(int j);

  SplittingCaseSettings settings_;
  std::vector<SplittingCase> cases_;
  std::vector<Pending> pending_;  // a queue of at most horizon choices, oldest first
  int pending_size_ = 0;
  std::vector<const CaseUse*> scratch_, low_, high_;
  std::vector<double> keys_;
  int last_case_ = 0;
  int splits_ = 0;
};

}  // namespace amp::learn
