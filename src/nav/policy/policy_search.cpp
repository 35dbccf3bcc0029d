#include "amp/nav/policy/policy_search.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>

#include "amp/core/error.hpp"
#include "amp/nav/footprint.hpp"
#include "amp/nav/policy/footprint_drive.hpp"
#include "amp/nav/nav_world.hpp"

namespace amp::nav {

void PolicySearchSettings::validate() const {
  auto positive = [](double v, const char* name) {
    if (!(v > 0.0) || !std::isfinite(v)) throw ParameterError(std::string(name) + " must be > 0, got " + std::to_string(v));
  };
  if (!(obstacle_weight >= 0.0) || !std::isfinite(obstacle_weight)) {
    throw ParameterError("obstacle_weight must be >= 0, got " + std::to_string(obstacle_weight));
  }
  positive(min_move, "min_move");
  positive(tolerance, "tolerance");
  positive(v_min, "v_min");
  if (max_sweeps < 1) throw ParameterError("max_sweeps must be >= 1, got " + std::to_string(max_sweeps));
  if (max_insertions < 0) throw ParameterError("max_insertions must be >= 0, got " + std::to_string(max_insertions));
  if (!(v_factor > 1.0) || !std::isfinite(v_factor)) throw ParameterError("v_factor must be > 1, got " + std::to_string(v_factor));
  if (!(v_max >= v_min) || !std::isfinite(v_max)) {
    throw ParameterError("v_max must be >= v_min, got " + std::to_string(v_max));
  }
}

bool segment_free(const NavWorld& world, const Eigen::Vector2d& a, const Eigen::Vector2d& b, double r) {
  const double len = (b - a).norm();
  constexpr double kTouch = 1e-9;
  for (double t = 0.0;;) {
    const Eigen::Vector2d p = len > 0.0 ? Eigen::Vector2d(a + (t / len) * (b - a)) : a;
    const double c = world.clearance(p, r);
    if (c <= kTouch) return false;
    if (t >= len) return true;
    t = std::min(len, t + c);  // no obstacle within c of p
  }
}

namespace {

Eigen::Vector2d xy(const State& w) { return {w[0], w[1]}; }

// Moving inner waypoint j keeps the footprint drivable: the two segments at w_j, and for a footprint
// that is not a disc the turns at w_j-1, w_j and w_j+1, whose headings it changes.
bool free_at(const PolicyValue& value, const std::vector<State>& w, std::size_t j) {
  return segment_drivable(value, w, j - 1) && segment_drivable(value, w, j) && turn_drivable(value, w, j - 1) &&
         turn_drivable(value, w, j) && turn_drivable(value, w, j + 1);
}

}  // namespace

void face_along(std::vector<State>& w) {
  for (std::size_t k = 0; k < w.size(); ++k) {
    const Eigen::Vector2d d = k + 1 < w.size() ? Eigen::Vector2d(xy(w[k + 1]) - xy(w[k]))
                                               : (k > 0 ? Eigen::Vector2d(xy(w[k]) - xy(w[k - 1])) : Eigen::Vector2d::Zero());
    if (d.squaredNorm() > 0.0) w[k][2] = std::atan2(d.y(), d.x());
    w[k][4] = 0.0;
  }
}

namespace {

// The steps at inner waypoints that last changed nothing, and what they read. A step at w_j reads
// only the positions and speeds of w_j-1, w_j and w_j+1 (headings and turn rates enter neither the
// value, nor eq. 11, nor the free-segment test), and for a footprint that is not a disc also w_j-2
// and w_j+2 (the turns at w_j-1 and w_j+1), so from bit-identical inputs it would again change
// nothing: it is skipped. Most waypoints settle after a few sweeps while their neighbours still move.
class SettledSteps {
 public:
  SettledSteps(std::size_t waypoints, bool disc) : inputs_(waypoints), reach_(disc ? 1 : 2) {}
  bool holds(const std::vector<State>& w, std::size_t j) const { return inputs_[j] && *inputs_[j] == read(w, j); }
  void record(const std::vector<State>& w, std::size_t j) { inputs_[j] = read(w, j); }
  void forget(std::size_t j) { inputs_[j].reset(); }
  // A waypoint inserted at index j: the steps after it move up by one.
  void insert(std::size_t j) { inputs_.insert(inputs_.begin() + static_cast<std::ptrdiff_t>(j), std::nullopt); }

