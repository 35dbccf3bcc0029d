#include "amp/nav/policy/policy_value.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
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

namespace {

// Metres of slack on a bound from a nearby point, far above the rounding of the distances it
// combines, so a bound never decides a point that the query would decide otherwise.
constexpr double kBoundSlack = 1e-9;
// The lattice's spacing in integration steps (2 cm by default): each node then serves a few dozen of
// the points a search evaluates, and bounds them to within its spacing / sqrt(2).
constexpr double kLatticeSteps = 2.0;
// Lattice nodes per side of a tile, the unit of allocation.
constexpr int kTile = 16;
// A node far from obstacles is filled with a free disc this many spacings wider than asked for,
// so that its bound serves the points along a path for a while.
constexpr double kFreeMargin = 10.0;

Eigen::Vector2d unit_normal(const Eigen::Vector2d& direction) {
  return direction.squaredNorm() > 0.0 ? Eigen::Vector2d(Eigen::Vector2d(-direction.y(), direction.x()).normalized())
                                       : Eigen::Vector2d::Zero();
}

}  // namespace

// Bounds on the distance to the obstacles at the nodes of a square lattice over the world's bounds,
// each found when a point near it is first asked about. Policy search evaluates about a million
// points around one path; the bounds of a node, widened by its distance to a point, decide nearly
// all of them without a query. A node far from every obstacle holds only a lower bound, from a free
// disc (cheap where the exact distance would scan far). Tiles of nodes are allocated on first use,
// so a large world costs only where the path goes.
class PolicyValue::DistanceLattice {
 public:
  DistanceLattice(const NavWorld& world, double spacing) : world_(&world), spacing_(spacing), inverse_(1.0 / spacing) {
    const Eigen::AlignedBox2d& box = world.bounds();
    origin_ = box.min();
    const Eigen::Vector2d tiles = (box.max() - box.min()) * (inverse_ / kTile) + Eigen::Vector2d::Ones();
    // A world too large for a table of tiles gets no lattice: every point is then queried.
    constexpr double kMaxTiles = 1 << 20;
    if (tiles.allFinite() && tiles.x() * tiles.y() <= kMaxTiles) {
      tiles_x_ = static_cast<int>(tiles.x());
      tiles_y_ = static_cast<int>(tiles.y());
      tiles_.resize(static_cast<std::size_t>(tiles_x_) * static_cast<std::size_t>(tiles_y_));
    }
  }

  // The bounds at the node nearest to q, found if they were not yet; a disc reaching `reach` and
  // kFreeMargin spacings more is tried first. Nothing is known outside the lattice.
  DistanceBounds bounds_near(const Eigen::Vector2d& q, double reach) {
    const Eigen::Vector2d g = (q - origin_) * inverse_;
    if (!(g.x() > -0.5 && g.y() > -0.5 && g.x() < tiles_x_ * kTile - 0.5 && g.y() < tiles_y_ * kTile - 0.5)) return {q};
    const int i = static_cast<int>(std::floor(g.x() + 0.5)), j = static_cast<int>(std::floor(g.y() + 0.5));
    std::unique_ptr<Node[]>& tile = tiles_[static_cast<std::size_t>(j / kTile) * static_cast<std::size_t>(tiles_x_) +
                                           static_cast<std::size_t>(i / kTile)];
    if (!tile) tile = std::make_unique<Node[]>(kTile * kTile);
    Node& node = tile[(j % kTile) * kTile + i % kTile];
    const Eigen::Vector2d at = origin_ + spacing_ * Eigen::Vector2d(i, j);
    if (std::isnan(node.lower)) {
      const double cap = reach + kFreeMargin * spacing_;
      if (world_->disc_free(at, cap)) {
        node.lower = cap;
      } else {
        node.lower = node.upper = world_->nearest_obstacle(at).distance;
      }
    }
    return {at, node.lower, node.upper};
  }

 private:
  struct Node {
    double lower = std::numeric_limits<double>::quiet_NaN();  // NaN: not found yet
    double upper = std::numeric_limits<double>::infinity();
  };
  const NavWorld* world_;
  double spacing_, inverse_;
  Eigen::Vector2d origin_;
  int tiles_x_ = 0, tiles_y_ = 0;
  std::vector<std::unique_ptr<Node[]>> tiles_;
};

namespace {
Footprint checked_disc(double radius) {
  if (!(radius > 0.0) || !std::isfinite(radius)) {
    throw ParameterError("policy value: the footprint's radius must be > 0, got " + std::to_string(radius));
  }
  return Footprint::disc(radius);
}
}  // namespace

PolicyValue::PolicyValue(const NavWorld& world, double radius, PolicyRewardSettings settings)
    : PolicyValue(world, checked_disc(radius), settings) {}

