#include "amp/bench/sins_calibration.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "amp/core/error.hpp"
#include "amp/core/number_text.hpp"
#include "amp/core/rng.hpp"
#include "amp/learn/case_library.hpp"
#include "amp/nav/sins/parameter_policy.hpp"
#include "amp/stats/descriptive.hpp"

namespace amp::bench {

namespace {

std::string percent(double share) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f%%", 100.0 * share);
  return text;
}

// Sequences [first, first + count) of the master seed, each drawn once for every system.
struct Sequences {
  std::vector<std::uint64_t> seeds;
  std::vector<nav::SequenceWorlds> worlds;
};

Sequences draw(const nav::SinsSettings& s, std::uint64_t master, int first, int count) {
  Sequences out;
  for (int i = first; i < first + count; ++i) {
    out.seeds.push_back(core::derive_seed(master, static_cast<std::uint64_t>(i)));
    out.worlds.push_back(nav::draw_sequence_worlds(s, out.seeds.back()));
  }
  return out;
}

// Each sequence driven by a fresh baseline system (static or random) from the middle of the ranges.
std::vector<nav::SequenceOutcome> drive(const char* system, const nav::SinsSettings& s, const Sequences& seqs) {
  std::vector<nav::SequenceOutcome> out;
  for (std::size_t i = 0; i < seqs.seeds.size(); ++i) {
    const std::unique_ptr<nav::ParameterPolicy> policy =
        nav::make_parameter_policy(system, learn::CaseSettings{}, nav::SchemaParameters::middle(), s.stall_exploration);
    out.push_back(nav::run_sequence(*policy, s, seqs.seeds[i], seqs.worlds[i]));
  }
  return out;
}

double solved_share(const nav::SequenceOutcome& run) {
  const auto solved = std::count_if(run.worlds.begin(), run.worlds.end(), [](const auto& w) { return w.solved; });
  return run.worlds.empty() ? 0.0 : static_cast<double>(solved) / static_cast<double>(run.worlds.size());
}

double pooled_share(const std::vector<nav::SequenceOutcome>& runs) {
  double solved = 0.0, total = 0.0;
  for (const nav::SequenceOutcome& r : runs) {
    solved += solved_share(r) * static_cast<double>(r.worlds.size());
    total += static_cast<double>(r.worlds.size());
  }
  return total > 0.0 ? solved / total : 0.0;
}

// The least step limit at which `target` of all the worlds are solved, read from runs at a larger
// limit: a world solved in k steps is solved at every limit >= k. Empty when too few are solved.
std::optional<int> limit_for_share(const std::vector<nav::SequenceOutcome>& runs, double target) {
  std::vector<int> steps;
  std::size_t total = 0;
  for (const nav::SequenceOutcome& r : runs) {
    total += r.worlds.size();
    for (const nav::WorldOutcome& w : r.worlds) {
      if (w.solved) steps.push_back(w.steps);
    }
  }
  const auto need = static_cast<std::size_t>(std::ceil(target * static_cast<double>(total) - 1e-9));
  if (need == 0) return 1;
  if (steps.size() < need) return std::nullopt;
  std::nth_element(steps.begin(), steps.begin() + static_cast<std::ptrdiff_t>(need - 1), steps.end());
  return std::max(1, steps[need - 1]);
}

nav::SinsSettings at_scale(const nav::SinsSettings& base, double factor, int step_limit) {
  nav::SinsSettings s = base;
  s.set_scale({"probe", factor, step_limit, ""});
  return s;
}

// One factor on sequences [first, first + count): the random system at the probe limit gives the
// step limit, then the static system runs at it. Throws ParameterError naming the factor when the random system cannot reach its share.
ScaleProbe probe(const SinsCalibrationSettings& c, double factor, int first, int count) {
  const nav::SinsSettings wide = at_scale(c.base, factor, c.probe_step_limit);
  const Sequences seqs = draw(wide, c.seed, first, count);
  const std::vector<nav::SequenceOutcome> random = drive("random", wide, seqs);
  const std::optional<int> limit = limit_for_share(random, c.random_target);
  if (!limit) {
    throw ParameterError("at scale " + core::number_text(factor) + " the random system solves " + percent(pooled_share(random)) +
                         " within " + std::to_string(c.probe_step_limit) + " steps, less than its target " +
                         percent(c.random_target));
  }
  ScaleProbe p;
  p.factor = factor;
  p.step_limit = *limit;
  const nav::SinsSettings at_limit = at_scale(c.base, factor, *limit);
  std::size_t solved = 0, total = 0;  // the random system's share at that limit, from the same runs
  for (const nav::SequenceOutcome& r : random) {
    total += r.worlds.size();
    for (const nav::WorldOutcome& w : r.worlds) solved += (w.solved && w.steps <= *limit) ? 1 : 0;
  }
  p.random_solved = total > 0 ? static_cast<double>(solved) / static_cast<double>(total) : 0.0;
  p.static_solved = pooled_share(drive("static", at_limit, seqs));
  return p;
}

SolvedShare share_of(const std::vector<nav::SequenceOutcome>& runs) {
  SolvedShare s;
  for (const nav::SequenceOutcome& r : runs) s.per_sequence.push_back(solved_share(r));
  const stats::Summary d = stats::describe(s.per_sequence);
  s.mean = d.mean;
  // One sequence has no interval: it then holds only its own value.
  s.ci95_low = std::isnan(d.ci95_low) ? d.mean : d.ci95_low;
  s.ci95_high = std::isnan(d.ci95_high) ? d.mean : d.ci95_high;
  return s;
}

std::string interval(const SolvedShare& s) {
  return percent(s.mean) + " [" + percent(s.ci95_low) + ", " + percent(s.ci95_high) + "]";
}

}  // namespace