 private:
  using Inputs = std::array<std::uint64_t, 15>;  // x, y, v of w_j-2 .. w_j+2 (those in reach), bit for bit
  Inputs read(const std::vector<State>& w, std::size_t j) const {
    Inputs in{};
    const std::size_t lo = j >= reach_ ? j - reach_ : 0, hi = std::min(w.size() - 1, j + reach_);
    for (std::size_t k = lo, at = 0; k <= hi; ++k, at += 3) {
      in[at] = std::bit_cast<std::uint64_t>(w[k][0]);
      in[at + 1] = std::bit_cast<std::uint64_t>(w[k][1]);
      in[at + 2] = std::bit_cast<std::uint64_t>(w[k][3]);
    }
    return in;
  }
  std::vector<std::optional<Inputs>> inputs_;
  std::size_t reach_;
};

// One sweep of Table 1, step 3; returns the value gained. Ends early, setting `stopped`, when `stop` fires.
double sweep(std::vector<State>& w, const PolicyValue& value, const PolicySearchSettings& s, SettledSteps& settled,
             const core::StopCondition* stop, bool& stopped) {
  double gained = 0.0;
  for (std::size_t j = 1; j + 1 < w.size(); ++j) {
    if (settled.holds(w, j)) continue;
    if (stop != nullptr && stop->time_up()) {
      stopped = true;
      break;
    }
    const double before = value.segments(w, j - 1, j + 1);
    double best = before;
    // Eq. 11: toward both neighbours, away from the nearest obstacle point.
    const Eigen::Vector2d p = xy(w[j]);
    const NearestObstacle zeta = value.world().nearest_obstacle(p);
    const Eigen::Vector2d grad = (xy(w[j - 1]) - p) + (xy(w[j + 1]) - p) - s.obstacle_weight * (zeta.point - p);
    for (double alpha = 1.0; alpha * grad.norm() >= s.min_move; alpha *= 0.5) {
      const State keep = w[j];
      w[j][0] = p.x() + alpha * grad.x();
      w[j][1] = p.y() + alpha * grad.y();
      const double v = value.segments(w, j - 1, j + 1);
      if (v > best && free_at(value, w, j)) {
        best = v;
        break;
      }
      w[j] = keep;
    }
    // The speed: faster or slower, whichever raises the two segments' value.
    for (const double f : {s.v_factor, 1.0 / s.v_factor}) {
      const double old = w[j][3];
      w[j][3] = std::clamp(old * f, s.v_min, s.v_max);
      const double v = value.segments(w, j - 1, j + 1);
      if (v > best) {
        best = v;
        break;
      }
      w[j][3] = old;
    }
    if (best > before) {
      gained += best - before;
      settled.forget(j);
    } else {
      settled.record(w, j);  // w_j is as it was
    }
  }
  return gained;
}

int search(std::vector<State>& w, const PolicyValue& value, const PolicySearchSettings& s, SettledSteps& settled,
           const core::StopCondition* stop, bool& stopped) {
  int sweeps = 0;
  while (sweeps < s.max_sweeps && !stopped) {
    ++sweeps;
    const double gained = sweep(w, value, s, settled, stop, stopped);
    face_along(w);
    if (gained < s.tolerance) break;
  }
  return sweeps;
}

}  // namespace

PolicySearchResult search_policy(std::vector<State> initial, const PolicyValue& value, const PolicySearchSettings& settings,
                                 const core::StopCondition* stop) {
  settings.validate();
  PolicySearchResult out;
  for (State& w : initial) w[3] = std::clamp(w[3], settings.v_min, settings.v_max);
  face_along(initial);
  out.projected = initial;
  out.value_projected = value.total(initial);
  std::vector<State> w = std::move(initial);
  SettledSteps settled(w.size(), value.footprint().is_disc());
  out.sweeps += search(w, value, settings, settled, stop, out.stopped);
  out.searched = w;
  out.value_searched = value.total(w);
  double current = out.value_searched;
  while (!out.stopped && out.insertions < settings.max_insertions && w.size() >= 2) {
    // Eq. 10: the lowest immediate reward inside a segment, below the reward at both its ends.
    std::size_t at = w.size();
    PolicyValue::Lowest pick;
    for (std::size_t j = 0; j + 1 < w.size(); ++j) {
      const PolicyValue::Lowest low = value.lowest_on_segment(w, j);
      const Eigen::Vector2d dir = xy(w[j + 1]) - xy(w[j]);
      if (low.reward < value.immediate(xy(w[j]), dir, w[j][3]) && low.reward < value.immediate(xy(w[j + 1]), dir, w[j + 1][3]) &&
          (at == w.size() || low.reward < pick.reward)) {
        at = j;
        pick = low;
      }
    }
    if (at == w.size()) break;
    std::vector<State> trial = w;
    State inserted = w[at];
    inserted[0] = pick.point.x();
    inserted[1] = pick.point.y();
    inserted[3] = pick.v;
    trial.insert(trial.begin() + static_cast<std::ptrdiff_t>(at) + 1, inserted);
    settled.insert(at + 1);  // a rejected trial ends the search, so `settled` need not go back
    const int sweeps = search(trial, value, settings, settled, stop, out.stopped);
    out.sweeps += sweeps;
    if (out.stopped) break;  // a trial cut short is not compared: the last kept policy stands
    const double v = value.total(trial);
    if (!(v > current + settings.tolerance)) break;  // no insertion raises the value: done
    w = std::move(trial);
    current = v;
    ++out.insertions;
  }
  out.final = w;
  out.value_final = current;
  return out;
}

}  // namespace amp::nav