PolicyValue::PolicyValue(const NavWorld& world, const Footprint& footprint, PolicyRewardSettings settings)
    : world_(&world), footprint_(footprint), radius_(footprint.disc_radius()), settings_(settings) {
  settings_.validate();
  lattice_ = std::make_unique<DistanceLattice>(world, kLatticeSteps * settings_.step);
}

PolicyValue::~PolicyValue() = default;
PolicyValue::PolicyValue(PolicyValue&&) noexcept = default;
PolicyValue& PolicyValue::operator=(PolicyValue&&) noexcept = default;

PolicyValue::Side PolicyValue::side_of(const DistanceBounds& b, const Eigen::Vector2d& p, double spread, double range) const {
  if (b.lower < 0.0) return Side::kUnknown;
  // The bounds widen by the farthest any of the points is from b.at; the slack covers rounding.
  const double moved = (p - b.at).norm() + spread;
  if (b.lower - moved - kBoundSlack - radius_ >= range) return Side::kClear;
  if (b.upper + moved + kBoundSlack - radius_ < range) return Side::kWithin;
  return Side::kUnknown;
}

bool PolicyValue::within_range(const Eigen::Vector2d& q, double range) const {
  const Side side = side_of(lattice_->bounds_near(q, radius_ + range), q, 0.0, range);
  if (side != Side::kUnknown) return side == Side::kWithin;
  return world_->clearance(q, radius_) < range;  // too close to the range to tell: the query itself
}

double PolicyValue::reward_at(const Eigen::Vector2d& p, const Eigen::Vector2d& side, double v, DistanceBounds& around) const {
  const PolicyRewardSettings& s = settings_;
  const double speed = std::max(v, s.v_floor);
  const double range = s.safety + s.safety_per_speed * speed;
  // Sigma points across the path (3-point Gauss-Hermite for a Gaussian).
  const double offset = std::sqrt(3.0) * s.sigma;
  const double weights[3] = {2.0 / 3.0, 1.0 / 6.0, 1.0 / 6.0};
  const double offsets[3] = {0.0, offset, -offset};
  // Every disc of the footprint at all three sigma points at once (they lie within offset + reach
  // of p), from the bounds carried along or else the nearest node's.
  const double spread = offset + footprint_.centre_reach();
  Side all = side_of(around, p, spread, range);
  if (all == Side::kUnknown) {
    around = lattice_->bounds_near(p, radius_ + range + spread);
    all = side_of(around, p, spread, range);
  }
  // The footprint faces along the path: direction (side.y, -side.x).
  const double heading = side.squaredNorm() > 0.0 ? std::atan2(-side.x(), side.y()) : 0.0;
  auto footprint_within = [&](const Eigen::Vector2d& q) {
    if (footprint_.is_disc()) return within_range(q, range);
    return !footprint_.all_placed(q, heading, [&](const Eigen::Vector2d& c) { return !within_range(c, range); });
  };
  double near = 0.0;
  for (int k = 0; k < 3; ++k) {
    if (all == Side::kWithin || (all == Side::kUnknown && footprint_within(p + offsets[k] * side))) near += weights[k];
  }
  return -s.c - s.c_time / speed - s.h * near;
}

double PolicyValue::immediate(const Eigen::Vector2d& p, const Eigen::Vector2d& direction, double v) const {
  DistanceBounds none;
  return reward_at(p, unit_normal(direction), v, none);
}

double PolicyValue::segments(const std::vector<State>& w, std::size_t first, std::size_t last) const {
  double sum = 0.0;
  DistanceBounds around;
  for (std::size_t j = first; j < last && j + 1 < w.size(); ++j) {
    const Eigen::Vector2d a(w[j][0], w[j][1]), b(w[j + 1][0], w[j + 1][1]);
    const double len = (b - a).norm();
    if (len == 0.0) continue;
    const Eigen::Vector2d side = unit_normal(b - a);
    // The midpoint rule on pieces of at most `step`.
    const int n = std::max(1, static_cast<int>(std::ceil(len / settings_.step)));
    for (int i = 0; i < n; ++i) {
      const double t = (i + 0.5) / n;
      sum += reward_at(a + t * (b - a), side, (1.0 - t) * w[j][3] + t * w[j + 1][3], around) * (len / n);
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
  const Eigen::Vector2d side = unit_normal(b - a);
  DistanceBounds around;
  for (int i = 1; i < n; ++i) {  // inside the segment, not at its ends
    const double t = static_cast<double>(i) / n;
    const double v = (1.0 - t) * w[j][3] + t * w[j + 1][3];
    const double r = reward_at(a + t * (b - a), side, v, around);
    if (!any || r < out.reward) out = {r, a + t * (b - a), v}, any = true;
  }
  if (!any) out = {0.0, 0.5 * (a + b), 0.5 * (w[j][3] + w[j + 1][3])};
  return out;
}

}  // namespace amp::nav