void SinsCalibrationSettings::validate() const {
  base.validate();
  const auto fail = [](const std::string& what) { throw ParameterError("sins calibration: " + what); };
  if (!(static_target > 0.0 && static_target < 1.0)) fail("static target " + core::number_text(static_target) + " is outside (0, 1)");
  if (!(random_target > 0.0 && random_target < 1.0)) fail("random target " + core::number_text(random_target) + " is outside (0, 1)");
  if (search_sequences < 1 || limit_sequences < 1 || sequences < 1 || bisections < 0 || probe_step_limit < 1) {
    fail("sequences, search sequences and the probe step limit must be >= 1, bisections >= 0");
  }
  if (!(factor_low > 0.0 && factor_low < factor_high && std::isfinite(factor_high))) {
    fail("the scale bracket [" + core::number_text(factor_low) + ", " + core::number_text(factor_high) + "] must have 0 < low < high");
  }
  if (!(factor_step > 0.0)) fail("the factor step must be > 0");
}

SinsCalibration calibrate_sins_scale(const SinsCalibrationSettings& c,
                                     const std::function<void(const ScaleProbe&)>& on_probe) {
  c.validate();
  SinsCalibration out;
  const auto measure = [&](double factor, int first = 0, int count = 0) {
    out.probes.push_back(probe(c, factor, first, count > 0 ? count : c.search_sequences));
    if (on_probe) on_probe(out.probes.back());
    return out.probes.back();
  };
  try {
    ScaleProbe low = measure(c.factor_low);
    ScaleProbe high = measure(c.factor_high);
    if (!(low.static_solved < c.static_target && c.static_target < high.static_solved)) {
      out.why = "the static system solves " + percent(low.static_solved) + " at scale " + core::number_text(low.factor) + " and " +
                percent(high.static_solved) + " at " + core::number_text(high.factor) + ": its target " +
                percent(c.static_target) + " is not between";
      return out;
    }
    for (int i = 0; i < c.bisections; ++i) {
      const ScaleProbe mid = measure(0.5 * (low.factor + high.factor));
      (mid.static_solved < c.static_target ? low : high) = mid;
    }
    const double factor = std::round(0.5 * (low.factor + high.factor) / c.factor_step) * c.factor_step;
    // The step limit again, on more worlds than the search's: a few sequences read it with an
    // error of tens of steps, which moves the random system's share by points. The check's
    // sequences come after these, so that it measures worlds the limit was not read on.
    const ScaleProbe chosen = measure(factor, c.search_sequences, c.limit_sequences);
    out.scale = {"calibrated", chosen.factor, chosen.step_limit, ""};
  } catch (const ParameterError& e) {
    out.why = e.what();
    return out;
  }
  const nav::SinsSettings s = at_scale(c.base, out.scale.factor, out.scale.step_limit);
  const Sequences check = draw(s, c.seed, c.search_sequences + c.limit_sequences, c.sequences);
  out.static_share = share_of(drive("static", s, check));
  out.random_share = share_of(drive("random", s, check));
  out.reached = out.static_share.holds(c.static_target) && out.random_share.holds(c.random_target);
  if (!out.reached) {
    out.why = "at scale " + core::number_text(out.scale.factor) + " and " + std::to_string(out.scale.step_limit) +
              " steps the static system solves " + interval(out.static_share) + " and the random system " +
              interval(out.random_share) + ": the targets " + percent(c.static_target) + " and " +
              percent(c.random_target) + " are not both inside";
  }
  return out;
}

}  // namespace amp::bench
