#pragma once
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "amp/nav/sins/sins_run.hpp"

namespace amp::bench {

// The calibration of SINS's lost scale to the paper's two baselines (docs/sins.md, "The calibrated
// scale"). Ram & Santamaria's final table gives, at 25% clutter, the static system at the middle of
// the ranges 14.5% solved and the random system 41.5%; their world size, robot speed and step limit
// are lost. The search keeps the robot and scales the world (nav::SinsScale::factor); for each
// factor the step limit is the one at which the random system solves its share, and the factor is
// bisected until the static system solves its share at that limit. Neither SINS nor any learning
// system takes part, so the scale is not tuned to the system the paper is about.
struct SinsCalibrationSettings {
  nav::SinsSettings base;          // everything but the scale (the clutter: 25%, the paper's)
  double static_target = 0.145;    // the paper's final table
  double random_target = 0.415;
  std::uint64_t seed = 20261207;   // the calibration sequences' master seed: used for nothing else
  int search_sequences = 4;        // sequences of base.worlds worlds per factor tried
  int limit_sequences = 20;        // sequences that read the step limit at the chosen factor
  int sequences = 10;              // sequences of the check at the chosen scale
  double factor_low = 1.0;         // the bracket: the static system must solve less than its
  double factor_high = 2.5;        // share at the low end and more at the high end
  int bisections = 6;
  double factor_step = 0.01;       // the chosen factor is rounded to this
  int probe_step_limit = 2000;     // the random system's runs that find the step limit

  // Throws ParameterError (one line) for targets outside (0, 1), counts below 1, or a bracket that
  // is not 0 < low < high.
  void validate() const;
};

// One factor tried: the random system's step limit there and what the static system solves at it.
struct ScaleProbe {
  double factor = 0.0;
  int step_limit = 0;          // the least limit at which the random system solves random_target
  double random_solved = 0.0;  // at that limit, from the probe runs (at least the target)
  double static_solved = 0.0;  // a real run at that limit
};

// A system's solved share over the check's sequences: the mean and Student's t 95% interval of the
// per-sequence shares (stats::describe).
struct SolvedShare {
  std::vector<double> per_sequence;
  double mean = 0.0, ci95_low = 0.0, ci95_high = 0.0;
  bool holds(double target) const { return ci95_low <= target && target <= ci95_high; }
};

struct SinsCalibration {
  std::vector<ScaleProbe> probes;  // in the order tried
  nav::SinsScale scale;            // the chosen factor and step limit (name "calibrated")
  SolvedShare static_share, random_share;  // the check at that scale
  bool reached = false;            // both targets inside their intervals
  std::string why;                 // one line when not reached
};

// The search; the step limit read again at the chosen factor on `limit_sequences` further sequences
// (the last probe); then the check: real runs of both systems at that scale on `sequences` fresh
// sequences of the calibration seed, which neither the search nor the limit has seen. Sequence i of
// a stage uses the seed derive_seed(seed, i) (the check's start after the search's), and every
// system meets the same worlds. Deterministic: the result depends only on the settings. `on_probe`
// (optional) sees each factor as it is measured.
SinsCalibration calibrate_sins_scale(const SinsCalibrationSettings& settings,
                                     const std::function<void(const ScaleProbe&)>& on_probe = {});

}  // namespace amp::bench
