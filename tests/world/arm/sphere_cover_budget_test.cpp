// A link of many large triangles is cut into a bounded number of pieces (sphere_pieces.hpp's
// budget): generation ends in a bounded time and the spheres still cover every triangle, proven as
// sphere_cover_test.cpp does (a triangle whose corners lie in one sphere is inside it, else its four
// midpoint parts are checked).
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <vector>

#include "amp/core/rng.hpp"
#include "amp/world/arm_spheres.hpp"

namespace amp::world {
namespace {

using Vec = Eigen::Vector3d;

bool in_one(const std::vector<LinkSphere>& spheres, const Vec& a, const Vec& b, const Vec& c) {
  for (const LinkSphere& s : spheres) {
    const double r2 = s.radius * s.radius;
    if ((a - s.center).squaredNorm() <= r2 && (b - s.center).squaredNorm() <= r2 && (c - s.center).squaredNorm() <= r2) return true;
  }
  return false;
}

bool covered(const std::vector<LinkSphere>& spheres, const Vec& a, const Vec& b, const Vec& c, int depth) {
  if (in_one(spheres, a, b, c)) return true;
  if (depth == 0) return false;
  const Vec ab = 0.5 * (a + b), bc = 0.5 * (b + c), ca = 0.5 * (c + a);
  return covered(spheres, a, ab, ca, depth - 1) && covered(spheres, ab, b, bc, depth - 1) &&
         covered(spheres, ca, bc, c, depth - 1) && covered(spheres, ab, bc, ca, depth - 1);
}

// 600 triangles of about 1.5 m in a 2 m box: 600 x 4^8 (39 million) pieces at 1 cm without the budget.
ArmModel big_mesh_arm() {
  auto mesh = std::make_shared<TriangleMesh>();
  core::Rng rng(4);
  for (int t = 0; t < 600; ++t) {
    for (int k = 0; k < 3; ++k) mesh->vertices.emplace_back(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(0, 2));
    mesh->triangles.emplace_back(3 * t, 3 * t + 1, 3 * t + 2);
  }
  std::vector<ArmLink> links(2);
  links[0] = {"base", -1, {0}, {Solid::mesh_of(*mesh)}};
  links[1] = {"tip", 0, {}, {}};
  std::vector<ArmJoint> joints(1);
  joints[0] = {"j0", ArmJointType::kFixed, 0, 1};
  return ArmModel("big", std::move(links), std::move(joints));
}

TEST(SphereCoverBudget, ManyLargeTrianglesStillCovered) {
  const ArmModel model = big_mesh_arm();
  const SphereCover cover = cover_with_spheres(model);
  ASSERT_FALSE(cover.spheres.empty());
  EXPECT_LE(cover.spheres.size(), 16u);
  const Solid& solid = model.link(0).collision.front();
  int uncovered = 0;
  for (const Eigen::Vector3i& t : solid.mesh->triangles) {
    const Vec a = solid.pose * solid.mesh->vertices[static_cast<std::size_t>(t[0])];
    const Vec b = solid.pose * solid.mesh->vertices[static_cast<std::size_t>(t[1])];
    const Vec c = solid.pose * solid.mesh->vertices[static_cast<std::size_t>(t[2])];
    uncovered += covered(cover.spheres, a, b, c, 12) ? 0 : 1;
  }
  EXPECT_EQ(uncovered, 0);
}

}  // namespace
}  // namespace amp::world
