#pragma once
// Random small 2-D problems for the property tests (issue 17): drawn from a seed as the test's own
// model (bounds, obstacles or a map's blocked cells, robot, start, goal), then written as YAML (and
// a MovingAI map) for world::load_problem. The planners see only the files, as `amp plan` does;
// the model, judged with exact_geometry.hpp, is the independent reference.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "amp/core/edge_steps.hpp"
#include "amp/core/rng.hpp"
#include "amp/core/state.hpp"
#include "support/exact_geometry.hpp"

namespace amp::test {

// ---- the robot, as the problem file describes it -----------------------------------------------
enum class RobotKind { kPoint, kDisc, kRigid, kArm, kLinkage };
struct Link {
  double length = 1.0, width = 0.1;
};
struct RobotModel {
  RobotKind kind = RobotKind::kPoint;
  double radius = 0.0;                    // disc
  std::vector<Poly> polygons;             // rigid body, own frame
  std::vector<Disc> discs;
  double base_x = 0, base_y = 0, base_th = 0;  // arm
  std::vector<Link> links;                // arm, linkage
  std::vector<std::pair<double, double>> limits;  // per joint angle; empty: continuous joints

  bool chain() const { return kind == RobotKind::kArm || kind == RobotKind::kLinkage; }
  int dimension() const {
    const int n = static_cast<int>(links.size());
    return kind == RobotKind::kArm ? n : kind == RobotKind::kLinkage ? n + 2 : kind == RobotKind::kRigid ? 3 : 2;
  }
  // 0: a length, 1: an angle that wraps (short way round), 2: a limited angle (straight).
  int coordinate_kind(int i) const {
    if (kind == RobotKind::kPoint || kind == RobotKind::kDisc) return 0;
    if (kind == RobotKind::kRigid) return i < 2 ? 0 : 1;
    const int joint = kind == RobotKind::kArm ? i : i - 2;  // linkage: joint 0 is theta, never limited
    if (joint < 0) return 0;
    if (kind == RobotKind::kLinkage && joint == 0) return 1;
    return limits.empty() ? 1 : 2;
  }
  std::pair<double, double> joint_range(int i) const {
    const int joint = kind == RobotKind::kArm ? i : i - 3;  // limits[] of a linkage start at q1
    return coordinate_kind(i) == 2 ? limits[static_cast<std::size_t>(joint)] : std::pair{-kPi, kPi};
  }
};

inline RobotModel disc_robot(double radius) {
  RobotModel r;
  r.kind = RobotKind::kDisc;
  r.radius = radius;
  return r;
}

// The robot placed at a state; a chain's polygons are its links, in order.
struct Placed {
  std::vector<Poly> polygons;
  std::vector<Disc> discs;
};
inline void place(const RobotModel& r, const State& s, Placed& out) {
  out.polygons.clear(), out.discs.clear();
  switch (r.kind) {
    case RobotKind::kPoint:
    case RobotKind::kDisc:
      out.discs.push_back({{s[0], s[1]}, r.kind == RobotKind::kDisc ? r.radius : 0.0});
      return;
    case RobotKind::kRigid:
      for (const Poly& p : r.polygons) {
        Poly q;
        for (const Vec2& v : p) q.push_back(transform(s[0], s[1], s[2], v));
        out.polygons.push_back(std::move(q));
      }
      for (const Disc& d : r.discs) out.discs.push_back({transform(s[0], s[1], s[2], d.c), d.r});
      return;
    case RobotKind::kArm:
    case RobotKind::kLinkage: {
      const bool arm = r.kind == RobotKind::kArm;
      double x = arm ? r.base_x : s[0], y = arm ? r.base_y : s[1], th = arm ? r.base_th + s[0] : s[2];
      for (std::size_t k = 0; k < r.links.size(); ++k) {
        if (k > 0) {
          x += r.links[k - 1].length * std::cos(th), y += r.links[k - 1].length * std::sin(th);
          th += s[static_cast<int>(arm ? k : k + 2)];
        }
        const double l = r.links[k].length, h = 0.5 * r.links[k].width;
        out.polygons.push_back({transform(x, y, th, {-h, -h}), transform(x, y, th, {l + h, -h}),
                                transform(x, y, th, {l + h, h}), transform(x, y, th, {-h, h})});
      }
      return;
    }
  }
}

// A planar problem: the model, and the files that describe it.
struct PlanarModel {
  Box2 bounds;                  // the workspace (a map's rectangle)
  std::vector<Poly> polygons;   // obstacles
  std::vector<Box2> polygon_boxes;
  std::vector<Disc> circles;
  std::vector<Box2> cells;      // a map's blocked cells
  double cell = 0.0;            // a map's cell side
  RobotModel robot;
  State start, goal;
  std::string yaml;             // the problem file
  std::string map_text;         // MovingAI map (map worlds), named map.map beside the YAML
};

// The robot's clearance at s: the least gap to an obstacle or to the outside of the bounds, and half
// the least gap between non-neighbouring links (two links close in on each other at twice the speed
// of either). > 0: valid with that margin; <= 0: not provably valid.
inline double clearance(const PlanarModel& m, const State& s, Placed& placed) {
  place(m.robot, s, placed);
  double c = kInf;
  for (std::size_t i = 0; i < placed.polygons.size(); ++i) {
    const Poly& p = placed.polygons[i];
    const Box2 pb = polygon_box(p);
    for (const Vec2& v : p) c = std::min(c, inner_slack(m.bounds, v, 0.0));
    for (std::size_t k = 0; k < m.polygons.size(); ++k) {
      if (box_box_distance(pb, m.polygon_boxes[k]) < c) c = std::min(c, polygon_polygon_gap(p, m.polygons[k]));
    }
    for (const Box2& cell : m.cells) {
      if (box_box_distance(pb, cell) < c) c = std::min(c, polygon_polygon_gap(p, box_polygon(cell)));
    }
    for (const Disc& d : m.circles) c = std::min(c, polygon_disc_gap(p, d));
  }
  for (const Disc& d : placed.discs) {
    c = std::min(c, inner_slack(m.bounds, d.c, d.r));
    for (const Poly& p : m.polygons) c = std::min(c, polygon_disc_gap(p, d));
    for (const Box2& cell : m.cells) {
      if (box_box_distance({d.c, d.c}, cell) - d.r < c) c = std::min(c, polygon_disc_gap(box_polygon(cell), d));
    }
    for (const Disc& o : m.circles) c = std::min(c, disc_disc_gap(d, o));
  }
  if (m.robot.chain()) {
    for (std::size_t i = 0; i < placed.polygons.size(); ++i) {
      for (std::size_t j = i + 2; j < placed.polygons.size(); ++j) c = std::min(c, 0.5 * polygon_polygon_gap(placed.polygons[i], placed.polygons[j]));
    }
  }
  return c;
}

// ---- drawing problems ------------------------------------------------------------------------
struct PlanarOptions {
  bool map = false;                   // a MovingAI map world instead of polygons and circles
  bool disc_only = false;             // a disc robot (navigation)
  int min_cells = 8, max_cells = 24;  // map sides, in cells
  double min_cell = 0.1, max_cell = 1.0;
  double min_disc_cells = 0.2, max_disc_cells = 1.2;  // a map's disc radius, in cells
  double max_density = 0.12;          // share of a map's cells blocked at random, at most
  int max_walls = 4;                  // lines of blocked cells in a map, at most
  bool plan_settings = true;          // write resolution and edge_check (planner problems)
  double resolution = 0.0;            // > 0: this one; else drawn
};

inline std::string num(double v) {
  std::ostringstream o;
  o.precision(17);
  o << v;
  return o.str();
}
inline std::string state_yaml(const Eigen::VectorXd& s) {
  std::ostringstream o;
  o.precision(17);
  o << "[";
  for (int i = 0; i < s.size(); ++i) o << (i ? ", " : "") << s[i];
  o << "]";
  return o.str();
}
inline std::string point_yaml(const Vec2& p) { return state_yaml(p); }

// `resolution` and `edge_check` lines: mostly ordinary steps, some down to the smallest accepted.
inline std::string random_plan_settings(core::Rng& rng) {
  const double u = rng.uniform01(), floor = core::kMinResolutionFraction;
  const double resolution = u < 0.02   ? floor
                            : u < 0.06 ? std::max(floor, std::pow(10.0, rng.uniform(std::log10(floor), -4)))
                                       : std::pow(10.0, rng.uniform(-3.3, -1.3));
  return "resolution: " + num(resolution) + "\nedge_check: " + (rng.uniform01() < 0.4 ? "certified" : "discrete") + "\n";
}

// A simple polygon: vertices at sorted random angles around `c`, each at its own radius (star-shaped,
// so convex or not but never self-intersecting).
inline Poly star_polygon(core::Rng& rng, const Vec2& c, double radius) {
  const int n = 3 + static_cast<int>(rng.uniform_index(6));
  std::vector<double> angles;
  const double step = 2 * kPi / n, phase = rng.uniform(0, 2 * kPi);
  for (int i = 0; i < n; ++i) angles.push_back(phase + step * (i + rng.uniform(0.05, 0.95)));
  Poly p;
  for (double a : angles) p.push_back(c + radius * rng.uniform(0.35, 1.0) * Vec2(std::cos(a), std::sin(a)));
  return p;
}
// A shape item: a star polygon, a circle, or a turned rectangle (its corners in `poly`).
inline std::string random_shape(core::Rng& rng, const Vec2& c, double size, Poly& poly, Disc& disc) {
  const std::uint64_t kind = rng.uniform_index(3);
  if (kind == 0) {
    poly = star_polygon(rng, c, size);
    std::string y = "{polygon: [";
    for (std::size_t i = 0; i < poly.size(); ++i) y += (i ? ", " : "") + point_yaml(poly[i]);
    return y + "]}";
  }
  if (kind == 1) {
    disc = {c, size * rng.uniform(0.3, 1.0)};
    return "{circle: {center: " + point_yaml(c) + ", radius: " + num(disc.r) + "}}";
  }
  const double w = size * rng.uniform(0.3, 2.0), h = size * rng.uniform(0.2, 1.0), a = rng.uniform(-kPi, kPi);
  poly = {transform(c.x(), c.y(), a, {-w / 2, -h / 2}), transform(c.x(), c.y(), a, {w / 2, -h / 2}),
          transform(c.x(), c.y(), a, {w / 2, h / 2}), transform(c.x(), c.y(), a, {-w / 2, h / 2})};
  return "{rectangle: {center: " + point_yaml(c) + ", size: [" + num(w) + ", " + num(h) + "], angle: " + num(a) + "}}";
}

inline State random_state(const RobotModel& r, const Box2& b, core::Rng& rng) {
  State s(r.dimension());
  for (int i = 0; i < s.size(); ++i) {
    const bool xy = r.coordinate_kind(i) == 0;
    const auto [lo, hi] = xy ? std::pair{b.lo[i], b.hi[i]} : r.joint_range(i);
    s[i] = rng.uniform(lo, hi);
  }
  return s;
}

// A MovingAI map: a few walls of cells and scattered cells; returns the world line of the YAML.
inline std::string draw_map(core::Rng& rng, const PlanarOptions& o, PlanarModel& m) {
  const auto side = [&] { return o.min_cells + static_cast<int>(rng.uniform_index(o.max_cells - o.min_cells + 1)); };
  const int w = side(), h = side();
  const double cell = rng.uniform(o.min_cell, o.max_cell), density = rng.uniform(0.0, o.max_density);
  m.cell = cell;
  std::vector<std::string> rows(h, std::string(w, '.'));  // rows[j]: y from j * cell
  for (int b = static_cast<int>(rng.uniform_index(o.max_walls + 1)); b > 0; --b) {
    const int x0 = static_cast<int>(rng.uniform_index(w)), y0 = static_cast<int>(rng.uniform_index(h));
    const bool across = rng.uniform01() < 0.5;
    const int len = 1 + static_cast<int>(rng.uniform_index((across ? w : h) * 3 / 4));
    for (int i = 0; i < len; ++i) rows[std::min(h - 1, y0 + (across ? 0 : i))][std::min(w - 1, x0 + (across ? i : 0))] = '@';
  }
  std::ostringstream map;
  map << "type octile\nheight " << h << "\nwidth " << w << "\nmap\n";
  for (int j = h - 1; j >= 0; --j) {  // the top row first
    for (char& ch : rows[j]) ch = rng.uniform01() < density ? '@' : ch;
    map << rows[j] << "\n";
  }
  m.map_text = map.str();
  for (int j = 0; j < h; ++j) {
    for (int i = 0; i < w; ++i) {
      if (rows[j][i] == '@') m.cells.push_back({{i * cell, j * cell}, {(i + 1) * cell, (j + 1) * cell}});
    }
  }
  m.bounds = {{0, 0}, {w * cell, h * cell}};
  return "world: {map: map.map, resolution: " + num(cell) + "}\n";
}

// Bounds and up to 7 polygons, circles and rectangles; returns their YAML.
inline std::string draw_obstacles(core::Rng& rng, PlanarModel& m) {
  m.bounds.lo = uniform2(rng, Vec2(-10, -10), Vec2(10, 10));
  m.bounds.hi = m.bounds.lo + uniform2(rng, Vec2(4, 4), Vec2(20, 20));
  const double extent = (m.bounds.hi - m.bounds.lo).minCoeff();
  std::string y = "bounds: {min: " + point_yaml(m.bounds.lo) + ", max: " + point_yaml(m.bounds.hi) + "}\n";
  const int n = static_cast<int>(rng.uniform_index(8));
  if (n > 0) y += "world:\n  obstacles:\n";
  for (int i = 0; i < n; ++i) {
    const Vec2 c = uniform2(rng, m.bounds.lo, m.bounds.hi);
    const double size = extent * rng.uniform(0.04, 0.25);
    Poly p;
    Disc d;
    y += "    - " + random_shape(rng, c, size, p, d) + "\n";
    if (p.empty()) {
      m.circles.push_back(d);
    } else {
      m.polygon_boxes.push_back(polygon_box(p));
      m.polygons.push_back(std::move(p));
    }
  }
  return y;
}

// A robot of `kind`, sized by `extent` (a map's cell, or the world's shorter side); returns its YAML.
inline std::string draw_robot(core::Rng& rng, const PlanarOptions& o, RobotKind kind, double extent, PlanarModel& m) {
  RobotModel& r = m.robot;
  r.kind = kind;
  std::ostringstream y;
  if (kind == RobotKind::kPoint) y << "robot: {type: point}\n";
  if (kind == RobotKind::kDisc) {
    r.radius = extent * (o.map ? rng.uniform(o.min_disc_cells, o.max_disc_cells) : rng.uniform(0.01, 0.08));
    y << "robot: {type: disc, radius: " << num(r.radius) << "}\n";
  }
  if (kind == RobotKind::kRigid) {
    const double size = extent * (o.map ? rng.uniform(0.2, 0.8) : rng.uniform(0.02, 0.08));
    y << "robot:\n  type: rigid2d\n  shapes:\n";
    for (int i = 1 + static_cast<int>(rng.uniform_index(3)); i > 0; --i) {
      Poly p;
      Disc d;
      const Vec2 c = uniform2(rng, Vec2(-size, -size), Vec2(size, size));
      y << "    - " << random_shape(rng, c, size, p, d) << "\n";
      if (p.empty()) r.discs.push_back(d); else r.polygons.push_back(std::move(p));
    }
  }
  if (!r.chain()) return y.str();
  const bool arm = kind == RobotKind::kArm;
  const int n = 1 + static_cast<int>(rng.uniform_index(arm ? 4 : 3));
  const double reach = extent * rng.uniform(0.15, 0.45);
  y << "robot:\n  type: " << (arm ? "arm" : "linkage") << "\n  links:\n";
  for (int i = 0; i < n; ++i) {
    const double l = reach / n * rng.uniform(0.6, 1.4);
    r.links.push_back({l, l * rng.uniform(0.05, 0.5)});  // longer than wide
    y << "    - {length: " << num(l) << ", width: " << num(r.links.back().width) << "}\n";
  }
  if (arm) {
    const Vec2 base = uniform2(rng, m.bounds.lo, m.bounds.hi);
    r.base_x = base.x(), r.base_y = base.y(), r.base_th = rng.uniform(-kPi, kPi);
    y << "  base: [" << num(r.base_x) << ", " << num(r.base_y) << ", " << num(r.base_th) << "]\n";
  }
  const int joints = arm ? n : n - 1;
  if (joints > 0 && rng.uniform01() < 0.5) {
    y << "  limits: [";
    for (int i = 0; i < joints; ++i) {
      const double lo = rng.uniform(-kPi, 0.5), hi = std::min(lo + 2 * kPi, lo + rng.uniform(0.5, 2 * kPi));
      r.limits.push_back({lo, hi});
      y << (i ? ", " : "") << "[" << num(lo) << ", " << num(hi) << "]";
    }
    y << "]\n";
  }
  return y.str();
}

// One attempt at a problem; false when no start or goal with a margin was found.
inline bool draw_planar(core::Rng& rng, const PlanarOptions& o, PlanarModel& m) {
  m = PlanarModel{};
  std::string y = o.map ? draw_map(rng, o, m) : draw_obstacles(rng, m);
  const double extent = o.map ? m.cell : (m.bounds.hi - m.bounds.lo).minCoeff();
  y += draw_robot(rng, o, static_cast<RobotKind>(o.disc_only ? 1 : rng.uniform_index(o.map ? 3 : 5)), extent, m);
  if (o.plan_settings) y += o.resolution > 0.0 ? "resolution: " + num(o.resolution) + "\n" : random_plan_settings(rng);
  Placed placed;
  const double margin = 1e-3 * (m.bounds.hi - m.bounds.lo).minCoeff();
  for (State* s : {&m.start, &m.goal}) {
    bool found = false;
    for (int i = 0; i < 400 && !found; ++i) {
      *s = random_state(m.robot, m.bounds, rng);
      found = clearance(m, *s, placed) > margin;
    }
    if (!found) return false;
  }
  m.yaml = y + "start: " + state_yaml(m.start) + "\ngoal: " + state_yaml(m.goal) + "\n";
  return true;
}

// The problem of `seed`: attempts from derived seeds until one has a valid start and goal.
inline PlanarModel random_planar(std::uint64_t seed, const PlanarOptions& o) {
  PlanarModel m;
  for (std::uint64_t attempt = 0;; ++attempt) {
    core::Rng rng(core::derive_seed(seed, attempt));
    if (draw_planar(rng, o, m)) return m;
  }
}

}  // namespace amp::test
