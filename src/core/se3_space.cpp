#include "amp/core/se3_space.hpp"

#include <cmath>
#include <numbers>

#include "amp/core/error.hpp"

namespace amp::core {

namespace {
constexpr double kBoundsSlack = 1e-9;
constexpr double kUnitNormTolerance = 1e-6;

double rotation_angle(const State& a, const State& b) {
  double dot = a[3] * b[3] + a[4] * b[4] + a[5] * b[5] + a[6] * b[6];
  dot = std::min(1.0, std::abs(dot));
  return 2.0 * std::acos(dot);  // q and -q are the same rotation
}
}  // namespace

Se3Space::Se3Space(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi, double rotation_weight,
                   double translation_weight, double resolution_fraction)
    : lo_(lo), hi_(hi), rotation_weight_(rotation_weight), translation_weight_(translation_weight) {
  for (int i = 0; i < 3; ++i) {
    if (!(lo_[i] < hi_[i])) {
      throw ParameterError("se3 bounds: min must be below max on every axis");
    }
  }
  if (!(rotation_weight_ > 0.0) || !(translation_weight_ > 0.0)) {
    throw ParameterError("se3 weights must be positive");
  }
  if (!(resolution_fraction > 0.0) || resolution_fraction > 1.0) {
    throw ParameterError("resolution fraction must be in (0, 1]");
  }
  set_resolution(resolution_fraction * maximum_extent());
}

std::optional<CoordinateLayout> Se3Space::coordinate_layout() const {
  CoordinateLayout layout;
  for (int i = 0; i < 3; ++i) layout.axes.push_back({CoordinateKind::kLinear, lo_[i], hi_[i], translation_weight_});
  layout.quaternion = true;
  layout.rotation_weight = rotation_weight_;
  return layout;
}

State Se3Space::make_state(const Eigen::Vector3d& p, const Eigen::Quaterniond& q) {
  const Eigen::Quaterniond n = q.normalized();
  State s(7);
  s << p.x(), p.y(), p.z(), n.x(), n.y(), n.z(), n.w();
  return s;
}

void Se3Space::from_unit(const double* u, State& out) const {
  out.resize(7);
  for (int i = 0; i < 3; ++i) out[i] = lo_[i] + (hi_[i] - lo_[i]) * u[i];
  // Shoemake's method: uniform over SO(3).
  const double u1 = u[3], u2 = u[4], u3 = u[5];
  const double a = std::sqrt(1.0 - u1), b = std::sqrt(u1);
  const double t2 = 2.0 * std::numbers::pi * u2, t3 = 2.0 * std::numbers::pi * u3;
  out[3] = a * std::sin(t2);
  out[4] = a * std::cos(t2);
  out[5] = b * std::sin(t3);
  out[6] = b * std::cos(t3);
}

double Se3Space::distance(const State& a, const State& b) const {
  return translation_weight_ * (a.head<3>() - b.head<3>()).norm() + rotation_weight_ * rotation_angle(a, b);
}

void Se3Space::interpolate(const State& a, const State& b, double t, State& out) const {
  out.resize(7);
  out.head<3>() = a.head<3>() + t * (b.head<3>() - a.head<3>());
  const Eigen::Quaterniond q = rotation(a).slerp(t, rotation(b));  // Eigen takes the short arc
  out[3] = q.x();
  out[4] = q.y();
  out[5] = q.z();
  out[6] = q.w();
}

bool Se3Space::in_bounds(const State& s) const {
  if (s.size() != 7 || !s.allFinite()) return false;
  for (int i = 0; i < 3; ++i) {
    if (s[i] < lo_[i] - kBoundsSlack || s[i] > hi_[i] + kBoundsSlack) return false;
  }
  return std::abs(s.tail<4>().norm() - 1.0) < kUnitNormTolerance;
}

void Se3Space::enforce_bounds(State& s) const {
  for (int i = 0; i < 3; ++i) s[i] = std::clamp(s[i], lo_[i], hi_[i]);
  const double n = s.tail<4>().norm();
  if (n > 0.0) {
    s.tail<4>() /= n;
  } else {
    s.tail<4>() << 0.0, 0.0, 0.0, 1.0;
  }
}

double Se3Space::maximum_extent() const {
  return translation_weight_ * (hi_ - lo_).norm() + rotation_weight_ * std::numbers::pi;
}

void Se3Space::embed_variant(const State& s, int variant, double* out) const {
  // sqrt(a^2 + b^2) <= a + b, and with c = 2*w_r the chord c*|q_a -+ q_b| = 4 w_r sin(angle/4) never
  // exceeds w_r * angle, so the embedding's distance (over both signs of q) is a lower bound.
  const double c = 2.0 * rotation_weight_ * (variant == 0 ? 1.0 : -1.0);
  for (int i = 0; i < 3; ++i) out[i] = translation_weight_ * s[i];
  for (int i = 3; i < 7; ++i) out[i] = c * s[i];
}

}  // namespace amp::core
