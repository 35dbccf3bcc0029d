#pragma once
// Exact 2-D geometry for the property tests (issue 17). It shares no code with the library's
// checkers, so a path or trace is judged against what the problem file says, not against the code
// under test. A gap <= 0 means overlap: touching counts, so a positive gap is a proven margin.
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include <Eigen/Core>

#include "amp/core/rng.hpp"

namespace amp::test {

using Vec2 = Eigen::Vector2d;
using Poly = std::vector<Vec2>;
struct Disc {
  Vec2 c = Vec2::Zero();
  double r = 0.0;
};
struct Box2 {
  Vec2 lo = Vec2::Zero(), hi = Vec2::Zero();
};
inline constexpr double kInf = std::numeric_limits<double>::infinity();
inline constexpr double kPi = std::numbers::pi;

inline double cross2(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }
inline double point_segment_distance(const Vec2& p, const Vec2& a, const Vec2& b) {
  const Vec2 ab = b - a;
  const double l2 = ab.squaredNorm();
  const double t = l2 > 0.0 ? std::clamp((p - a).dot(ab) / l2, 0.0, 1.0) : 0.0;
  return (a + t * ab - p).norm();
}
inline double segment_segment_distance(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d) {
  const double d1 = cross2(b - a, c - a), d2 = cross2(b - a, d - a), d3 = cross2(d - c, a - c), d4 = cross2(d - c, b - c);
  if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0))) return 0.0;
  return std::min({point_segment_distance(a, c, d), point_segment_distance(b, c, d), point_segment_distance(c, a, b),
                   point_segment_distance(d, a, b)});
}
inline bool point_in_polygon(const Vec2& p, const Poly& poly) {  // crossing number
  bool in = false;
  for (std::size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++) {
    const Vec2 &a = poly[j], &b = poly[i];
    if ((a.y() > p.y()) != (b.y() > p.y()) && p.x() < a.x() + (p.y() - a.y()) * (b.x() - a.x()) / (b.y() - a.y())) in = !in;
  }
  return in;
}
inline double polygon_boundary_distance(const Vec2& p, const Poly& poly) {
  double d = kInf;
  for (std::size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++) d = std::min(d, point_segment_distance(p, poly[j], poly[i]));
  return d;
}
inline double polygon_polygon_gap(const Poly& a, const Poly& b) {
  if (point_in_polygon(a[0], b) || point_in_polygon(b[0], a)) return 0.0;
  double d = kInf;
  for (std::size_t i = 0, j = a.size() - 1; i < a.size(); j = i++) {
    for (std::size_t k = 0, l = b.size() - 1; k < b.size(); l = k++) d = std::min(d, segment_segment_distance(a[j], a[i], b[l], b[k]));
  }
  return d;
}
inline double polygon_disc_gap(const Poly& p, const Disc& d) {
  return point_in_polygon(d.c, p) ? -d.r : polygon_boundary_distance(d.c, p) - d.r;
}
inline double disc_disc_gap(const Disc& a, const Disc& b) { return (a.c - b.c).norm() - a.r - b.r; }
inline Poly box_polygon(const Box2& b) { return {b.lo, {b.hi.x(), b.lo.y()}, b.hi, {b.lo.x(), b.hi.y()}}; }
inline Box2 polygon_box(const Poly& p) {
  Box2 b{p[0], p[0]};
  for (const Vec2& v : p) b.lo = b.lo.cwiseMin(v), b.hi = b.hi.cwiseMax(v);
  return b;
}
// A lower bound of the distance between two boxes (0 when they overlap).
inline double box_box_distance(const Box2& a, const Box2& b) {
  return Vec2((a.lo - b.hi).cwiseMax(b.lo - a.hi).cwiseMax(0.0)).norm();
}
// How far a disc (a point: r = 0) may move and stay inside `b`.
inline double inner_slack(const Box2& b, const Vec2& p, double r) {
  return std::min({p.x() - r - b.lo.x(), p.y() - r - b.lo.y(), b.hi.x() - p.x() - r, b.hi.y() - p.y() - r});
}
// Uniform in the box [lo, hi], x drawn first (one draw per statement: argument order is unspecified).
inline Vec2 uniform2(core::Rng& rng, const Vec2& lo, const Vec2& hi) {
  const double x = rng.uniform(lo.x(), hi.x());
  return {x, rng.uniform(lo.y(), hi.y())};
}
inline Vec2 transform(double x, double y, double th, const Vec2& p) {
  return {x + std::cos(th) * p.x() - std::sin(th) * p.y(), y + std::sin(th) * p.x() + std::cos(th) * p.y()};
}
inline double wrap(double a) { return a - 2 * kPi * std::floor((a + kPi) / (2 * kPi)); }

}  // namespace amp::test
