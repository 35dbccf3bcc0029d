#pragma once
#include <array>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "amp/learn/case_library.hpp"
#include "amp/learn/splitting_cases.hpp"
#include "amp/nav/sins/motor_schemas.hpp"

namespace amp::core {
class Rng;
}

namespace amp::nav {

// How the schema parameters are chosen while the robot drives: the three systems Ram & Santamaria
// (1993, Sec. 3) compare. A policy lives for a whole sequence of worlds, so what it learns carries
// from one world to the next. Implementations: StaticParameters, RandomParameters,
// CaseBasedParameters (SINS).
class ParameterPolicy {
 public:
  virtual ~ParameterPolicy() = default;
  // "static", "random" or "adaptive".
  virtual std::string_view name() const = 0;
  // A new world begins: the parameters to start it with.
  virtual SchemaParameters begin_world(core::Rng& rng) = 0;
  // A control interval ended with these perceived inputs (EnvironmentTrends::close_interval): the
  // parameters for the next one. Allocates nothing.
  virtual SchemaParameters end_interval(const learn::CaseInputs& inputs, core::Rng& rng) = 0;
  // The world ended: solved or not, after this share of its step limit. (A world stopped by a
  // time limit does not end.)
  virtual void end_world(bool /*solved*/, double /*steps_fraction*/) {}
  // Cases in memory (0 for the systems that keep none).
  virtual int cases() const { return 0; }
};

// The static system: the same parameters throughout (by default the middle of every range).
class StaticParameters final : public ParameterPolicy {
 public:
  explicit StaticParameters(SchemaParameters p = SchemaParameters::middle());  // throws ParameterError
  std::string_view name() const override { return "static"; }
  SchemaParameters begin_world(core::Rng&) override { return p_; }
  SchemaParameters end_interval(const learn::CaseInputs&, core::Rng&) override { return p_; }

 private:
  SchemaParameters p_;
};

// The random system: every parameter drawn uniformly over its range at the start of each world and
// after every control interval (four draws, in the order of SchemaParameters).
class RandomParameters final : public ParameterPolicy {
 public:
  std::string_view name() const override { return "random"; }
  SchemaParameters begin_world(core::Rng& rng) override { return draw(rng); }
  SchemaParameters end_interval(const learn::CaseInputs&, core::Rng& rng) override { return draw(rng); }
  static SchemaParameters draw(core::Rng& rng);
};

// What the last cycle of the adaptive system did, for figures and tests.
struct CaseCycle {
  learn::CaseMatch match;
  learn::Learned learned = learn::Learned::kKept;
  double relative_similarity = 1.0;
};

// SINS (Ram & Santamaria 1993, Sec. 2.4): at the end of every control interval, perceive (the
// inputs join the history with the parameters that were in use), retrieve the best case and
// alignment, adapt (install its recommended parameters with exploration scaled by the mismatch), and
// learn from the use. Each world starts from `initial` (the static system's parameters: "SINS would
// also start out with those same settings") with an empty history; the cases carry over.
//
// Two AMP additions, because the paper's rule as reconstructed has no pull toward better parameters
// (measured in docs/sins.md): each interval's reward is its progress toward the goal,
// r = clamp(2 (Motion-Towards-Goal - 0.5), 0, 1), and reinforcement moves outputs in proportion to
// it (learn::CaseSettings::reward_weighted); and the exploration spread is at least
// stall_exploration x (1 - r), so a robot that stalls in a well-matched situation still searches.
// stall_exploration = 0 and reward_weighted = false give the paper's rule.
class CaseBasedParameters final : public ParameterPolicy {
 public:
  // Throws ParameterError for bad settings or parameters, or stall_exploration outside [0, 1].
  explicit CaseBasedParameters(learn::CaseSettings settings = {}, SchemaParameters initial = SchemaParameters::middle(),
                               double stall_exploration = kStallExploration);
  static constexpr double kStallExploration = 0.5;
  std::string_view name() const override { return "adaptive"; }
  SchemaParameters begin_world(core::Rng& rng) override;
  SchemaParameters end_interval(const learn::CaseInputs& inputs, core::Rng& rng) override;
  int cases() const override { return library_.size(); }
  // With CaseSettings::outcome_rate > 0, the outcome credit: the world's return
  // R = solved ? 1 - steps_fraction : 0 against a running baseline b (b += 0.1 (R - b); the first
  // world sets it), and every output sample the world used moves toward the mean of the outputs
  // installed from it by outcome_rate x (R - b), away from them when R < b (REINFORCE with a
  // baseline, Williams 1992, on the adapt step's exploration). Otherwise nothing.
  void end_world(bool solved, double steps_fraction) override;
  static constexpr double kBaselineRate = 0.1;
  double baseline() const { return baseline_; }

  const learn::CaseLibrary& library() const { return library_; }
  const learn::CaseHistory& history() const { return history_; }
  // The last cycle (none before the first interval ends).
  const std::optional<CaseCycle>& last_cycle() const { return last_; }

 private:
  learn::CaseLibrary library_;
  learn::CaseHistory history_;
  SchemaParameters initial_, current_;
  double stall_exploration_;
  std::optional<CaseCycle> last_;
  // Per output sample (case j, sample q at j * case_length + q): the outputs installed from it this
  // world, summed, and how many times (sized for max_cases up front: nothing allocates per step).
  std::vector<learn::CaseOutputs> installed_sum_;
  std::vector<int> installed_count_;
  double baseline_ = 0.0;
  bool has_baseline_ = false;
};

// The system by name: "static" (StaticParameters(initial)), "random", "adaptive" (also "sins":
// CaseBasedParameters(cases, initial, stall_exploration), which SinsSettings carries) or
// "sins-plus" (SplittingCaseParameters(plus, initial), sins_plus_parameters.hpp). Throws
// ParameterError naming the choices for another name.
std::unique_ptr<ParameterPolicy> make_parameter_policy(
    const std::string& system, const learn::CaseSettings& cases, const SchemaParameters& initial,
    double stall_exploration, const learn::SplittingCaseSettings& plus = {});

}  // namespace amp::nav
