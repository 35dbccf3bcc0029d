#include "amp/nav/unicycle_disc.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>
#include <string>

#include "amp/core/error.hpp"

namespace amp::nav {

void UnicycleDiscSettings::validate() const {
  auto positive = [](double v, const char* name) {
    if (!(v > 0.0) || !std::isfinite(v)) {
      throw ParameterError(std::string("unicycle: ") + name + " must be > 0, got " + std::to_string(v));
    }
  };
  positive(radius, "radius");
  positive(v_max, "v_max");
  positive(omega_max, "omega_max");
  positive(accel, "accel");
  positive(alpha, "alpha");
  if (!(v_min <= 0.0) || !std::isfinite(v_min)) {
    throw ParameterError("unicycle: v_min must be <= 0 (0: no reversing), got " + std::to_string(v_min));
  }
  if (length != 0.0 && !(length >= 2.0 * radius && std::isfinite(length))) {
    throw ParameterError("unicycle: length must be 0 (a disc) or at least the width 2 radius = " +
                         std::to_string(2.0 * radius) + ", got " + std::to_string(length));
  }
}

UnicycleDisc::UnicycleDisc(UnicycleDiscSettings settings) : settings_(settings) { settings_.validate(); }

Eigen::Vector2d UnicycleDisc::clipped(const Eigen::Vector2d& command) const {
  if (!command.allFinite()) return Eigen::Vector2d::Zero();
  return {std::clamp(command.x(), settings_.v_min, settings_.v_max),
          std::clamp(command.y(), -settings_.omega_max, settings_.omega_max)};
}

namespace {

// A velocity that moves from x0 toward target at `rate`, then holds: its value at time t.
double ramp(double x0, double target, double rate, double t) {
  const double gap = target - x0;
  return std::abs(gap) <= rate * t ? target : x0 + std::copysign(rate * t, gap);
}

// Pose change over [0, t] at constant v and omega, from heading theta: the exact arc.
Eigen::Vector2d arc(double v, double omega, double theta, double t) {
  if (std::abs(omega * t) < 1e-9) {
    return v * t * Eigen::Vector2d(std::cos(theta + 0.5 * omega * t), std::sin(theta + 0.5 * omega * t));
  }
  const double r = v / omega;
  return {r * (std::sin(theta + omega * t) - std::sin(theta)), -r * (std::cos(theta + omega * t) - std::cos(theta))};
}

}  // namespace

RobotState UnicycleDisc::propagate(const RobotState& s, const Eigen::Vector2d& command, double t) const {
  const Eigen::Vector2d target = clipped(command);
  const double v0 = s.velocity.x(), w0 = s.velocity.y();
  // Both velocities hold after the later of the two ramps ends (or at t).
  const double tv = std::abs(target.x() - v0) / settings_.accel, tw = std::abs(target.y() - w0) / settings_.alpha;
  const double t_ramp = std::min(t, std::max(tv, tw));
  RobotState out = s;
  if (t_ramp > 0.0) {
    // Simpson's rule on [0, t_ramp], split at the earlier ramp's end so each piece is smooth.
    auto heading = [&](double u) {
      // theta(u) = theta0 + integral of omega: linear ramp then hold.
      const double ue = std::min(u, tw), w_end = ramp(w0, target.y(), settings_.alpha, ue);
      return s.heading + 0.5 * (w0 + w_end) * ue + w_end * (u - ue);
    };
    auto velocity = [&](double u) {
      const double v = ramp(v0, target.x(), settings_.accel, u);
      const double th = heading(u);
      return Eigen::Vector2d(v * std::cos(th), v * std::sin(th));
    };
    const double split = std::min(std::min(tv, tw), t_ramp);
    for (const auto& [a, b] : {std::pair{0.0, split}, std::pair{split, t_ramp}}) {
      if (b <= a) continue;
      constexpr int kIntervals = 32;  // even; the error is below 1e-10 m over a 0.4 s ramp
      const double h = (b - a) / kIntervals;
      Eigen::Vector2d sum = velocity(a) + velocity(b);
      for (int i = 1; i < kIntervals; ++i) sum += (i % 2 == 1 ? 4.0 : 2.0) * velocity(a + i * h);
      out.position += sum * (h / 3.0);
    }
    out.heading = heading(t_ramp);
  }
  out.velocity = Eigen::Vector2d(ramp(v0, target.x(), settings_.accel, t_ramp), ramp(w0, target.y(), settings_.alpha, t_ramp));
  if (t > t_ramp) {
    out.position += arc(out.velocity.x(), out.velocity.y(), out.heading, t - t_ramp);
    out.heading += out.velocity.y() * (t - t_ramp);
  }
  out.heading = std::remainder(out.heading, 2.0 * std::numbers::pi);
  return out;
}

double UnicycleDisc::speed_bound(const RobotState& s, const Eigen::Vector2d& command) const {
  return std::max(std::abs(s.velocity.x()), std::abs(clipped(command).x()));
}

Footprint UnicycleDisc::footprint() const {
  return settings_.length > 0.0 ? Footprint::rectangle(settings_.length, 2.0 * settings_.radius)
                                : Footprint::disc(settings_.radius);
}

// omega ramps between its value now and the clipped command's, so neither is exceeded.
double UnicycleDisc::turn_bound(const RobotState& s, const Eigen::Vector2d& command) const {
  return std::max(std::abs(s.velocity.y()), std::abs(clipped(command).y()));
}

}  // namespace amp::nav
