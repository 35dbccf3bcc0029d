#include "amp/nav/policy/footprint_drive.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>

#include "amp/nav/footprint.hpp"
#include "amp/nav/nav_world.hpp"
#include "amp/nav/policy/policy_search.hpp"

namespace amp::nav {

namespace {

Eigen::Vector2d xy(const State& w) { return {w[0], w[1]}; }

double heading_of(const std::vector<State>& w, std::size_t k) {  // segment k: w_k -> w_k+1
  const Eigen::Vector2d d = xy(w[k + 1]) - xy(w[k]);
  return std::atan2(d.y(), d.x());
}

Eigen::Vector2d unit(double heading) { return {std::cos(heading), std::sin(heading)}; }

}  // namespace

bool segment_drivable(const PolicyValue& value, const std::vector<State>& w, std::size_t k) {
  const Footprint& f = value.footprint();
  if (f.is_disc()) return segment_free(value.world(), xy(w[k]), xy(w[k + 1]), value.radius());
  const Eigen::Vector2d shift = xy(w[k + 1]) - xy(w[k]);
  return f.all_placed(xy(w[k]), heading_of(w, k),
                      [&](const Eigen::Vector2d& c) { return segment_free(value.world(), c, c + shift, value.radius()); });
}

bool turn_drivable(const PolicyValue& value, const std::vector<State>& w, std::size_t k) {
  const Footprint& f = value.footprint();
  if (f.is_disc() || k + 1 >= w.size()) return true;
  // The robot starts facing the goal (unicycle_simulator places it so).
  const double from = k > 0 ? heading_of(w, k - 1) : std::atan2(w.back()[1] - w[0][1], w.back()[0] - w[0][0]);
  return f.turn_free(value.world(), xy(w[k]), from, std::remainder(heading_of(w, k) - from, 2.0 * std::numbers::pi));
}

bool policy_free(const PolicyValue& value, const std::vector<State>& w) {
  for (std::size_t k = 0; k + 1 < w.size(); ++k) {
    if (!segment_drivable(value, w, k) || !turn_drivable(value, w, k)) return false;
  }
  return true;
}

bool make_drivable(const PolicyValue& value, std::vector<State>& w, double step) {
  const double most = value.footprint().length() + value.footprint().width();
  // Everything that depends on where inner waypoint k is: its two segments and three turns.
  auto drivable_about = [&](std::size_t k) {
    return segment_drivable(value, w, k - 1) && segment_drivable(value, w, k) && turn_drivable(value, w, k - 1) &&
           turn_drivable(value, w, k) && turn_drivable(value, w, k + 1);
  };
  for (std::size_t k = 1; k + 1 < w.size();) {
    if (segment_drivable(value, w, k - 1) && segment_drivable(value, w, k) && turn_drivable(value, w, k)) {
      ++k;
      continue;
    }
    // Without it: a grid path's jog of a cell or two that a long body cannot follow.
    const State original = w[k];
    w.erase(w.begin() + static_cast<std::ptrdiff_t>(k));
    if (segment_drivable(value, w, k - 1) && turn_drivable(value, w, k - 1) && turn_drivable(value, w, k)) continue;
    w.insert(w.begin() + static_cast<std::ptrdiff_t>(k), original);
    // Turn further on (out of a door first), or sooner (lined up before entering one), or else
    // anywhere as near: on the ring of lattice points `r` steps away, after those two.
    const Eigen::Vector2d on = (xy(w[k]) - xy(w[k - 1])).normalized(), back = (xy(w[k]) - xy(w[k + 1])).normalized();
    auto try_at = [&](const Eigen::Vector2d& offset) {
      w[k][0] = original[0] + offset.x();
      w[k][1] = original[1] + offset.y();
      return drivable_about(k);
    };
    bool fixed = false;
    const int rings = static_cast<int>(std::floor(most / step));
    for (int r = 1; r <= rings && !fixed; ++r) {
      fixed = try_at(r * step * on) || try_at(r * step * back);
      for (int i = -r; i <= r && !fixed; ++i) {
        for (const Eigen::Vector2d& d : {Eigen::Vector2d(i, -r), Eigen::Vector2d(i, r), Eigen::Vector2d(-r, i), Eigen::Vector2d(r, i)}) {
          if (try_at(step * d)) {
            fixed = true;
            break;
          }
        }
      }
    }
    if (!fixed) {
      w[k] = original;
      return false;
    }
    ++k;
  }
  face_along(w);
  return policy_free(value, w);
}

namespace {

// The footprint's least clearance with its centre on centre + t u (u at `heading`), |t| <= half,
// to within `spacing`: the room a crossing leaves, for comparing crossings (drivability is then
// certified exactly). Each disc sweeps its own line; a disc's clearance is 1-Lipschitz along it, so
// from a point with clearance c no point nearer than c - least can be below the least found, and
// the sweep steps that far (only the stretch beside an obstacle is sampled finely). Stops early at
// or below `floor`, a room already beaten.
double room_along(const PolicyValue& value, const Eigen::Vector2d& centre, double heading, double half, double spacing,
                  double floor = -std::numeric_limits<double>::infinity()) {
  const Eigen::Vector2d u = unit(heading);
  const NavWorld& world = value.world();
  double least = std::numeric_limits<double>::infinity();
  value.footprint().all_placed(centre, heading, [&](const Eigen::Vector2d& q) {
    least = std::min(least, world.clearance(q, value.radius()));
    for (const double side : {1.0, -1.0}) {
      for (double t = 0.0; t < half && least > floor;) {
        t = std::min(half, t + spacing);
        const double c = world.clearance(q + side * t * u, value.radius());
        least = std::min(least, c);
        t += std::max(0.0, c - least - spacing);
      }
    }
    return least > floor;
  });
  return least;
}

// The footprint's least clearance over the turn in place at waypoint k (as turn_drivable turns it),
// sampled every degree: how much a turn under noise has to spare.
double turn_room(const PolicyValue& value, const std::vector<State>& w, std::size_t k) {
  const Footprint& f = value.footprint();
  const Eigen::Vector2d p = xy(w[k]);
  if (k + 1 >= w.size()) return std::numeric_limits<double>::infinity();
  const double from = k > 0 ? heading_of(w, k - 1) : std::atan2(w.back()[1] - w[0][1], w.back()[0] - w[0][0]);
  const double turn = std::remainder(heading_of(w, k) - from, 2.0 * std::numbers::pi);
  const int n = std::max(1, static_cast<int>(std::ceil(std::abs(turn) * 180.0 / std::numbers::pi)));
  double least = std::numeric_limits<double>::infinity();
  for (int i = 0; i <= n; ++i) least = std::min(least, f.clearance(value.world(), p, from + turn * i / n));
  return least;
}

struct Crossing {
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
  double heading = 0.0;
  double room = -std::numeric_limits<double>::infinity();
};

// The crossing of the place at p with the most room. Headings within 60 degrees of `heading`, by
// 1 degree, nearest the segment's first (ties keep the least change); for each, offsets across by
// step / 4 up to `step`, the room sampled every step / 10. The room is 1-Lipschitz in the offset,
// so only a heading within step / 8 (half an offset) and the sampling error of the best can hold a
// better crossing: for those, a golden-section search of the offset about their best, sampled
// every step / 50. A crossing through a door is tent-shaped in the offset, which it suits.
Crossing roomiest_crossing(const PolicyValue& value, const Eigen::Vector2d& p, double heading, double half, double step) {
  constexpr int kHeadings = 60, kOffsets = 4, kGoldenSteps = 8;
  const double degree = std::numbers::pi / 180.0, shift = 0.25 * step, coarse = 0.1 * step, fine = 0.02 * step;
  const double margin = 0.5 * shift + coarse;
  auto centre = [&](double h, double offset) { return Eigen::Vector2d(p + offset * Eigen::Vector2d(-std::sin(h), std::cos(h))); };
  struct Option {
    double heading, offset, room;
  };
  std::vector<Option> options;
  Crossing best;
  for (int a = 0; a <= 2 * kHeadings; ++a) {
    const double h = heading + ((a + 1) / 2) * (a % 2 == 1 ? 1.0 : -1.0) * degree;
    Option o{h, 0.0, -std::numeric_limits<double>::infinity()};
    for (int k = 0; k <= 2 * kOffsets; ++k) {
      const double offset = ((k + 1) / 2) * (k % 2 == 1 ? 1.0 : -1.0) * shift;
      const double room = room_along(value, centre(h, offset), h, half, coarse, std::max(o.room, best.room - margin));
      if (room > o.room) o.offset = offset, o.room = room;
    }
    if (o.room > best.room) best = {centre(h, o.offset), h, o.room};
    options.push_back(o);
  }
  const double bar = best.room - margin;
  best.room = -std::numeric_limits<double>::infinity();
  const double golden = 0.5 * (std::sqrt(5.0) - 1.0);
  for (const Option& o : options) {
    if (!(o.room > bar)) continue;
    auto room_at = [&](double offset) { return room_along(value, centre(o.heading, offset), o.heading, half, fine); };
    double lo = o.offset - 0.5 * shift, hi = o.offset + 0.5 * shift;
    double x1 = hi - golden * (hi - lo), x2 = lo + golden * (hi - lo), r1 = room_at(x1), r2 = room_at(x2);
    for (int i = 0; i < kGoldenSteps; ++i) {
      if (r1 >= r2) {
        hi = x2, x2 = x1, r2 = r1, x1 = hi - golden * (hi - lo), r1 = room_at(x1);
      } else {
        lo = x1, x1 = x2, r1 = r2, x2 = lo + golden * (hi - lo), r2 = room_at(x2);
      }
    }
    const double offset = r1 >= r2 ? x1 : x2, room = std::max(r1, r2);
    if (room > best.room) best = {centre(o.heading, offset), o.heading, room};
  }
  return best;
}

// The policy with the waypoints about the crossing replaced by its two ends A and B, each `reach`
// from its centre, or nothing if the start or the goal would be passed or a changed segment or turn
// is not drivable. `k` is the segment the crossing replaces and `v` the speed through it.
std::optional<std::vector<State>> with_crossing(const PolicyValue& value, const std::vector<State>& w, std::size_t k,
                                                const Crossing& x, double reach, double v, std::size_t& at_b) {
  const Eigen::Vector2d u = unit(x.heading);
  auto along = [&](std::size_t m) { return (xy(w[m]) - x.centre).dot(u); };
  std::size_t i = k, j = k + 1;
  while (i > 0 && along(i) >= -reach) --i;
  while (j + 1 < w.size() && along(j) <= reach) ++j;
  if (along(i) >= -reach || along(j) <= reach) return std::nullopt;
  std::vector<State> out(w.begin(), w.begin() + static_cast<std::ptrdiff_t>(i) + 1);
  for (const double s : {-reach, reach}) {
    State e = w[k];
    e[0] = x.centre.x() + s * u.x();
    e[1] = x.centre.y() + s * u.y();
    e[3] = v;
    out.push_back(e);
  }
  out.insert(out.end(), w.begin() + static_cast<std::ptrdiff_t>(j), w.end());
  for (std::size_t m = i; m <= i + 2; ++m) {
    if (!segment_drivable(value, out, m)) return std::nullopt;
  }
  for (std::size_t m = i; m <= i + 3; ++m) {
    if (!turn_drivable(value, out, m)) return std::nullopt;
  }
  face_along(out);
  at_b = i + 2;
  return out;
}

}  // namespace

int square_crossings(const PolicyValue& value, std::vector<State>& w, double step) {
  const Footprint& f = value.footprint();
  if (f.is_disc() || w.size() < 2 || !(step > 0.0)) return 0;
  const double half = 0.5 * (f.length() + f.width());  // the body, and as much again, either side of the passage
  const double threshold = value.settings().safety;
  int squared = 0;
  // Each replacement moves on past its crossing; the guard bounds pathological back-and-forth.
  std::size_t guard = 2 * w.size();
  for (std::size_t k = 0; k + 1 < w.size() && guard > 0; ++k, --guard) {
    // The tightest place along the segment, driven at its heading.
    const Eigen::Vector2d a = xy(w[k]), b = xy(w[k + 1]);
    const double len = (b - a).norm(), heading = heading_of(w, k);
    if (len == 0.0) continue;
    const int n = std::max(1, static_cast<int>(std::ceil(len / (0.5 * step))));
    double tightest = std::numeric_limits<double>::infinity(), t_at = 0.0;
    for (int i = 0; i <= n; ++i) {
      const double t = static_cast<double>(i) / n;
      const double c = f.clearance(value.world(), a + t * (b - a), heading);
      if (c < tightest) tightest = c, t_at = t;
    }
    if (tightest >= threshold) continue;
    const Eigen::Vector2d p = a + t_at * (b - a);
    const double room = room_along(value, p, heading, half, 0.5 * step);
    const Crossing best = roomiest_crossing(value, p, heading, half, step);
    if (!(best.room >= room + kMinCrossingGain)) continue;
    // How far either side of the passage to turn: the nearest where both turns have the safety
    // range to spare, or else the roomiest (a turn a hair from a door frame fails under noise).
    const double v = (1.0 - t_at) * w[k][3] + t_at * w[k + 1][3];
    std::optional<std::vector<State>> chosen;
    std::size_t chosen_b = 0;
    double chosen_room = -std::numeric_limits<double>::infinity();
    for (double reach = half + step; reach <= half + 2.0 * f.length(); reach += step) {
      std::size_t at_b = 0;
      auto replaced = with_crossing(value, w, k, best, reach, v, at_b);
      if (!replaced) continue;
      const double turns = std::min(turn_room(value, *replaced, at_b - 1), turn_room(value, *replaced, at_b));
      if (turns > chosen_room) chosen = std::move(replaced), chosen_b = at_b, chosen_room = turns;
      if (chosen_room >= threshold) break;
    }
    if (chosen) {
      w = std::move(*chosen);
      ++squared;
      k = chosen_b - 1;  // on from B's segment
    }
  }
  return squared;
}

}  // namespace amp::nav
