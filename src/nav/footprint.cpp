#include "amp/nav/footprint.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "amp/core/error.hpp"
#include "amp/nav/nav_world.hpp"

namespace amp::nav {

namespace {
// Below this clearance a turn counts as touching (blocked, as segment_free counts it), and
// conservative advancement would crawl.
constexpr double kTouch = 1e-9;
constexpr int kMaxTurnAdvances = 100000;
}  // namespace

Footprint::Footprint(std::vector<Eigen::Vector2d> centres, double radius, double length, double width)
    : centres_(std::move(centres)), radius_(radius), length_(length), width_(width) {
  for (const Eigen::Vector2d& c : centres_) reach_ = std::max(reach_, c.norm());
}

Footprint Footprint::disc(double radius) {
  if (!(radius > 0.0) || !std::isfinite(radius)) {
    throw ParameterError("footprint: the disc's radius must be > 0, got " + std::to_string(radius));
  }
  return Footprint({Eigen::Vector2d::Zero()}, radius, 2.0 * radius, 2.0 * radius);
}

Footprint Footprint::rectangle(double length, double width, double cover_tolerance) {
  if (!(width > 0.0) || !std::isfinite(width) || !(length >= width) || !std::isfinite(length)) {
    throw ParameterError("footprint: a rectangle needs length >= width > 0, got " + std::to_string(length) + " x " +
                         std::to_string(width));
  }
  if (!(cover_tolerance > 0.0) || !std::isfinite(cover_tolerance)) {
    throw ParameterError("footprint: cover_tolerance must be > 0, got " + std::to_string(cover_tolerance));
  }
  const double half_w = 0.5 * width;
  // The longest slice whose corner disc stays within the tolerance of the half width.
  const double half_slice = std::sqrt((half_w + cover_tolerance) * (half_w + cover_tolerance) - half_w * half_w);
  const int n = std::max(1, static_cast<int>(std::ceil(length / (2.0 * half_slice) - 1e-12)));
  const double slice = length / n;
  std::vector<Eigen::Vector2d> centres;
  for (int k = 0; k < n; ++k) centres.emplace_back(-0.5 * length + (k + 0.5) * slice, 0.0);
  return Footprint(std::move(centres), std::hypot(half_w, 0.5 * slice), length, width);
}

std::vector<Eigen::Vector2d> Footprint::placed(const Eigen::Vector2d& p, double heading) const {
  std::vector<Eigen::Vector2d> out;
  out.reserve(centres_.size());
  all_placed(p, heading, [&](const Eigen::Vector2d& q) {
    out.push_back(q);
    return true;
  });
  return out;
}

bool Footprint::free(const NavWorld& world, const Eigen::Vector2d& p, double heading) const {
  if (is_disc()) return world.disc_free(p, radius_);
  return all_placed(p, heading, [&](const Eigen::Vector2d& q) { return world.disc_free(q, radius_); });
}

double Footprint::clearance(const NavWorld& world, const Eigen::Vector2d& p, double heading) const {
  if (is_disc()) return world.clearance(p, radius_);
  double least = std::numeric_limits<double>::infinity();
  all_placed(p, heading, [&](const Eigen::Vector2d& q) {
    least = std::min(least, world.clearance(q, radius_));
    return true;
  });
  return least;
}

double Footprint::clearance_up_to(const NavWorld& world, const Eigen::Vector2d& p, double heading, double cap) const {
  double least = cap;
  all_placed(p, heading, [&](const Eigen::Vector2d& q) {
    least = std::min(least, world.clearance_up_to(q, radius_, least));
    return true;
  });
  return least;
}

bool Footprint::turn_free(const NavWorld& world, const Eigen::Vector2d& p, double from, double turn) const {
  if (!free(world, p, from)) return false;
  if (reach_ == 0.0 || turn == 0.0) return true;
  const double total = std::abs(turn), sign = turn > 0.0 ? 1.0 : -1.0;
  double done = 0.0;
  for (int i = 0; i < kMaxTurnAdvances; ++i) {
    const double c = clearance(world, p, from + sign * done);
    if (!(c > kTouch)) return false;
    done += c / reach_;
    if (done >= total) return free(world, p, from + turn);
  }
  return false;  // too close to advance: counted as blocked
}

}  // namespace amp::nav
