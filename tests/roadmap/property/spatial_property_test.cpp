// Property tests of every planner on 200 random 3-D problems (issue 17): boxes, spheres and
// cylinders (turned at random) in a box, and a sphere robot (R3) or a rigid body of spheres (SE3),
// each written as a YAML file and loaded as `amp plan` loads it. The properties are the planar
// ones (planar_property_test.cpp): limits kept, solved paths from start to goal certified by the
// test's own conservative advancement, and the same result on two threads. Robots are unions of
// spheres because a sphere's distance to a box, a sphere or a cylinder is exact in a few lines, so
// the certificate needs nothing of FCL.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include "amp/world/problem.hpp"
#include "support/exact_geometry.hpp"
#include "support/planner_runs.hpp"
#include "support/random_problems.hpp"
#include "support/sanitizer_build.hpp"

namespace amp::roadmap {
namespace {

namespace fs = std::filesystem;
using Vec3 = Eigen::Vector3d;
using Quat = Eigen::Quaterniond;

constexpr std::uint64_t kMasterSeed = 0x17'0002'0003ULL;
constexpr int kCases = 200;
constexpr int kShards = 2;
constexpr long kCertifyBudget = 2'000'000;

enum class SolidKind { kBox, kSphere, kCylinder };
struct Solid {
  SolidKind kind = SolidKind::kSphere;
  Vec3 c = Vec3::Zero();
  Quat q = Quat::Identity();
  Vec3 half = Vec3::Zero();  // box: half sizes; cylinder: (radius, radius, half length)
  double r = 0.0;            // sphere
};

// Distance from p to the solid (0 inside).
double distance(const Solid& s, const Vec3& p) {
  if (s.kind == SolidKind::kSphere) return std::max(0.0, (p - s.c).norm() - s.r);
  const Vec3 l = s.q.conjugate() * (p - s.c);
  if (s.kind == SolidKind::kBox) return (l.cwiseAbs() - s.half).cwiseMax(0.0).norm();
  return std::hypot(std::max(0.0, std::hypot(l.x(), l.y()) - s.half.x()), std::max(0.0, std::abs(l.z()) - s.half.z()));
}

struct Model {
  Vec3 lo = Vec3::Zero(), hi = Vec3::Zero();
  std::vector<Solid> obstacles;
  bool rigid = false;                // SE3 body of spheres, else a sphere robot in R3
  std::vector<Vec3> centres;         // body frame
  std::vector<double> radii;
  State start, goal;
  std::string yaml;

