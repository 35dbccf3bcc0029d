// A check must not allocate: this binary counts every operator new while a flag is up.
#include <gtest/gtest.h>

#include "support/counting_allocator.hpp"


#include "amp/core/rng.hpp"
#include "amp/core/se3_space.hpp"
#include "amp/world/spatial_environment.hpp"

using amp::test::g_allocations;
using amp::test::g_counting;

namespace amp::world {
namespace {

TriangleMesh box_mesh(double sx, double sy, double sz) {
  TriangleMesh m;
  for (int i = 0; i < 8; ++i) m.vertices.emplace_back(i & 1 ? sx : 0, i & 2 ? sy : 0, i & 4 ? sz : 0);
  m.triangles = {{0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}, {0, 1, 5}, {0, 5, 4},
                 {1, 3, 7}, {1, 7, 5}, {3, 2, 6}, {3, 6, 7}, {2, 0, 4}, {2, 4, 6}};
  return m;
}

// Allocations made by `n` checks (and clearance queries, if asked) after one warm-up round.
long allocations(bool meshes, bool clearance) {
  std::vector<Solid> obstacles;
  for (int i = 0; i < 20; ++i) {
    const Eigen::Isometry3d at(Eigen::Translation3d(i % 5 * 2.0 - 4.0, i / 5 * 2.0 - 4.0, 0.0));
    if (meshes) {
      obstacles.push_back(Solid::mesh_of(box_mesh(1, 0.5 + 0.1 * i, 1), at));
    } else {
      obstacles.push_back(i % 2 == 0 ? Solid::box({1, 1, 1}, at) : Solid::sphere(0.5, at.translation()));
    }
  }
  const Eigen::AlignedBox3d bounds(Eigen::Vector3d(-6, -6, -3), Eigen::Vector3d(6, 6, 3));
  auto world = std::make_shared<const SpatialWorld>(std::move(obstacles), bounds);
  std::vector<Solid> body;
  if (meshes) {
    body = {Solid::mesh_of(box_mesh(0.8, 0.3, 0.3)), Solid::mesh_of(box_mesh(0.2, 0.2, 0.6))};
  } else {
    body = {Solid::sphere(0.3, {0, 0, 0}), Solid::sphere(0.2, {0.5, 0, 0})};
  }
  const SpatialEnvironment env(world, SpatialRobot::rigid(std::move(body)));
  core::Counters counters;
  auto checker = env.make_checker(counters);
  const core::Se3Space space(bounds.min(), bounds.max(), 1.0);
  core::Rng rng(7);
  std::vector<State> states(300);
  for (State& s : states) space.sample_uniform(rng, s);
  int valid = 0;
  for (const State& s : states) valid += clearance ? checker->clearance(s).distance > 0 : checker->is_valid(s);
  EXPECT_GT(valid, 0);  // the states exercise both outcomes
  EXPECT_LT(valid, 300);

  g_allocations = 0;
  g_counting = true;
  int again = 0;
  for (const State& s : states) again += clearance ? checker->clearance(s).distance > 0 : checker->is_valid(s);
  g_counting = false;
  EXPECT_EQ(again, valid);
  return g_allocations.load();
}

// FCL's own narrow phase allocates for some pairs (primitive vs mesh: it fits the primitive's
// bounding volume per call; box vs box: a local contact vector), so the claim is checked where
// FCL does not: meshes against meshes (OMPL.app problems) and spheres against boxes and spheres.
// Our code around FCL adds no allocation.
TEST(SpatialCheckerAllocation, MeshChecksDoNotAllocate) { EXPECT_EQ(allocations(true, false), 0); }
TEST(SpatialCheckerAllocation, PrimitiveChecksDoNotAllocate) { EXPECT_EQ(allocations(false, false), 0); }
TEST(SpatialCheckerAllocation, MeshClearanceDoesNotAllocate) { EXPECT_EQ(allocations(true, true), 0); }

}  // namespace
}  // namespace amp::world
