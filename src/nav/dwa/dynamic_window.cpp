#include "amp/nav/dwa/dynamic_window.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include "amp/core/error.hpp"
#include "amp/core/joint_space.hpp"
#include "amp/nav/nav_world.hpp"
#include "amp/nav/simulator.hpp"

namespace amp::nav {

void DynamicWindowSettings::validate() const {
  auto positive = [](double v, const char* name) {
    if (!(v > 0.0) || !std::isfinite(v)) throw ParameterError(std::string("dwa: ") + name + " must be > 0, got " + std::to_string(v));
  };
  auto non_negative = [](double v, const char* name) {
    if (!(v >= 0.0) || !std::isfinite(v)) throw ParameterError(std::string("dwa: ") + name + " must be >= 0, got " + std::to_string(v));
  };
  positive(sim_time, "sim_time");
  positive(granularity, "granularity");
  positive(clearance_cap, "clearance_cap");
  positive(goal_tolerance, "goal_tolerance");
  non_negative(heading_weight, "heading_weight");
  non_negative(clearance_weight, "clearance_weight");
  non_negative(velocity_weight, "velocity_weight");
  if (v_samples < 1 || omega_samples < 1) throw ParameterError("dwa: v_samples and omega_samples must be >= 1");
}

DynamicWindow::DynamicWindow(const world::GridCostToGo& cost_to_go, Eigen::Vector2d origin, Eigen::Vector2d goal,
                             UnicycleDiscSettings robot, DynamicWindowSettings settings)
    : cost_(&cost_to_go), origin_(origin), goal_(goal), robot_(robot), settings_(settings) {
  robot_.validate();
  settings_.validate();
}

bool DynamicWindow::arrived(const RobotState& s) const { return (s.position - goal_).norm() < settings_.goal_tolerance; }

Eigen::Vector2d DynamicWindow::descent(const Eigen::Vector2d& p) const {
  const world::GridCells& g = cost_->cells();
  const Eigen::Vector2d q = (p - origin_) / g.cell_size;
  const int x = static_cast<int>(std::floor(q.x())), y = static_cast<int>(std::floor(q.y()));
  auto value = [&](int cx, int cy) {
    return cost_->free(cx, cy) ? cost_->distance(cost_->index(cx, cy)) : world::GridCostToGo::kUnreachable;
  };
  const double here = value(x, y);
  if (here == world::GridCostToGo::kUnreachable) return goal_ - p;
  if (here == 0.0) return goal_ - p;  // in the goal's cell
  // Central differences of the cost-to-go, one-sided beside blocked cells.
  auto slope = [&](double minus, double plus) {
    const bool m = minus < world::GridCostToGo::kUnreachable, pl = plus < world::GridCostToGo::kUnreachable;
    if (m && pl) return 0.5 * (plus - minus);
    if (pl) return plus - here;
    if (m) return here - minus;
    return 0.0;
  };
  const Eigen::Vector2d down(-slope(value(x - 1, y), value(x + 1, y)), -slope(value(x, y - 1), value(x, y + 1)));
  if (down.squaredNorm() > 0.0) return down;
  const int n = cost_->next(cost_->index(x, y));  // a saddle: the maximum-likelihood step
  return n < 0 ? Eigen::Vector2d(goal_ - p)
               : Eigen::Vector2d(origin_ + g.cell_size * Eigen::Vector2d(n % g.width + 0.5, n / g.width + 0.5) - p);
}

Eigen::Vector2d DynamicWindow::command(const Simulator& sim) {
  const RobotState& s = sim.state();
  const NavWorld& world = sim.next_world();
  const double dt = sim.time_step();
  const Footprint& f = sim.footprint();
  const double v_lo = std::max(robot_.v_min, s.velocity.x() - robot_.accel * dt);
  const double v_hi = std::min(robot_.v_max, s.velocity.x() + robot_.accel * dt);
  const double w_lo = std::max(-robot_.omega_max, s.velocity.y() - robot_.alpha * dt);
  const double w_hi = std::min(robot_.omega_max, s.velocity.y() + robot_.alpha * dt);
  struct Sample {
    double v, w, heading, clearance;
  };
  constexpr double kFirstCheck = 0.005;  // m
  // Only a clearance below kFirstCheck matters here (capped there, the tests below are unchanged).
  const double here = f.clearance_up_to(world, s.position, s.heading, kFirstCheck);
  std::vector<Sample> admissible;
  admissible.reserve(static_cast<std::size_t>(settings_.v_samples * settings_.omega_samples));
  auto at = [](double lo, double hi, int i, int n) { return n == 1 ? 0.5 * (lo + hi) : lo + (hi - lo) * i / (n - 1); };
  for (int i = 0; i < settings_.v_samples; ++i) {
    if (stop_ != nullptr && stop_->time_up()) break;
    const double v = at(v_lo, v_hi, i, settings_.v_samples);
    for (int k = 0; k < settings_.omega_samples; ++k) {
      const double w = at(w_lo, w_hi, k, settings_.omega_samples);
      // The arc, checked at the footprint's heading every `granularity` metres that any of its
      // discs travels (a disc's rotation sweeps nothing), and at its first kFirstCheck metres: a
      // robot touching a wall may only take arcs that leave it (the simulator refuses moves that do
      // not gain clearance in contact).
      const double length = std::abs(v) * settings_.sim_time;
      const double swept = length + f.centre_reach() * std::abs(w) * settings_.sim_time;
      const int n = std::max(1, static_cast<int>(std::ceil(swept / settings_.granularity)));
      auto pose = [&](double t, double& heading_out) {
        heading_out = s.heading + w * t;
        return Eigen::Vector2d(s.position + (std::abs(w) < 1e-9
                                                 ? Eigen::Vector2d(v * t * std::cos(s.heading), v * t * std::sin(s.heading))
                                                 : Eigen::Vector2d(v / w * (std::sin(heading_out) - std::sin(s.heading)),
                                                                   -v / w * (std::cos(heading_out) - std::cos(s.heading)))));
      };
      double least = std::numeric_limits<double>::infinity();
      double heading = s.heading;
      Eigen::Vector2d end = s.position;
      bool free = true;
      if (length > 0.0 && here < kFirstCheck) {
        double h0 = 0.0;
        const Eigen::Vector2d first = pose(settings_.sim_time * std::min(1.0, kFirstCheck / length), h0);
        free = f.clearance_up_to(world, first, h0, kFirstCheck) > here;
      }
      for (int j = 1; j <= n && free; ++j) {
        end = pose(settings_.sim_time * j / n, heading);
        // Capped: the score uses min(least, cap), and the cap is > 0 so `free` is unchanged.
        const double c = f.clearance_up_to(world, end, heading, settings_.clearance_cap);
        least = std::min(least, c);
        free = c > 0.0;
      }
      if (length == 0.0) heading = s.heading + w * settings_.sim_time;
      if (!free) continue;
      const Eigen::Vector2d to = descent(end);
      const double err = to.squaredNorm() > 0.0 ? std::abs(core::angle_difference(heading, std::atan2(to.y(), to.x()))) : 0.0;
      admissible.push_back({v, w, 1.0 - err / std::numbers::pi, std::min(least, settings_.clearance_cap)});
    }
  }
  if (admissible.empty()) {
    const Eigen::Vector2d to = descent(s.position);
    return {0.0, std::copysign(robot_.omega_max, core::angle_difference(s.heading, std::atan2(to.y(), to.x())))};
  }
  const Sample* best = nullptr;
  double best_score = -1e300;
  for (const Sample& a : admissible) {
    const double score = settings_.heading_weight * a.heading + settings_.clearance_weight * a.clearance / settings_.clearance_cap +
                         settings_.velocity_weight * a.v / robot_.v_max;
    if (score > best_score) best_score = score, best = &a;
  }
  return {best->v, best->w};
}

}  // namespace amp::nav
