#include "amp/core/joint_space.hpp"

#include <cmath>
#include <numbers>

#include "amp/core/error.hpp"

namespace amp::core {

namespace {
constexpr double kPi = std::numbers::pi;
constexpr double kTwoPi = 2.0 * std::numbers::pi;
// Slack when comparing against bounds so that interpolated endpoints count as inside.
constexpr double kBoundsSlack = 1e-9;
}  // namespace

double wrap_angle(double a) {
  double r = std::fmod(a + kPi, kTwoPi);
  if (r < 0.0) r += kTwoPi;
  return r - kPi;
}

double angle_difference(double a, double b) { return wrap_angle(b - a); }

JointSpace::JointSpace(std::string kind, std::vector<Joint> joints, double resolution_fraction)
    : kind_(std::move(kind)), joints_(std::move(joints)) {
  if (joints_.empty() || static_cast<int>(joints_.size()) > kMaxDof) {
    throw ParameterError("a " + kind_ + " space needs 1 to " + std::to_string(kMaxDof) + " coordinates, got " +
                         std::to_string(joints_.size()));
  }
  double sq = 0.0;
  for (const Joint& j : joints_) {
    if (!(j.weight > 0.0) || !std::isfinite(j.weight)) {
      throw ParameterError("joint '" + j.name + "': weight must be positive");
    }
    if (j.kind == JointKind::kContinuous) {
      embedding_dim_ += 2;
      sq += (j.weight * kPi) * (j.weight * kPi);
      continue;
    }
    if (!(j.lo < j.hi) || !std::isfinite(j.lo) || !std::isfinite(j.hi)) {
      throw ParameterError("joint '" + j.name + "': lower bound " + std::to_string(j.lo) +
                           " must be below upper bound " + std::to_string(j.hi));
    }
    if (j.kind == JointKind::kRevolute && j.hi - j.lo > kTwoPi + 1e-9) {
      throw ParameterError("joint '" + j.name + "': revolute range exceeds 2*pi; make it continuous");
    }
    embedding_dim_ += 1;
    sq += (j.weight * (j.hi - j.lo)) * (j.weight * (j.hi - j.lo));
  }
  extent_ = std::sqrt(sq);
  if (!(resolution_fraction > 0.0) || resolution_fraction > 1.0) {
    throw ParameterError("resolution fraction must be in (0, 1], got " + std::to_string(resolution_fraction));
  }
  set_resolution(resolution_fraction * extent_);
}

void JointSpace::from_unit(const double* u, State& out) const {
  out.resize(dimension());
  for (int i = 0; i < dimension(); ++i) {
    const Joint& j = joints_[i];
    // The same arithmetic as Rng::uniform(lo, hi), so random draws are unchanged by this map.
    out[i] = j.kind == JointKind::kContinuous ? -kPi + (kPi - -kPi) * u[i] : j.lo + (j.hi - j.lo) * u[i];
  }
}

double JointSpace::distance(const State& a, const State& b) const {
  double sq = 0.0;
  for (int i = 0; i < dimension(); ++i) {
    const Joint& j = joints_[i];
    const double d = j.kind == JointKind::kContinuous ? angle_difference(a[i], b[i]) : b[i] - a[i];
    sq += (j.weight * d) * (j.weight * d);
  }
  return std::sqrt(sq);
}

void JointSpace::interpolate(const State& a, const State& b, double t, State& out) const {
  out.resize(dimension());
  for (int i = 0; i < dimension(); ++i) {
    if (joints_[i].kind == JointKind::kContinuous) {
      out[i] = wrap_angle(a[i] + t * angle_difference(a[i], b[i]));
    } else {
      out[i] = a[i] + t * (b[i] - a[i]);
    }
  }
}

bool JointSpace::in_bounds(const State& s) const {
  if (s.size() != dimension()) return false;
  for (int i = 0; i < dimension(); ++i) {
    const Joint& j = joints_[i];
    if (!std::isfinite(s[i])) return false;
    if (j.kind == JointKind::kContinuous) continue;
    if (s[i] < j.lo - kBoundsSlack || s[i] > j.hi + kBoundsSlack) return false;
  }
  return true;
}

void JointSpace::enforce_bounds(State& s) const {
  for (int i = 0; i < dimension(); ++i) {
    const Joint& j = joints_[i];
    s[i] = j.kind == JointKind::kContinuous ? wrap_angle(s[i]) : std::clamp(s[i], j.lo, j.hi);
  }
}

void JointSpace::embed(const State& s, double* out) const {
  // A continuous joint maps to w*(cos, sin): the chord 2w*sin(d/2) never exceeds the arc w*d.
  for (int i = 0; i < dimension(); ++i) {
    const Joint& j = joints_[i];
    if (j.kind == JointKind::kContinuous) {
      *out++ = j.weight * std::cos(s[i]);
      *out++ = j.weight * std::sin(s[i]);
    } else {
      *out++ = j.weight * s[i];
    }
  }
}

std::optional<CoordinateLayout> JointSpace::coordinate_layout() const {
  CoordinateLayout layout;
  for (const Joint& j : joints_) {
    const CoordinateKind kind = j.kind == JointKind::kContinuous ? CoordinateKind::kAngle : CoordinateKind::kLinear;
    layout.axes.push_back({kind, j.lo, j.hi, j.weight});
  }
  return layout;
}

JointSpace make_rn_space(const std::vector<double>& lo, const std::vector<double>& hi) {
  if (lo.size() != hi.size()) throw ParameterError("bounds: min and max have different dimensions");
  std::vector<Joint> joints;
  static constexpr const char* kNames[] = {"x", "y", "z"};
  for (std::size_t i = 0; i < lo.size(); ++i) {
    std::string name = i < 3 ? kNames[i] : std::string("x").append(std::to_string(i));
    joints.push_back({std::move(name), JointKind::kLinear, lo[i], hi[i], 1.0});
  }
  return JointSpace("rn", std::move(joints));
}

JointSpace make_se2_space(double xlo, double ylo, double xhi, double yhi, double rotation_weight) {
  return JointSpace("se2", {{"x", JointKind::kLinear, xlo, xhi, 1.0},
                            {"y", JointKind::kLinear, ylo, yhi, 1.0},
                            {"theta", JointKind::kContinuous, -kPi, kPi, rotation_weight}});
}

}  // namespace amp::core
