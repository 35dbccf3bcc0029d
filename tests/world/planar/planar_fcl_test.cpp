// The planar checker against FCL as an independent reference: obstacle polygons are extruded into
// thin prisms (triangle meshes, BVHModel<OBBRSS>), circles into cylinders; the robot's rectangles
// become taller boxes and its discs taller cylinders, so every 2-D overlap (including containment
// either way) is a 3-D overlap of a convex robot piece with an obstacle.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <numbers>

#include <fcl/geometry/bvh/BVH_model.h>
#include <fcl/geometry/shape/box.h>
#include <fcl/geometry/shape/cylinder.h>
#include <fcl/narrowphase/collision.h>
#include <fcl/narrowphase/collision_object.h>

#include "amp/core/rng.hpp"
#include "amp/world/planar_checker.hpp"
#include "amp/world/polygon_geometry.hpp"

namespace amp::world {
namespace {

using V = Eigen::Vector2d;
constexpr double kPi = std::numbers::pi;
constexpr double kSize = 20.0;
// Obstacles span z in [-kObstacleHalfHeight, +], robot pieces twice as much.
constexpr double kObstacleHalfHeight = 0.5;
constexpr double kRobotHeight = 2.0;
// States whose clearance is below this are too close to touching for a fair comparison with GJK.
constexpr double kContactSlack = 1e-6;

using Mesh = fcl::BVHModel<fcl::OBBRSSd>;

// Star-shaped polygon around c (kept as the fan centre of the prism's caps).
std::shared_ptr<Mesh> prism(const V& c, const std::vector<V>& ring) {
  const int n = static_cast<int>(ring.size());
  std::vector<fcl::Vector3d> pts;
  std::vector<fcl::Triangle> tris;
  pts.emplace_back(c.x(), c.y(), kObstacleHalfHeight);
  pts.emplace_back(c.x(), c.y(), -kObstacleHalfHeight);
  for (const V& v : ring) {
    pts.emplace_back(v.x(), v.y(), kObstacleHalfHeight);
    pts.emplace_back(v.x(), v.y(), -kObstacleHalfHeight);
  }
  for (int i = 0; i < n; ++i) {
    const int j = (i + 1) % n;
    const int ti = 2 + 2 * i, bi = ti + 1, tj = 2 + 2 * j, bj = tj + 1;
    tris.emplace_back(0, ti, tj);
    tris.emplace_back(1, bj, bi);
    tris.emplace_back(ti, bi, bj);
    tris.emplace_back(ti, bj, tj);
  }
  auto mesh = std::make_shared<Mesh>();
  mesh->beginModel();
  mesh->addSubModel(pts, tris);
  mesh->endModel();
  return mesh;
}

struct Scene {
  Shapes2d shapes;
  std::vector<std::unique_ptr<fcl::CollisionObjectd>> fcl_objects;
};

Scene random_scene(core::Rng& rng) {
  Scene scene;
  while (scene.shapes.polygons.size() < 30) {
    const V c(rng.uniform(0, kSize), rng.uniform(0, kSize));
    const double r = rng.uniform(0.3, 2.5);
    const int n = 3 + static_cast<int>(rng.uniform_index(10));
    std::vector<double> angles(n);
    for (double& a : angles) a = rng.uniform(0, 2 * kPi);
    std::sort(angles.begin(), angles.end());
    std::vector<V> ring;
    for (double a : angles) ring.push_back(c + rng.uniform(0.3 * r, r) * V(std::cos(a), std::sin(a)));
    // The fan from c must stay inside: c strictly left of every edge (counter-clockwise ring).
    bool fan_ok = std::abs(signed_area(ring)) > 1e-3;
    for (int i = 0; i < n && fan_ok; ++i) fan_ok = orient2d(ring[i], ring[(i + 1) % n], c) > 1e-9;
    if (!fan_ok) continue;
    scene.fcl_objects.push_back(std::make_unique<fcl::CollisionObjectd>(prism(c, ring)));
    scene.shapes.polygons.push_back(Polygon{std::move(ring)});
  }
  for (int i = 0; i < 10; ++i) {
    const Circle c{{rng.uniform(0, kSize), rng.uniform(0, kSize)}, rng.uniform(0.1, 1.2)};
    auto cyl = std::make_shared<fcl::Cylinderd>(c.radius, 2 * kObstacleHalfHeight);
    fcl::Transform3d tf = fcl::Transform3d::Identity();
    tf.translation() << c.center.x(), c.center.y(), 0.0;
    scene.fcl_objects.push_back(std::make_unique<fcl::CollisionObjectd>(cyl, tf));
    scene.shapes.circles.push_back(c);
  }
  return scene;
}

// An axis-aligned rectangle of the robot body, as FCL sees it.
struct BodyBox {
  V center;
  V size;
};

bool fcl_collides(const Scene& scene, const std::vector<BodyBox>& boxes, const std::vector<Circle>& discs,
                  const State& s) {
  const double th = s.size() > 2 ? s[2] : 0.0;
  const Eigen::Rotation2Dd rot(th);
  std::vector<std::unique_ptr<fcl::CollisionObjectd>> pieces;
  for (const BodyBox& b : boxes) {
    const V c = V(s[0], s[1]) + rot * b.center;
    fcl::Transform3d tf = fcl::Transform3d::Identity();
    tf.linear() = fcl::AngleAxisd(th, fcl::Vector3d::UnitZ()).toRotationMatrix();
    tf.translation() << c.x(), c.y(), 0.0;
    pieces.push_back(std::make_unique<fcl::CollisionObjectd>(
        std::make_shared<fcl::Boxd>(b.size.x(), b.size.y(), kRobotHeight), tf));
  }
  for (const Circle& d : discs) {
    const V c = V(s[0], s[1]) + rot * d.center;
    fcl::Transform3d tf = fcl::Transform3d::Identity();
    tf.translation() << c.x(), c.y(), 0.0;
    pieces.push_back(
        std::make_unique<fcl::CollisionObjectd>(std::make_shared<fcl::Cylinderd>(d.radius, kRobotHeight), tf));
  }
  for (const auto& piece : pieces) {
    for (const auto& obstacle : scene.fcl_objects) {
      fcl::CollisionRequestd request;
      fcl::CollisionResultd result;
      if (fcl::collide(piece.get(), obstacle.get(), request, result) > 0) return true;
    }
  }
  return false;
}

void compare(const PlanarRobot& robot, const std::vector<BodyBox>& boxes, const std::vector<Circle>& discs,
             std::uint64_t seed) {
  core::Rng rng(seed);
  Scene scene = random_scene(rng);
  const auto world = std::make_shared<const PlanarWorld>(
      scene.shapes, Eigen::AlignedBox2d(V(-100, -100), V(100, 100)));  // bounds out of the way
  core::Counters counters;
  PlanarChecker checker(world, robot, counters);
  int compared = 0, collisions = 0, mismatches = 0;
  for (int i = 0; i < 1500; ++i) {
    State s(robot.state_dimension());
    s[0] = rng.uniform(0, kSize);
    s[1] = rng.uniform(0, kSize);
    if (s.size() > 2) s[2] = rng.uniform(-kPi, kPi);
    const bool ours = checker.is_valid(s);
    if (ours && checker.clearance(s).distance < kContactSlack) continue;
    ++compared;
    collisions += !ours;
    const bool theirs = !fcl_collides(scene, boxes, discs, s);
    if (ours != theirs) {
      ++mismatches;
      ADD_FAILURE() << "state " << s.transpose() << ": ours " << ours << ", FCL " << theirs;
    }
  }
  EXPECT_EQ(mismatches, 0);
  EXPECT_GT(compared, 1400);
  EXPECT_GT(collisions, 100);
  EXPECT_LT(collisions, compared - 100);
}

TEST(PlanarFcl, LShapedRigidRobotAgreesWithFcl) {
  // Bar [-1, 1] x [-0.15, 0.15] and foot [-1, -0.7] x [0.15, 1].
  const std::vector<BodyBox> boxes = {{{0, 0}, {2, 0.3}}, {{-0.85, 0.575}, {0.3, 0.85}}};
  Shapes2d body;
  for (const BodyBox& b : boxes) {
    const V lo = b.center - b.size / 2, hi = b.center + b.size / 2;
    body.polygons.push_back(Polygon{{lo, {hi.x(), lo.y()}, hi, {lo.x(), hi.y()}}});
  }
  compare(PlanarRobot::rigid(body), boxes, {}, 11);
}

TEST(PlanarFcl, RigidBodyWithDiscsAgreesWithFcl) {
  const std::vector<BodyBox> boxes = {{{0.5, 0}, {1.0, 0.2}}};
  const std::vector<Circle> discs = {{{-0.3, 0.2}, 0.4}};
  Shapes2d body{{Polygon{{{0, -0.1}, {1, -0.1}, {1, 0.1}, {0, 0.1}}}}, discs};
  compare(PlanarRobot::rigid(body), boxes, discs, 12);
}

TEST(PlanarFcl, DiscRobotAgreesWithFcl) {
  const std::vector<Circle> discs = {{{0, 0}, 0.6}};
  compare(PlanarRobot::translating({{}, discs}), {}, discs, 13);
}

}  // namespace
}  // namespace amp::world
