#pragma once
#include <array>
#include <vector>

#include "amp/core/settings_schema.hpp"

namespace amp::core {
class Rng;
}  // namespace amp::core

namespace amp::learn {

// SINS's case vocabulary (Ram & Santamaria 1993, section 2.3): four perceived inputs and the four
// schema parameters in use. Every value is normalised to [0, 1] by the caller (nav maps each schema
// parameter's range onto [0, 1]), so that errors of different inputs are comparable.
inline constexpr int kCaseInputs = 4;   // Obstacle-Density, Absolute-Motion, Relative-Motion, Motion-Towards-Goal
inline constexpr int kCaseOutputs = 4;  // Obstacle-Gain, Goal-Gain, Noise-Gain, Noise-Persistence
using CaseInputs = std::array<double, kCaseInputs>;
using CaseOutputs = std::array<double, kCaseOutputs>;

struct CaseSettings {
  int max_cases = 10;               // the paper's max-cases: no case is created beyond this many
  int case_length = 4;              // samples per case and per history (the paper's case-length)
  double learning_rate = 0.5;       // lambda of the reinforcement update, in (0, 1]
  double new_case_threshold = 0.1;  // a relative similarity below this starts a new case, in [0, 1)
  // Reinforcement moves each aligned output sample toward the history's by learning_rate x the
  // overlap factor x that sample's reward (CaseHistory::push), so that outputs which paid off
  // attract the case and the others do not. An AMP addition: the paper's rule (false) has no such
  // term, and measured, it drifts from good parameters as readily as toward them (docs/sins.md).
  bool reward_weighted = true;
  // > 0: outputs learn from whole worlds instead (the caller's outcome credit, shift_outputs, at
  // this rate), and the interval's reinforcement moves the inputs only. An AMP addition
  // (docs/sins.md): an interval's progress is a myopic reward. 0: the interval rule above.
  double outcome_rate = 0.0;
  static const core::SettingsSchema<CaseSettings>& schema();
  void validate() const;  // throws ParameterError naming the setting
};

// The environment's recent history: the last `length` inputs perceived and the outputs in use when
// each was perceived. A ring buffer: input(0) is the oldest kept, input(size() - 1) the newest.
// Nothing allocates after construction.
class CaseHistory {
 public:
  explicit CaseHistory(int length);  // throws ParameterError for length < 1

  // `reward` in [0, 1] says how well the outputs did over the sample (used by reward-weighted
  // reinforcement; 1 when the caller has none). Throws ParameterError for a value outside [0, 1]
  // (or NaN); the history is then unchanged.
  void push(const CaseInputs& inputs, const CaseOutputs& outputs, double reward = 1.0);
  void clear() { start_ = size_ = 0; }

  int size() const { return size_; }
  int capacity() const { return static_cast<int>(inputs_.size()); }
  bool full() const { return size_ == capacity(); }
  const CaseInputs& input(int i) const { return inputs_[slot(i)]; }     // 0 <= i < size()
  const CaseOutputs& output(int i) const { return outputs_[slot(i)]; }  // 0 <= i < size()
  double reward(int i) const { return rewards_[slot(i)]; }               // 0 <= i < size()

