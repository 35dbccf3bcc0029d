// The grid broad phase and the clearance pruning against brute force (every robot shape against
// every obstacle shape, with no grid) on random worlds and every robot kind.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <memory>
#include <numbers>

#include "amp/core/rng.hpp"
#include "amp/world/planar_checker.hpp"
#include "amp/world/polygon_geometry.hpp"

namespace amp::world {
namespace {

using V = Eigen::Vector2d;
constexpr double kPi = std::numbers::pi;
constexpr double kSize = 20.0;

// Star-shaped (so simple, usually non-convex) polygon around c.
Polygon star(core::Rng& rng, V c, double r, int n) {
  std::vector<double> angles(n);
  for (double& a : angles) a = rng.uniform(0, 2 * kPi);
  std::sort(angles.begin(), angles.end());
  Polygon p;
  for (double a : angles) p.vertices.push_back(c + rng.uniform(0.3 * r, r) * V(std::cos(a), std::sin(a)));
  return p;
}

// Obstacles keep 1 away from the arm's base (10, 10), so that the arm has free states.
Shapes2d random_obstacles(core::Rng& rng, int polygons, int circles) {
  const V base(10, 10);
  Shapes2d s;
  while (static_cast<int>(s.polygons.size()) < polygons) {
    Polygon p = star(rng, {rng.uniform(0, kSize), rng.uniform(0, kSize)}, rng.uniform(0.3, 2.5),
                     3 + static_cast<int>(rng.uniform_index(10)));
    const double area = std::abs(signed_area(p.vertices));
    const bool clear_of_base = bounding_box(p.vertices).squaredExteriorDistance(base) > 1.0;
    if (area > 1e-3 && is_simple(p.vertices) && clear_of_base) s.polygons.push_back(std::move(p));
  }
  while (static_cast<int>(s.circles.size()) < circles) {
    const Circle c{{rng.uniform(0, kSize), rng.uniform(0, kSize)}, rng.uniform(0.1, 1.0)};
    if ((c.center - base).norm() > c.radius + 1.0) s.circles.push_back(c);
  }
  return s;
}

std::vector<Shapes2d> placed_links(const PlanarRobot& r, const State& s) {
  std::vector<Pose2> poses(r.link_count());
  r.link_poses(s, poses.data());
  std::vector<Shapes2d> out;
  for (int i = 0; i < r.link_count(); ++i) out.push_back(transform_shapes(r.links()[i], poses[i]));
  return out;
}

// Every pair, with only a bounding-box pre-test (no grid).
bool shapes_overlap(const Shapes2d& a, const Shapes2d& b) {
  for (const Polygon& p : a.polygons) {
    const Eigen::AlignedBox2d pb = bounding_box(p.vertices);
    for (const Polygon& q : b.polygons) {
      if (pb.intersects(bounding_box(q.vertices)) && polygons_overlap(p.vertices, q.vertices)) return true;
    }
    for (const Circle& c : b.circles) {
      if (polygon_circle_overlap(p.vertices, c.center, c.radius)) return true;
    }
  }
  for (const Circle& c : a.circles) {
    for (const Polygon& q : b.polygons) {
      if (polygon_circle_overlap(q.vertices, c.center, c.radius)) return true;
    }
    for (const Circle& d : b.circles) {
      if ((c.center - d.center).norm() <= c.radius + d.radius) return true;
    }
  }
  return false;
}

bool brute_valid(const PlanarWorld& w, const PlanarRobot& r, const State& s) {
  const std::vector<Shapes2d> links = placed_links(r, s);
  for (const Shapes2d& l : links) {
    for (const Polygon& p : l.polygons) {
      for (const V& v : p.vertices) {
        if (!w.bounds().contains(v)) return false;
      }
    }
    for (const Circle& c : l.circles) {
      const V rr = V::Constant(c.radius);
      if (!w.bounds().contains(c.center - rr) || !w.bounds().contains(c.center + rr)) return false;
    }
    if (shapes_overlap(l, w.obstacles())) return false;
  }
  if (r.has_self_collision()) {
    for (std::size_t i = 0; i < links.size(); ++i) {
      for (std::size_t j = i + 2; j < links.size(); ++j) {
        if (shapes_overlap(links[i], links[j])) return false;
      }
    }
  }
  return true;
}

// Brute-force distance between disjoint shape sets.
double brute_distance(const Shapes2d& a, const Shapes2d& b) {
  double best = std::numeric_limits<double>::infinity();
  for (const Polygon& p : a.polygons) {
    const auto& v = p.vertices;
    for (std::size_t i = 0; i < v.size(); ++i) {
      const V& p0 = v[i];
      const V& p1 = v[(i + 1) % v.size()];
      for (const Polygon& q : b.polygons) {
        const auto& u = q.vertices;
        for (std::size_t k = 0; k < u.size(); ++k) {
          best = std::min(best, std::sqrt(segment_segment_distance_sq(p0, p1, u[k], u[(k + 1) % u.size()])));
        }
      }
      for (const Circle& c : b.circles) best = std::min(best, std::sqrt(point_segment_distance_sq(c.center, p0, p1)) - c.radius);
    }
  }
  for (const Circle& c : a.circles) {
    for (const Polygon& q : b.polygons) {
      const auto& u = q.vertices;
      for (std::size_t k = 0; k < u.size(); ++k) {
        best = std::min(best, std::sqrt(point_segment_distance_sq(c.center, u[k], u[(k + 1) % u.size()])) - c.radius);
      }
    }
    for (const Circle& d : b.circles) best = std::min(best, (c.center - d.center).norm() - c.radius - d.radius);
  }
  return best;
}

struct NamedRobot {
  const char* name;
  PlanarRobot robot;
};

std::vector<NamedRobot> robots() {
  const Polygon bar{{{-1, -0.15}, {1, -0.15}, {1, 0.15}, {-1, 0.15}}};
  const Polygon foot{{{-1, 0.15}, {-0.7, 0.15}, {-0.7, 1}, {-1, 1}}};
  const Polygon hook{{{0, 0}, {1.2, 0}, {1.2, 0.8}, {0.9, 0.8}, {0.9, 0.3}, {0.3, 0.3}, {0.3, 0.8}, {0, 0.8}}};
  return {{"L", PlanarRobot::rigid({{bar, foot}, {}})},
          {"hook+disc", PlanarRobot::rigid({{hook}, {Circle{{-0.4, 0}, 0.3}}})},
          {"disc", PlanarRobot::translating({{}, {Circle{{0, 0}, 0.4}}})},
          {"point", PlanarRobot::translating({{}, {Circle{{0, 0}, 0.0}}})},
          {"arm", PlanarRobot::fixed_arm({10, 10, 0}, {{3, 0.3}, {2.5, 0.3}, {2, 0.2}, {1.5, 0.2}})},
          {"linkage", PlanarRobot::free_linkage({{1.5, 0.3}, {1.2, 0.3}, {1.0, 0.2}, {0.8, 0.2}})}};
}

State random_state(core::Rng& rng, const PlanarRobot& r) {
  State s(r.state_dimension());
  int i = 0;
  if (r.kind() != PlanarRobot::Kind::kFixedArm) {
    s[i++] = rng.uniform(-1, kSize + 1);
    s[i++] = rng.uniform(-1, kSize + 1);
  }
  for (; i < s.size(); ++i) s[i] = rng.uniform(-kPi, kPi);
  return s;
}

TEST(PlanarBruteForce, GridCheckerEqualsBruteForceOnRandomWorlds) {
  core::Rng rng(2024);
  const Eigen::AlignedBox2d bounds(V(0, 0), V(kSize, kSize));
  for (int world_index = 0; world_index < 5; ++world_index) {
    const auto world = std::make_shared<const PlanarWorld>(
        random_obstacles(rng, 5 + 15 * world_index, 2 + 4 * world_index), bounds);
    for (const NamedRobot& nr : robots()) {
      core::Counters counters;
      PlanarChecker checker(world, nr.robot, counters);
      int mismatches = 0, invalid = 0;
      constexpr int kStates = 300;
      for (int i = 0; i < kStates; ++i) {
        const State s = random_state(rng, nr.robot);
        const bool expected = brute_valid(*world, nr.robot, s);
        mismatches += checker.is_valid(s) != expected;
        invalid += !expected;
      }
      EXPECT_EQ(mismatches, 0) << nr.name << " in world " << world_index;
      EXPECT_EQ(counters.cd_calls(), static_cast<std::uint64_t>(kStates));
      // Both answers occur, so the comparison means something.
      if (world_index > 1) {
        EXPECT_GT(invalid, 0) << nr.name;
      }
      EXPECT_LT(invalid, kStates) << nr.name << " in world " << world_index;
    }
  }
}

TEST(PlanarBruteForce, ClearanceEqualsBruteForceDistance) {
  core::Rng rng(99);
  const Eigen::AlignedBox2d bounds(V(0, 0), V(kSize, kSize));
  const auto world = std::make_shared<const PlanarWorld>(random_obstacles(rng, 25, 8), bounds);
  for (const NamedRobot& nr : robots()) {
    core::Counters counters;
    PlanarChecker checker(world, nr.robot, counters);
    int checked = 0;
    for (int i = 0; i < 150; ++i) {
      const State s = random_state(rng, nr.robot);
      const Clearance c = checker.clearance(s);
      if (!brute_valid(*world, nr.robot, s)) {
        EXPECT_EQ(c.distance, 0.0);
        continue;
      }
      ++checked;
      const double expected = brute_distance(nr.robot.outline(s), world->obstacles());
      ASSERT_NEAR(c.distance, expected, 1e-9) << nr.name;
      EXPECT_NEAR((c.robot_point - c.obstacle_point).norm(), expected, 1e-9) << nr.name;
      EXPECT_EQ(c.robot_point.z(), 0.0);
    }
    EXPECT_GT(checked, 10) << nr.name;
    EXPECT_EQ(counters.cd_calls(), 0u);
  }
}

}  // namespace
}  // namespace amp::world
