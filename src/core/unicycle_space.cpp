#include "amp/core/unicycle_space.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>
#include <string>
#include <utility>

#include "amp/core/error.hpp"
#include "amp/core/number_text.hpp"

namespace amp::core {

namespace {
constexpr double kPi = std::numbers::pi;
constexpr double kTwoPi = 2.0 * std::numbers::pi;
// Slack when comparing against bounds so that interpolated endpoints count as inside.
constexpr double kBoundsSlack = 1e-9;

void check_interval(const char* lo_name, double lo, const char* hi_name, double hi) {
  for (const auto& [name, value] : {std::pair{lo_name, lo}, std::pair{hi_name, hi}}) {
    if (!std::isfinite(value)) {
      throw ParameterError(std::string("unicycle bounds: ") + name + " must be finite, got " + core::number_text(value));
    }
  }
  if (!(lo < hi)) {
    throw ParameterError(std::string("unicycle bounds: ") + lo_name + " (" + core::number_text(lo) + ") must be below " +
                         hi_name + " (" + core::number_text(hi) + ")");
  }
}

void check_weight(const char* name, double w) {
  if (!(w > 0.0) || !std::isfinite(w)) {
    throw ParameterError(std::string("unicycle weights: ") + name + " must be positive and finite, got " +
                         core::number_text(w));
  }
}

// Unsigned shortest angle between two headings, in [0, pi]. Computed from |b - a|, which is exactly
// |a - b|, so distance() is exactly symmetric.
double angle_between(double a, double b) {
  const double d = std::fmod(std::abs(b - a), kTwoPi);
  return d > kPi ? kTwoPi - d : d;
}
}  // namespace

UnicycleSpace::UnicycleSpace(const UnicycleBounds& bounds, const UnicycleWeights& weights,
                             double resolution_fraction)
    : bounds_(bounds), weights_(weights) {
  check_interval("x_min", bounds_.x_min, "x_max", bounds_.x_max);
  check_interval("y_min", bounds_.y_min, "y_max", bounds_.y_max);
  check_interval("v_min", bounds_.v_min, "v_max", bounds_.v_max);
  check_interval("omega_min", bounds_.omega_min, "omega_max", bounds_.omega_max);
  check_weight("theta", weights_.theta);
  check_weight("v", weights_.v);
  check_weight("omega", weights_.omega);
  if (!(resolution_fraction > 0.0) || resolution_fraction > 1.0) {
    throw ParameterError("resolution fraction must be in (0, 1], got " + core::number_text(resolution_fraction));
  }
  // Attained by opposite corners of the box with antipodal headings.
  const double dx = bounds_.x_max - bounds_.x_min;
  const double dy = bounds_.y_max - bounds_.y_min;
  const double dth = weights_.theta * kPi;
  const double dv = weights_.v * (bounds_.v_max - bounds_.v_min);
  const double dw = weights_.omega * (bounds_.omega_max - bounds_.omega_min);
  extent_ = std::sqrt(dx * dx + dy * dy + dth * dth + dv * dv + dw * dw);
  set_resolution(resolution_fraction * extent_);
}

State UnicycleSpace::make_state(double x, double y, double theta, double v, double omega) {
  State s(5);
  s << x, y, theta, v, omega;
  return s;
}

double UnicycleSpace::wrap_heading(double theta) {
  if (theta > -kPi && theta <= kPi) return theta;
  double r = std::fmod(theta + kPi, kTwoPi);  // (-2pi, 2pi)
  if (r <= 0.0) r += kTwoPi;                  // (0, 2pi]
  const double w = r - kPi;
  return w <= -kPi ? kPi : w;  // a tiny r rounds onto -pi, which is pi here; NaN stays NaN
}

double UnicycleSpace::heading_difference(double a, double b) { return wrap_heading(b - a); }

void UnicycleSpace::from_unit(const double* u, State& out) const {
  out.resize(5);
  // The same arithmetic as Rng::uniform(lo, hi), so random draws are unchanged by this map.
  out[kX] = bounds_.x_min + (bounds_.x_max - bounds_.x_min) * u[kX];
  out[kY] = bounds_.y_min + (bounds_.y_max - bounds_.y_min) * u[kY];
  out[kTheta] = wrap_heading(-kPi + (kPi - -kPi) * u[kTheta]);  // [-pi, pi) -> (-pi, pi]
  out[kV] = bounds_.v_min + (bounds_.v_max - bounds_.v_min) * u[kV];
  out[kOmega] = bounds_.omega_min + (bounds_.omega_max - bounds_.omega_min) * u[kOmega];
}

double UnicycleSpace::distance(const State& a, const State& b) const {
  const double dx = b[kX] - a[kX];
  const double dy = b[kY] - a[kY];
  const double dth = weights_.theta * angle_between(a[kTheta], b[kTheta]);
  const double dv = weights_.v * (b[kV] - a[kV]);
  const double dw = weights_.omega * (b[kOmega] - a[kOmega]);
  return std::sqrt(dx * dx + dy * dy + dth * dth + dv * dv + dw * dw);
}

void UnicycleSpace::interpolate(const State& a, const State& b, double t, State& out) const {
  // The endpoints are returned as given (not a + 1 * (b - a), which can round), heading wrapped.
  if (t <= 0.0 || t >= 1.0) {
    const State& end = t <= 0.0 ? a : b;
    out = end;
    out[kTheta] = wrap_heading(out[kTheta]);
    return;
  }
  const double dth = heading_difference(a[kTheta], b[kTheta]);  // read before out may overwrite a
  out.resize(5);
  for (const int i : {kX, kY, kV, kOmega}) out[i] = a[i] + t * (b[i] - a[i]);
  out[kTheta] = wrap_heading(a[kTheta] + t * dth);
}

bool UnicycleSpace::in_bounds(const State& s) const {
  if (s.size() != 5 || !s.allFinite()) return false;
  const auto inside = [](double x, double lo, double hi) { return x >= lo - kBoundsSlack && x <= hi + kBoundsSlack; };
  return inside(s[kX], bounds_.x_min, bounds_.x_max) && inside(s[kY], bounds_.y_min, bounds_.y_max) &&
         inside(s[kV], bounds_.v_min, bounds_.v_max) && inside(s[kOmega], bounds_.omega_min, bounds_.omega_max);
}

void UnicycleSpace::enforce_bounds(State& s) const {
  s[kX] = std::clamp(s[kX], bounds_.x_min, bounds_.x_max);
  s[kY] = std::clamp(s[kY], bounds_.y_min, bounds_.y_max);
  s[kTheta] = wrap_heading(s[kTheta]);
  s[kV] = std::clamp(s[kV], bounds_.v_min, bounds_.v_max);
  s[kOmega] = std::clamp(s[kOmega], bounds_.omega_min, bounds_.omega_max);
}

void UnicycleSpace::embed(const State& s, double* out) const {
  // The heading maps to w*(cos, sin): the chord 2w*sin(d/2) never exceeds the arc w*d.
  out[0] = s[kX];
  out[1] = s[kY];
  out[2] = weights_.theta * std::cos(s[kTheta]);
  out[3] = weights_.theta * std::sin(s[kTheta]);
  out[4] = weights_.v * s[kV];
  out[5] = weights_.omega * s[kOmega];
}

}  // namespace amp::core