 private:
  int slot(int i) const {
    const int s = start_ + i;
    return s < capacity() ? s : s - capacity();
  }
  std::vector<CaseInputs> inputs_;
  std::vector<CaseOutputs> outputs_;
  std::vector<double> rewards_;
  int start_ = 0;  // slot of the oldest sample
  int size_ = 0;
};

// One case: case_length samples of the inputs and of the recommended outputs (k = 0 the oldest),
// and the statistics of its past uses.
struct Case {
  std::vector<CaseInputs> inputs;
  std::vector<CaseOutputs> outputs;
  int uses = 0;             // n: how many times learn() has seen it used
  double mean_error = 0.0;  // Ebar: its mean match error over those uses
};

// A case aligned with the history: the history's newest `overlap` samples lie on the case's samples
// position - overlap .. position - 1 (the newest on position - 1), with mean squared difference
// `error` per value, in [0, 1].
struct CaseMatch {
  int case_index = 0;
  int position = 1;  // p, 1 .. case_length
  int overlap = 0;   // o = min(history size, p)
  double error = 1.0;
};

enum class Learned {
  kReinforced,  // the case moved toward the history
  kKept,        // the case was left alone
  kCreated,     // a new case, a copy of the history, was added
  kFull,        // a new case was due, but the library already holds max_cases
};

// The case library of SINS (Ram & Santamaria 1993, "A Multistrategy Case-Based and Reinforcement
// Learning Approach to Self-Improving Reactive Control Systems for Autonomous Robotic Navigation",
// section 2.4): retrieve the case whose inputs best match the recent history, adapt its recommended
// outputs with exploration, and learn from the use. The paper's formulas survive only garbled;
// docs/sins.md gives the reconstruction implemented here.
//
// retrieve, adapt and learn allocate nothing (capacity for max_cases cases is reserved up front,
// so even a created case's slot does not reallocate the library; its two vectors are new).
class CaseLibrary {
 public:
  // One generic case, every value 0.5: the paper's cases start "under-constrained and generic".
  explicit CaseLibrary(CaseSettings settings = {});  // throws ParameterError
  // A library restored as it was (1 .. max_cases cases of case_length samples, values in [0, 1]).
  CaseLibrary(CaseSettings settings, std::vector<Case> cases);  // throws ParameterError

  // The best case and alignment over every case and every alignment of the reverse sweep
  // p = case_length .. 1: least error, then the larger overlap, then the lower case index, then the
  // larger p. An empty history matches case 0 at p = 1 with overlap 0 and error 1 (nothing known).
  // Throws ParameterError when env's capacity is not case_length.
  CaseMatch retrieve(const CaseHistory& env) const;
  // Case j aligned at p (1 .. case_length) with env, as retrieve scores it; throws ParameterError
  // for a j or p out of range.
  CaseMatch match(int j, int p, const CaseHistory& env) const;

  // The case's outputs at min(p, case_length - 1), the sample after the aligned part (or the
  // last), each plus s * u, u ~ U(-1, 1) drawn in output order, clamped to [0, 1], where the
  // spread s = max(sqrt(error), min_spread) (min_spread clamped to [0, 1]).
  CaseOutputs adapt(const CaseMatch& m, core::Rng& rng, double min_spread = 0.0) const;

  // Ebar / E for the case's past uses (1 before its first use). Both are floored at 1e-12, so a
  // case that has always matched exactly and does so again scores 1, not 0.
  double relative_similarity(const CaseMatch& m) const;
  // The reinforcement step: reinforce (relative similarity >= 1), create a case from the history
  // (below new_case_threshold with a full history), or keep; then the use is recorded on the case
  // matched. `m` must come from retrieve() or match() on this `env`.
  Learned learn(const CaseMatch& m, const CaseHistory& env);
  // Moves case j's output sample q toward `toward` by `weight` (negative: away), each value
  // clamped to [0, 1]: the outcome credit of CaseSettings::outcome_rate. Throws ParameterError for
  // a j or q out of range.
  void shift_outputs(int j, int q, const CaseOutputs& toward, double weight);

  int size() const { return static_cast<int>(cases_.size()); }
  const Case& at(int j) const { return cases_.at(static_cast<std::size_t>(j)); }
  const std::vector<Case>& cases() const { return cases_; }
  const CaseSettings& settings() const { return settings_; }

 private:
  CaseMatch score(int j, int p, const CaseHistory& env) const;  // match() unchecked
  void check_history(const CaseHistory& env) const;
  void check_match(const CaseMatch& m, const CaseHistory& env) const;

  CaseSettings settings_;
  std::vector<Case> cases_;
};

}  // namespace amp::learn
