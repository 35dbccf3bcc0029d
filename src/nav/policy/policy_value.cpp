#include "amp/nav/policy/policy_value.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "amp/core/error.hpp"
#include "amp/nav/nav_world.hpp"

namespace amp::nav {

void PolicyRewardSettings::validate() const {
  auto check = [](double v, const char* name, bool positive) {
    if (!std::isfinite(v) || v < 0.0 || (positive && v == 0.0)) {
      throw ParameterError(std::string(name) + (positive ? " must be > 0" : " must be >= 0") + ", got " + std::to_string(v));
    }
  };
  check(c, "c", false);
  check(c_time, "c_time", false);
  check(g, "g", false);
  check(h, "h", false);
  check(safety, "safety", false);
  check(safety_per_speed, "safety_per_speed", false);
  check(sigma, "sigma", false);
  check(step, "step", true);
  check(v_floor, "v_floor", true);
}

PolicyValue::PolicyValue(const NavWorld& world, double radius, PolicyRewardSettings settings)
    : world_(&world), radius_(radius), settings_(settings) {
  settings_.validate();
  if (!(radius_ > 0.0) || !std::isfinite(radius_)) {
    throw ParameterError("policy value: the footprint's radius must be > 0, got " + std::to_string(radius_));
  }
}

double PolicyValue::immediate(const Eigen::Vector2d& p, const Eigen::Vector2d& direction, double v) const {
  const PolicyRewardSettings& s = settings_;
  const double speed = std::max(v, s.v_floor);
  const double range = s.safety + s.safety_per_speed * speed;
  // Sigma points across the path (3-point Gauss-Hermite for a Gaussian).
  const Eigen::Vector2d side = direction.squaredNorm() > 0.0 ? Eigen::Vector2d(-direction.y(), direction.x()).normalized()
                                                             : Eigen::Vector2d::Zero();
  const double offset = std::sqrt(3.0) * s.sigma;
  const double weights[3] = {2.0 / 3.0, 1.0 / 6.0, 1.0 / 6.0};
  const double offsets[3] = {0.0, offset, -offset};
  double near = 0.0;
  for (int k = 0; k < 3; ++k) {
    if (world_->clearance(p + offsets[k] * side, radius_) < range) near += weights[k];
  }
  return -s.c - s.c_time / speed - s.h * near;
}

double PolicyValue::segments(const std::vector<State>& w, std::size_t first, std::size_t last) const {
  double sum = 0.0;
  for (std::size_t j = first; j < last && j + 1 < w.size(); ++j) {
    const Eigen::Vector2d a(w[j][0], w[j][1]), b(w[j + 1][0], w[j + 1][1]);
    const double len = (b - a).norm();
    if (len == 0.0) continue;
    // The midpoint rule on pieces of at most `step`.
    const int n = std::max(1, static_cast<int>(std::ceil(len / settings_.step)));
    for (int i = 0; i < n; ++i) {
      const double t = (i + 0.5) / n;
      sum += immediate(a + t * (b - a), b - a, (1.0 - t) * w[j][3] + t * w[j + 1][3]) * (len / n);
    }
  }
  return sum;
}

PolicyValue::Lowest PolicyValue::lowest_on_segment(const std::vector<State>& w, std::size_t j) const {
  const Eigen::Vector2d a(w[j][0], w[j][1]), b(w[j + 1][0], w[j + 1][1]);
  const int n = std::max(1, static_cast<int>(std::ceil((b - a).norm() / settings_.step)));
  Lowest out;
  out.reward = 0.0;
  bool any = false;
  for (int i = 1; i < n; ++i) {  // inside the segment, not at its ends
    const double t = static_cast<double>(i) / n;
    const double v = (1.0 - t) * w[j][3] + t * w[j + 1][3];
    const double r = immediate(a + t * (b - a), b - a, v);
    if (!any || r < out.reward) out = {r, a + t * (b - a), v}, any = true;
  }
  if (!any) out = {0.0, 0.5 * (a + b), 0.5 * (w[j][3] + w[j + 1][3])};
  return out;
}

}  // namespace amp::nav
