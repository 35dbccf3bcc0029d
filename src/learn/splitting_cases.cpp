#include "amp/learn/splitting_cases.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include <Eigen/Dense>

#include "amp/core/error.hpp"
#include "amp/core/rng.hpp"

namespace amp::learn {

const core::SettingsSchema<SplittingCaseSettings>& SplittingCaseSettings::schema() {
  using S = SplittingCaseSettings;
  static const core::SettingsSchema<S> schema(
      "sins-plus",
      {core::integer_field<S>("max_cases", &S::max_cases, 1, 1000, "no case is split beyond this many"),
       core::integer_field<S>("horizon", &S::horizon, 1, 1000,
                              "control intervals a choice's credit looks ahead over (its own included)"),
       core::real_field<S>("exploration", &S::exploration, 0, 1,
                           "half-width of the exploration around a case's outputs (outputs normalised to [0, 1])"),
       core::real_field<S>("step", &S::step, 0, 1, "how far one fit moves an output whose slope is significant"),
       core::integer_field<S>("window", &S::window, 16, 100000, "credited uses each case keeps for its fits"),
       core::integer_field<S>("refit_every", &S::refit_every, 1, 100000, "credited uses between two fits of a case"),
       core::real_field<S>("step_t", &S::step_t, 0, 100, "|t| of an output's slope that moves the output"),
       core::real_field<S>("split_t", &S::split_t, 0, 100,
                           "|t| both halves' slopes must reach, with opposite signs, to split a case"),
       core::real_field<S>("prototype_rate", &S::prototype_rate, 0, 1,
                           "how far a case's situation moves toward each one it is used in")});
  return schema;
}

void SplittingCaseSettings::validate() const {
  schema().validate(*this);
  if (!(exploration > 0.0)) throw ParameterError("sins-plus: parameter 'exploration' must be > 0");
  if (!(split_t > 0.0)) throw ParameterError("sins-plus: parameter 'split_t' must be > 0");
  if (refit_every > window) {
    throw ParameterError("sins-plus: parameter 'refit_every' (" + std::to_string(refit_every) +
                         ") must not exceed 'window' (" + std::to_string(window) + ")");
  }
}

namespace {

// The fit's regressors: the outputs, then the inputs.
constexpr int kRegressors = kCaseOutputs + kCaseInputs;
// A fit needs this many degrees of freedom left after its coefficients.
constexpr int kLeastDegreesOfFreedom = 5;
// Outputs that vary less than this over a window have no slope to estimate.
constexpr double kLeastVariance = 1e-10;

double clamp01(double v) { return std::clamp(v, 0.0, 1.0); }

void check_unit(const CaseOutputs& v, const char* what) {
  for (const double x : v) {
    if (!(x >= 0.0 && x <= 1.0)) throw ParameterError(std::string("sins-plus: ") + what + " must lie in [0, 1]");
  }
}

// Each output moved by `step` along its slope where the slope's |t| reaches `least_t`.
void step_outputs(CaseOutputs& outputs, const OutputSlopes& s, double step, double least_t) {
  for (int o = 0; o < kCaseOutputs; ++o) {
    if (std::abs(s.t[o]) >= least_t && s.t[o] != 0.0) outputs[o] = clamp01(outputs[o] + (s.t[o] > 0 ? step : -step));
  }
}

CaseInputs mean_inputs(const std::vector<const CaseUse*>& uses) {
  CaseInputs m{};
  for (const CaseUse* u : uses) {
    for (int x = 0; x < kCaseInputs; ++x) m[x] += u->inputs[x];
  }
  for (double& v : m) v /= static_cast<double>(uses.size());
  return m;
}

}  // namespace

OutputSlopes SplittingCaseLibrary::fit(const CaseUse* const* uses, int n) {
  // The credit is regressed on the outputs and on the situation's inputs together: the inputs take
  // up what the situation alone explains (a trap pays little whatever was chosen), which would
  // otherwise be noise on the outputs' slopes. Only the outputs' slopes are reported.
  using Vector = Eigen::Matrix<double, kRegressors, 1>;
  using Matrix = Eigen::Matrix<double, kRegressors, kRegressors>;
  OutputSlopes out;
  out.uses = n;
  const auto regressors = [](const CaseUse& u) {
    Vector z;
    for (int o = 0; o < kCaseOutputs; ++o) z(o) = u.outputs[o];
    for (int x = 0; x < kCaseInputs; ++x) z(kCaseOutputs + x) = u.inputs[x];
    return z;
  };
  Vector mean_z = Vector::Zero();
  double mean_g = 0.0;
  for (int i = 0; i < n; ++i) mean_z += regressors(*uses[i]), mean_g += uses[i]->credit;
  if (n > 0) mean_z /= n, mean_g /= n;
  Matrix ztz = Matrix::Zero();
  Vector zty = Vector::Zero();
  for (int i = 0; i < n; ++i) {
    const Vector z = regressors(*uses[i]) - mean_z;
    ztz += z * z.transpose();
    zty += z * (uses[i]->credit - mean_g);
  }
  // Regressors that did not vary (an output pinned at a bound, say) leave the fit: identity rows.
  std::array<bool, kRegressors> varied{};
  int fitted = 0;
  for (int k = 0; k < kRegressors; ++k) {
    varied[k] = n > 0 && ztz(k, k) / n > kLeastVariance;
    fitted += varied[k] ? 1 : 0;
    if (!varied[k]) ztz.row(k).setZero(), ztz.col(k).setZero(), ztz(k, k) = 1.0, zty(k) = 0.0;
  }
  const int dof = n - 1 - fitted;
  if (dof < kLeastDegreesOfFreedom) return out;
  const Eigen::LDLT<Matrix> ldlt(ztz);
  const Vector g = ldlt.solve(zty);
  double rss = 0.0;
  for (int i = 0; i < n; ++i) {
    const double e = uses[i]->credit - mean_g - g.dot(regressors(*uses[i]) - mean_z);
    rss += e * e;
  }
  const double s2 = rss / dof;
  const Matrix inverse = ldlt.solve(Matrix::Identity());
  for (int o = 0; o < kCaseOutputs; ++o) {
    if (!varied[o]) continue;
    out.slope[o] = g(o);
    const double se = std::sqrt(std::max(0.0, s2 * inverse(o, o)));
    // An exact fit (no residual) makes any non-zero slope certain.
    constexpr double kCertain = std::numeric_limits<double>::infinity();
    out.t[o] = se > 0.0 ? g(o) / se : (g(o) != 0.0 ? std::copysign(kCertain, g(o)) : 0.0);
  }
  return out;
}

SplittingCaseLibrary::SplittingCaseLibrary(SplittingCaseSettings settings, const CaseOutputs& initial)
    : settings_(settings) {
  settings_.validate();
  check_unit(initial, "the initial outputs");
  const auto window = static_cast<std::size_t>(settings_.window);
  cases_.reserve(static_cast<std::size_t>(settings_.max_cases));
  SplittingCase first;
  first.prototype.fill(0.5);
  first.outputs = initial;
  first.uses.reserve(window);
  cases_.push_back(std::move(first));
  pending_.resize(static_cast<std::size_t>(settings_.horizon));
  scratch_.reserve(window), low_.reserve(window), high_.reserve(window), keys_.reserve(window);
}

int SplittingCaseLibrary::nearest(const CaseInputs& inputs) const {
  int best = 0;
  double best_d = std::numeric_limits<double>::infinity();
  for (int j = 0; j < size(); ++j) {
    double d = 0.0;
    for (int x = 0; x < kCaseInputs; ++x) {
      const double e = inputs[x] - cases_[static_cast<std::size_t>(j)].prototype[x];
      d += e * e;
    }
    if (d < best_d) best_d = d, best = j;
  }
  return best;
}

CaseOutputs SplittingCaseLibrary::choose(const CaseInputs& inputs, core::Rng& rng) {
  check_unit(inputs, "inputs");
  const int j = nearest(inputs);
  SplittingCase& c = cases_[static_cast<std::size_t>(j)];
  for (int x = 0; x < kCaseInputs; ++x) c.prototype[x] += settings_.prototype_rate * (inputs[x] - c.prototype[x]);
  CaseOutputs a;
  for (int o = 0; o < kCaseOutputs; ++o) a[o] = clamp01(c.outputs[o] + settings_.exploration * rng.uniform(-1.0, 1.0));
  // The queue holds at most `horizon` choices: the oldest was credited by the reward that filled it
  // (two choices with no reward between, which the navigation loop never makes, credit it early).
  if (pending_size_ == settings_.horizon) credit_oldest(pending_[0].rewards);
  Pending& p = pending_[static_cast<std::size_t>(pending_size_++)];
  p.case_index = j;
  p.use = CaseUse{inputs, a, 0.0};
  p.rewards = 0;
  last_case_ = j;
  return a;
}

void SplittingCaseLibrary::reward(double r) {
  if (!(r >= -1.0 && r <= 1.0)) throw ParameterError("sins-plus: a reward must lie in [-1, 1]");
  for (int i = 0; i < pending_size_; ++i) {
    pending_[static_cast<std::size_t>(i)].use.credit += r;
    ++pending_[static_cast<std::size_t>(i)].rewards;
  }
  if (pending_size_ > 0 && pending_[0].rewards >= settings_.horizon) credit_oldest(settings_.horizon);
}

void SplittingCaseLibrary::credit_oldest(int rewards) {
  Pending done = pending_[0];
  std::rotate(pending_.begin(), pending_.begin() + 1, pending_.begin() + pending_size_);
  --pending_size_;
  if (rewards == 0) return;
  done.use.credit /= rewards;
  credit(done);
}

void SplittingCaseLibrary::end_episode(double terminal) {
  const bool filled = terminal >= -1.0;
  if (filled && terminal > 1.0) throw ParameterError("sins-plus: a terminal reward must lie in [-1, 1]");
  for (int i = 0; i < pending_size_; ++i) {
    Pending p = pending_[static_cast<std::size_t>(i)];
    if (filled) {
      p.use.credit = (p.use.credit + (settings_.horizon - p.rewards) * terminal) / settings_.horizon;
    } else if (p.rewards > 0) {
      p.use.credit /= p.rewards;
    } else {
      continue;  // nothing was seen of this choice's effect
    }
    credit(p);
  }
  pending_size_ = 0;
}

void SplittingCaseLibrary::credit(const Pending& p) {
  SplittingCase& c = cases_[static_cast<std::size_t>(p.case_index)];
  if (static_cast<int>(c.uses.size()) < settings_.window) {
    c.uses.push_back(p.use);
  } else {
    c.uses[static_cast<std::size_t>(c.next)] = p.use;
    c.next = (c.next + 1) % settings_.window;
  }
  if (++c.since_fit >= settings_.refit_every) learn(p.case_index);
}

void SplittingCaseLibrary::learn(int j) {
  SplittingCase& c = cases_[static_cast<std::size_t>(j)];
  c.since_fit = 0;
  ++c.fits;
  if (static_cast<int>(c.uses.size()) == settings_.window && size() < settings_.max_cases && try_split(j)) return;
  scratch_.clear();
  for (const CaseUse& u : c.uses) scratch_.push_back(&u);
  step_outputs(c.outputs, fit(scratch_.data(), static_cast<int>(scratch_.size())), settings_.step, settings_.step_t);
}

bool SplittingCaseLibrary::try_split(int j) {
  const std::vector<CaseUse>& uses = cases_[static_cast<std::size_t>(j)].uses;
  double best = 0.0;
  int best_input = -1;
  double best_median = 0.0;
  for (int x = 0; x < kCaseInputs; ++x) {
    keys_.clear();
    for (const CaseUse& u : uses) keys_.push_back(u.inputs[x]);
    auto middle = keys_.begin() + static_cast<std::ptrdiff_t>(keys_.size() / 2);
    std::nth_element(keys_.begin(), middle, keys_.end());
    const double median = *middle;
    low_.clear(), high_.clear();
    for (const CaseUse& u : uses) (u.inputs[x] < median ? low_ : high_).push_back(&u);
    const OutputSlopes lo = fit(low_.data(), static_cast<int>(low_.size()));
    const OutputSlopes hi = fit(high_.data(), static_cast<int>(high_.size()));
    for (int o = 0; o < kCaseOutputs; ++o) {
      const double weaker = std::min(std::abs(lo.t[o]), std::abs(hi.t[o]));
      if (lo.t[o] * hi.t[o] < 0.0 && weaker >= settings_.split_t && weaker > best) {
        best = weaker, best_input = x, best_median = median;
      }
    }
  }
  if (best_input < 0) return false;
  // The case becomes two: the uses below the median stay, those at or above it found the new case.
  low_.clear(), high_.clear();
  for (const CaseUse& u : uses) (u.inputs[best_input] < best_median ? low_ : high_).push_back(&u);
  SplittingCase upper;
  upper.prototype = mean_inputs(high_);
  upper.outputs = cases_[static_cast<std::size_t>(j)].outputs;
  upper.uses.reserve(static_cast<std::size_t>(settings_.window));
  for (const CaseUse* u : high_) upper.uses.push_back(*u);
  step_outputs(upper.outputs, fit(high_.data(), static_cast<int>(high_.size())), settings_.step, settings_.step_t);
  SplittingCase& lower = cases_[static_cast<std::size_t>(j)];
  lower.prototype = mean_inputs(low_);
  step_outputs(lower.outputs, fit(low_.data(), static_cast<int>(low_.size())), settings_.step, settings_.step_t);
  std::vector<CaseUse> kept;
  kept.reserve(static_cast<std::size_t>(settings_.window));
  for (const CaseUse* u : low_) kept.push_back(*u);
  lower.uses.swap(kept);
  lower.next = 0;
  cases_.push_back(std::move(upper));  // capacity reserved: `lower` and the pointers above stay valid until here
  ++splits_;
  return true;
}

}  // namespace amp::learn