  Quat rotation(const State& s) const { return rigid ? Quat(s[6], s[3], s[4], s[5]).normalized() : Quat::Identity(); }
  double clearance(const State& s) const {
    const Quat q = rotation(s);
    double c = test::kInf;
    for (std::size_t i = 0; i < centres.size(); ++i) {
      const Vec3 p = s.head<3>() + q * centres[i];
      c = std::min(c, std::min((p - lo).minCoeff(), (hi - p).minCoeff()) - radii[i]);  // inside the bounds
      for (const Solid& o : obstacles) c = std::min(c, distance(o, p) - radii[i]);
    }
    return c;
  }
};

std::string vec_yaml(const Vec3& v) { return test::state_yaml(v); }
std::string quat_yaml(const Quat& q) { return test::state_yaml(Eigen::Vector4d(q.x(), q.y(), q.z(), q.w())); }
// Braced lists: their elements are drawn left to right (a call's arguments in no set order).
Quat random_rotation(core::Rng& rng) {
  return Quat{rng.normal(), rng.normal(), rng.normal(), rng.normal()}.normalized();
}

bool draw(core::Rng& rng, Model& m) {
  m = Model{};
  std::ostringstream y;
  m.lo = Vec3{rng.uniform(-5, 5), rng.uniform(-5, 5), rng.uniform(-5, 5)};
  m.hi = m.lo + Vec3{rng.uniform(3, 12), rng.uniform(3, 12), rng.uniform(3, 12)};
  const double extent = (m.hi - m.lo).minCoeff();
  y << "bounds: {min: " << vec_yaml(m.lo) << ", max: " << vec_yaml(m.hi) << "}\n";
  const int n = static_cast<int>(rng.uniform_index(15));
  if (n > 0) y << "world:\n  obstacles:\n";
  for (int i = 0; i < n; ++i) {
    Solid o;
    o.c = m.lo + (m.hi - m.lo).cwiseProduct(Vec3{rng.uniform01(), rng.uniform01(), rng.uniform01()});
    const double size = extent * rng.uniform(0.05, 0.3);
    o.kind = static_cast<SolidKind>(rng.uniform_index(3));
    if (o.kind == SolidKind::kSphere) {
      o.r = size;
      y << "    - {sphere: {center: " << vec_yaml(o.c) << ", radius: " << test::num(o.r) << "}}\n";
    } else {
      o.q = random_rotation(rng);
      if (o.kind == SolidKind::kBox) {
        o.half = size * Vec3{rng.uniform(0.2, 1), rng.uniform(0.2, 1), rng.uniform(0.2, 1)};
        y << "    - {box: {center: " << vec_yaml(o.c) << ", size: " << vec_yaml(2 * o.half);
      } else {
        o.half = size * Vec3{rng.uniform(0.1, 0.6), 0, rng.uniform(0.3, 1.5)};
        o.half.y() = o.half.x();
        y << "    - {cylinder: {center: " << vec_yaml(o.c) << ", radius: " << test::num(o.half.x())
          << ", length: " << test::num(2 * o.half.z());
      }
      y << ", rotation: " << quat_yaml(o.q) << "}}\n";
    }
    m.obstacles.push_back(o);
  }
  m.rigid = rng.uniform01() < 0.6;
  if (m.rigid) {
    y << "robot:\n  type: rigid3d\n  shapes:\n";
    const int k = 1 + static_cast<int>(rng.uniform_index(4));
    for (int i = 0; i < k; ++i) {
      m.centres.push_back(extent * 0.1 * Vec3{rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)});
      m.radii.push_back(extent * rng.uniform(0.02, 0.06));
      y << "    - {sphere: {center: " << vec_yaml(m.centres.back()) << ", radius: " << test::num(m.radii.back()) << "}}\n";
    }
  } else {
    m.centres.push_back(Vec3::Zero());
    m.radii.push_back(extent * rng.uniform(0.02, 0.08));
    y << "robot: {type: sphere, radius: " << test::num(m.radii.back()) << "}\n";
  }
  y << test::random_plan_settings(rng);
  for (State* s : {&m.start, &m.goal}) {
    bool found = false;
    for (int i = 0; i < 400 && !found; ++i) {
      s->resize(m.rigid ? 7 : 3);
      s->head<3>() = m.lo + (m.hi - m.lo).cwiseProduct(Vec3{rng.uniform01(), rng.uniform01(), rng.uniform01()});
      if (m.rigid) {
        const Quat q = random_rotation(rng);
        s->tail<4>() << q.x(), q.y(), q.z(), q.w();
      }
      found = m.clearance(*s) > 1e-3 * extent;
    }
    if (!found) return false;
  }
  y << "start: " << test::state_yaml(m.start) << "\ngoal: " << test::state_yaml(m.goal) << "\n";
  m.yaml = y.str();
  return true;
}

// The state at t along a -> b: position straight, rotation by slerp along the short arc.
State interpolate(const Model& m, const State& a, const State& b, double t) {
  State s = a + t * (b - a);
  if (!m.rigid) return s;
  Quat qa = m.rotation(a), qb = m.rotation(b);
  if (qa.dot(qb) < 0.0) qb.coeffs() = -qb.coeffs();
  const double cos_th = std::min(1.0, qa.dot(qb)), th = std::acos(cos_th);
  Eigen::Vector4d q = th < 1e-9 ? Eigen::Vector4d((1 - t) * qa.coeffs() + t * qb.coeffs())
                                : Eigen::Vector4d((std::sin((1 - t) * th) * qa.coeffs() + std::sin(t * th) * qb.coeffs()) / std::sin(th));
  q.normalize();
  s.tail<4>() = q;  // Eigen's coeffs() are (x, y, z, w), the state's order
  return s;
}

// How far any robot point moves per unit of t: the translation plus the farthest centre times the
// angle turned (a sphere turning about its own centre sweeps nothing).
double motion_bound(const Model& m, const State& a, const State& b) {
  double bound = (b.head<3>() - a.head<3>()).norm();
  if (m.rigid) {
    double reach = 0.0;
    for (const Vec3& c : m.centres) reach = std::max(reach, c.norm());
    bound += reach * 2.0 * std::acos(std::min(1.0, std::abs(m.rotation(a).dot(m.rotation(b)))));
  }
  return bound;
}

double state_gap(const Model& m, const State& a, const State& b) {
  if (a.size() != b.size()) return test::kInf;
  double g = (a.head<3>() - b.head<3>()).cwiseAbs().maxCoeff();
  if (m.rigid) g = std::max(g, 1.0 - std::abs(m.rotation(a).dot(m.rotation(b))));
  return g;
}

std::string certify(const Model& m, const std::vector<State>& path) {
  const double floor = 1e-12 * (m.hi - m.lo).maxCoeff();
  long budget = kCertifyBudget;
  for (std::size_t i = 1; i < path.size(); ++i) {
    const double speed = motion_bound(m, path[i - 1], path[i]);
    for (double t = 0.0;;) {
      const double c = m.clearance(interpolate(m, path[i - 1], path[i], t));
      if (!(c > floor)) {
        return "segment " + std::to_string(i) + " of " + std::to_string(path.size() - 1) + " at t = " + test::num(t) +
               ": clearance " + test::num(c);
      }
      if (t >= 1.0) break;
      if (--budget < 0) return "not certified within " + std::to_string(kCertifyBudget) + " steps";
      t = speed > 0.0 ? std::min(1.0, t + 0.999 * c / speed) : 1.0;
    }
  }
  return "";
}

using Case = test::PlannerCase<Model>;

Case make_case(int index, const fs::path& root) {
  static const std::vector<std::string> planners = test::any_world_planners();
  Case c;
  c.index = index;
  core::Rng rng(core::derive_seed(kMasterSeed, static_cast<std::uint64_t>(index)));
  for (std::uint64_t attempt = 0;; ++attempt) {
    core::Rng draw_rng(core::derive_seed(rng.next_u64(), attempt));
    if (draw(draw_rng, c.model)) break;
  }
  c.file = root / ("case-" + std::to_string(index) + ".yaml");
  std::ofstream(c.file) << "name: case-" << index << "\n" << c.model.yaml;
  c.problem = world::load_problem(c.file);
  c.planner = planners[static_cast<std::size_t>(index) % planners.size()];
  c.draw_run(rng, 200);
  return c;
}

void expect_solved_path(const Case& c, const test::TimedRun& r) {
  const std::vector<State>& path = r.out.path;
  ASSERT_GE(path.size(), 2u) << c.describe();
  const double tol = 1e-9 * (c.model.hi - c.model.lo).maxCoeff();
  EXPECT_LE(state_gap(c.model, path.front(), c.model.start), tol) << "path does not start at the start\n" << c.describe();
  EXPECT_LE(state_gap(c.model, path.back(), c.model.goal), tol) << "path does not end at the goal\n" << c.describe();
  const std::string why = certify(c.model, path);
  EXPECT_EQ(why, "") << "solved path not certified: " << why << "\n" << c.describe();
}

class SpatialProperties : public ::testing::TestWithParam<int> {};

TEST_P(SpatialProperties, RunsKeepTheirLimitsAndSolvedPathsAreCertifiedAndThreadIndependent) {
  const int shard = GetParam(), per_shard = kCases / kShards;
  test::TempDir dir("spatial-" + std::to_string(shard));
  std::vector<Case> cases;
  for (int i = shard * per_shard; i < shard * per_shard + test::case_share(per_shard); ++i) cases.push_back(make_case(i, dir.path()));
  test::run_shard("shard " + std::to_string(shard), cases, expect_solved_path);
}

// The certificate is no rubber stamp (as the planar one): a straight line from start to goal that a
// dense sampling finds in collision is refused.
TEST(SpatialCertificate, RefusesEveryStraightLineASamplingFindsInCollision) {
  int refused = 0;
  for (int i = 0; i < 100; ++i) {
    core::Rng rng(core::derive_seed(kMasterSeed + 1, static_cast<std::uint64_t>(i)));
    Model m;
    while (!draw(rng, m)) {
    }
    bool hit = false;
    for (int k = 0; k <= 2000 && !hit; ++k) hit = m.clearance(interpolate(m, m.start, m.goal, k / 2000.0)) <= 0.0;
    const std::string why = certify(m, {m.start, m.goal});
    if (hit) {
      EXPECT_NE(why, "") << "case " << i << ": a colliding line was certified\n" << m.yaml;
    }
    refused += why.empty() ? 0 : 1;
  }
  EXPECT_GT(refused, 10);
}

INSTANTIATE_TEST_SUITE_P(Shards, SpatialProperties, ::testing::Range(0, kShards));

}  // namespace
}  // namespace amp::roadmap
