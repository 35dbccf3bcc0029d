#include "amp/learn/case_library.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <string>
#include <system_error>
#include <utility>

#include "amp/core/error.hpp"
#include "amp/core/number_text.hpp"
#include "amp/core/rng.hpp"

namespace amp::learn {
namespace {

constexpr double kGenericValue = 0.5;  // every value of the initial case: the middle of [0, 1]
// Floor of Ebar and E in the relative similarity: keeps Ebar / E finite for an exact match.
constexpr double kErrorFloor = 1e-12;

bool in_unit(double v) { return v >= 0.0 && v <= 1.0; }  // false for NaN

template <class A>
bool all_in_unit(const A& values) {
  return std::all_of(values.begin(), values.end(), in_unit);
}

}  // namespace

const core::SettingsSchema<CaseSettings>& CaseSettings::schema() {
  using S = CaseSettings;
  static const core::SettingsSchema<S> schema(
      "case_library",
      {core::integer_field<S>("max_cases", &S::max_cases, 1, 1e6, "no case is created beyond this many"),
       core::integer_field<S>("case_length", &S::case_length, 1, 1e6, "samples per case and per history"),
       core::real_field<S>("learning_rate", &S::learning_rate, 0, 1,
                           "lambda: how far a reinforced case moves toward the history, in (0, 1]"),
       core::real_field<S>("new_case_threshold", &S::new_case_threshold, 0, 1,
                           "a relative similarity below this creates a case, in [0, 1)"),
       core::bool_field<S>("reward_weighted", &S::reward_weighted,
                           "reinforced outputs move in proportion to each sample's reward (false: the paper's rule)"),
       core::real_field<S>("outcome_rate", &S::outcome_rate, 0, 1,
                           "> 0: outputs learn from each world's outcome at this rate, not from the interval (0: off)")});
  return schema;
}

void CaseSettings::validate() const {
  schema().validate(*this);
  // The schema's ranges are closed; these two ends are open.
  if (learning_rate == 0.0) {
    throw ParameterError("case_library: parameter 'learning_rate': 0 is outside (0, 1] (the cases would never learn)");
  }
  if (new_case_threshold == 1.0) {
    throw ParameterError("case_library: parameter 'new_case_threshold': 1 is outside [0, 1)");
  }
}

// ---- CaseHistory ----

CaseHistory::CaseHistory(int length) {
  if (length < 1) throw ParameterError("case_history: length " + std::to_string(length) + " is below 1");
  inputs_.resize(static_cast<std::size_t>(length));
  outputs_.resize(static_cast<std::size_t>(length));
  rewards_.resize(static_cast<std::size_t>(length));
}

void CaseHistory::push(const CaseInputs& inputs, const CaseOutputs& outputs, double reward) {
  if (!in_unit(reward)) throw ParameterError("case_history: reward is " + core::number_text(reward) + ", outside [0, 1]");
  for (int x = 0; x < kCaseInputs; ++x) {
    if (!in_unit(inputs[x])) {
      throw ParameterError("case_history: input " + std::to_string(x) + " is " + core::number_text(inputs[x]) +
                           ", outside [0, 1]");
    }
  }
  for (int x = 0; x < kCaseOutputs; ++x) {
    if (!in_unit(outputs[x])) {
      throw ParameterError("case_history: output " + std::to_string(x) + " is " + core::number_text(outputs[x]) +
                           ", outside [0, 1]");
    }
  }
  int s;
  if (size_ < capacity()) {
    s = slot(size_++);
  } else {  // full: overwrite the oldest, which makes the next one the oldest
    s = start_;
    start_ = slot(1);
  }
  inputs_[s] = inputs;
  outputs_[s] = outputs;
  rewards_[s] = reward;
}

// ---- CaseLibrary ----

CaseLibrary::CaseLibrary(CaseSettings settings) : settings_(settings) {
  settings_.validate();
  const auto length = static_cast<std::size_t>(settings_.case_length);
  cases_.reserve(static_cast<std::size_t>(settings_.max_cases));
  CaseInputs in;
  in.fill(kGenericValue);
  CaseOutputs out;
  out.fill(kGenericValue);
  cases_.push_back(Case{std::vector<CaseInputs>(length, in), std::vector<CaseOutputs>(length, out), 0, 0.0});
}

CaseLibrary::CaseLibrary(CaseSettings settings, std::vector<Case> cases)
    : settings_(settings), cases_(std::move(cases)) {
  settings_.validate();
  const int n = size();
  if (n < 1 || n > settings_.max_cases) {
    throw ParameterError("case_library: " + std::to_string(n) + " cases given, expected 1 to max_cases (" +
                         std::to_string(settings_.max_cases) + ")");
  }
  const auto length = static_cast<std::size_t>(settings_.case_length);
  for (int j = 0; j < n; ++j) {
    const Case& c = cases_[static_cast<std::size_t>(j)];
    const std::string where = "case_library: case " + std::to_string(j);
    if (c.inputs.size() != length || c.outputs.size() != length) {
      throw ParameterError(where + " has " + std::to_string(c.inputs.size()) + " inputs and " +
                           std::to_string(c.outputs.size()) + " outputs, expected case_length (" +
                           std::to_string(length) + ") of each");
    }
    const bool values_ok = std::all_of(c.inputs.begin(), c.inputs.end(), all_in_unit<CaseInputs>) &&
                           std::all_of(c.outputs.begin(), c.outputs.end(), all_in_unit<CaseOutputs>);
    if (!values_ok) throw ParameterError(where + " has a value outside [0, 1]");
    if (c.uses < 0 || !in_unit(c.mean_error)) {
      throw ParameterError(where + ": uses " + std::to_string(c.uses) + " and mean error " + core::number_text(c.mean_error) +
                           " must be >= 0 and in [0, 1]");
    }
  }
  cases_.reserve(static_cast<std::size_t>(settings_.max_cases));
}

void CaseLibrary::check_history(const CaseHistory& env) const {
  if (env.capacity() != settings_.case_length) {
    throw ParameterError("case_library: a history of length " + std::to_string(env.capacity()) +
                         " for cases of case_length " + std::to_string(settings_.case_length));
  }
}

void CaseLibrary::check_match(const CaseMatch& m, const CaseHistory& env) const {
  check_history(env);
  if (m.case_index < 0 || m.case_index >= size() || m.position < 1 || m.position > settings_.case_length ||
      m.overlap != std::min(env.size(), m.position) || !in_unit(m.error)) {
    throw ParameterError("case_library: match (case " + std::to_string(m.case_index) + ", position " +
                         std::to_string(m.position) + ", overlap " + std::to_string(m.overlap) + ", error " +
                         core::number_text(m.error) + ") does not fit this library and history");
  }
}

CaseMatch CaseLibrary::match(int j, int p, const CaseHistory& env) const {
  check_history(env);
  if (j < 0 || j >= size() || p < 1 || p > settings_.case_length) {
    throw ParameterError("case_library: no case " + std::to_string(j) + " at position " + std::to_string(p));
  }
  return score(j, p, env);
}

CaseMatch CaseLibrary::score(int j, int p, const CaseHistory& env) const {
  // Section 2.4's similarity metric, read as the mean squared difference per value over the
  // overlap min(l_E, p): the history's newest sample on the case's sample p - 1, and backwards.
  const Case& c = cases_[static_cast<std::size_t>(j)];
  const int newest = env.size() - 1;
  const int o = std::min(env.size(), p);
  double sum = 0.0;
  for (int i = 0; i < o; ++i) {
    const CaseInputs& e = env.input(newest - i);
    const CaseInputs& k = c.inputs[static_cast<std::size_t>(p - 1 - i)];
    for (int x = 0; x < kCaseInputs; ++x) {
      const double d = e[x] - k[x];
      sum += d * d;
    }
  }
  return {j, p, o, o == 0 ? 1.0 : sum / (kCaseInputs * o)};
}

CaseMatch CaseLibrary::retrieve(const CaseHistory& env) const {
  check_history(env);
  if (env.size() == 0) return {0, 1, 0, 1.0};  // nothing perceived: the worst match
  CaseMatch best{0, 0, 0, 2.0};                  // worse than any error: replaced by the first
  for (int j = 0; j < size(); ++j) {
    // The paper's "reverse sweep over the time axis similar to a convolution": the history's end
    // slides from the case's last sample back to its first.
    for (int p = settings_.case_length; p >= 1; --p) {
      const CaseMatch m = score(j, p, env);
      // Strict: among equal errors the first in (larger overlap, lower case, larger p) order stays;
      // the sweep visits equal overlaps in case-then-p order, so only the overlap needs a test.
      if (m.error < best.error || (m.error == best.error && m.overlap > best.overlap)) best = m;
    }
  }
  return best;
}

CaseOutputs CaseLibrary::adapt(const CaseMatch& m, core::Rng& rng, double min_spread) const {
  if (m.case_index < 0 || m.case_index >= size() || m.position < 1 || m.position > settings_.case_length) {
    throw ParameterError("case_library: no case " + std::to_string(m.case_index) + " at position " +
                         std::to_string(m.position) + " to adapt");
  }
  const Case& c = cases_[static_cast<std::size_t>(m.case_index)];
  // The prediction: what the case did after the aligned part (the dashed part of the paper's
  // figure 3), or its last sample when the alignment reaches its end.
  const int q = std::clamp(m.position, 0, settings_.case_length - 1);
  // Exploration "allows the system to explore the search space locally": its size is the RMS
  // difference of the match, so a well-matched case is followed closely.
  // The caller may ask for more (SINS in AMP: when the robot has stalled, docs/sins.md).
  const double spread = std::max(std::sqrt(std::max(m.error, 0.0)), std::clamp(min_spread, 0.0, 1.0));
  CaseOutputs out = c.outputs[static_cast<std::size_t>(q)];
  for (int x = 0; x < kCaseOutputs; ++x) out[x] = std::clamp(out[x] + spread * rng.uniform(-1.0, 1.0), 0.0, 1.0);
  return out;
}

double CaseLibrary::relative_similarity(const CaseMatch& m) const {
  if (m.case_index < 0 || m.case_index >= size()) {
    throw ParameterError("case_library: no case " + std::to_string(m.case_index));
  }
  const Case& c = cases_[static_cast<std::size_t>(m.case_index)];
  if (c.uses == 0) return 1.0;  // no past use to compare with: as good as before
  return std::max(c.mean_error, kErrorFloor) / std::max(m.error, kErrorFloor);
}

Learned CaseLibrary::learn(const CaseMatch& m, const CaseHistory& env) {
  check_match(m, env);
  const double rho = relative_similarity(m);
  Learned result = Learned::kKept;
  if (rho >= 1.0) {
    // As good a match as the case's past ones: the situation shows the regularity the case is
    // converging on, so move the aligned part toward it. Weights fall from lambda on the newest
    // aligned sample to lambda / o on the oldest: the overlap factor "attenuate[s] the
    // modification of early values within the case which contribute more to the selection".
    Case& c = cases_[static_cast<std::size_t>(m.case_index)];
    const int o = m.overlap;
    const int newest = env.size() - 1;
    for (int i = 0; i < o; ++i) {
      const double w = settings_.learning_rate * (o - i) / o;
      const auto k = static_cast<std::size_t>(m.position - 1 - i);
      const CaseInputs& ei = env.input(newest - i);
      const CaseOutputs& eo = env.output(newest - i);
      // Reward weighting (an AMP addition, docs/sins.md): outputs move only as far as they paid.
      const double wo = settings_.outcome_rate > 0.0 ? 0.0 : settings_.reward_weighted ? w * env.reward(newest - i) : w;
      for (int x = 0; x < kCaseInputs; ++x) c.inputs[k][x] += w * (ei[x] - c.inputs[k][x]);
      for (int x = 0; x < kCaseOutputs; ++x) c.outputs[k][x] += wo * (eo[x] - c.outputs[k][x]);
    }
    result = Learned::kReinforced;
  } else if (rho < settings_.new_case_threshold && env.full()) {
    // "A very bad fit": probably a new class of situations, which the history itself starts.
    if (size() < settings_.max_cases) {
      Case fresh;
      fresh.inputs.resize(static_cast<std::size_t>(env.size()));
      fresh.outputs.resize(static_cast<std::size_t>(env.size()));
      for (int i = 0; i < env.size(); ++i) {
        fresh.inputs[static_cast<std::size_t>(i)] = env.input(i);
        fresh.outputs[static_cast<std::size_t>(i)] = env.output(i);
      }
      cases_.push_back(std::move(fresh));  // max_cases reserved: no reallocation
      result = Learned::kCreated;
    } else {
      result = Learned::kFull;
    }
  }
  // Otherwise kept: a worse match would pull the case away from its regularity.
  Case& used = cases_[static_cast<std::size_t>(m.case_index)];
  ++used.uses;
  used.mean_error += (m.error - used.mean_error) / used.uses;  // running mean of E over the uses
  return result;
}

void CaseLibrary::shift_outputs(int j, int q, const CaseOutputs& toward, double weight) {
  if (j < 0 || j >= size() || q < 0 || q >= settings_.case_length) {
    throw ParameterError("case_library: no output sample " + std::to_string(q) + " of case " + std::to_string(j));
  }
  CaseOutputs& o = cases_[static_cast<std::size_t>(j)].outputs[static_cast<std::size_t>(q)];
  for (int x = 0; x < kCaseOutputs; ++x) o[x] = std::clamp(o[x] + weight * (toward[x] - o[x]), 0.0, 1.0);
}

}  // namespace amp::learn
