// The two views `amp render` draws of an arm problem (WorldDrawing: top (x, y) and front (x, z)),
// on the two-link arm of tests/data/arm/two_link, against extents worked out by hand from its files.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <limits>
#include <numbers>
#include <string>

#include "amp/world/arm_problem.hpp"
#include "support/state_of.hpp"
#include "support/source_tree.hpp"

namespace amp::world {
namespace {

namespace fs = std::filesystem;
using test::st;

constexpr double kPi = std::numbers::pi;
constexpr double kTol = 1e-9;

ArmFiles files() {
  const fs::path dir = fs::path(AMP_SOURCE_DIR) / "tests" / "data" / "arm" / "two_link";
  return {dir / "two_link.urdf", dir / "two_link.srdf", dir / "scene.yaml", dir / "request.yaml", {}, {}};
}

// The bounding box of every polygon vertex and circle of `shapes`.
Eigen::AlignedBox2d extent(const Shapes2d& shapes) {
  Eigen::AlignedBox2d box;
  for (const Polygon& p : shapes.polygons) {
    for (const Eigen::Vector2d& v : p.vertices) box.extend(v);
  }
  for (const Circle& c : shapes.circles) {
    box.extend(c.center - Eigen::Vector2d::Constant(c.radius));
    box.extend(c.center + Eigen::Vector2d::Constant(c.radius));
  }
  return box;
}

void expect_box(const Eigen::AlignedBox2d& got, double x0, double y0, double x1, double y1, const std::string& what) {
  EXPECT_NEAR(got.min().x(), x0, kTol) << what;
  EXPECT_NEAR(got.min().y(), y0, kTol) << what;
  EXPECT_NEAR(got.max().x(), x1, kTol) << what;
  EXPECT_NEAR(got.max().y(), y1, kTol) << what;
}

// The box obstacle spans x in [0.95, 1.05], y in [-0.05, 0.05], z in [0.1, 0.2] (scene.yaml).
TEST(ArmViews, ObstacleSeenFromAboveAndFromTheFront) {
  const Problem p = load_arm_problem(files());
  ASSERT_TRUE(p.environment->has_front_view());
  expect_box(extent(p.environment->obstacle_outline().shapes), 0.95, -0.05, 1.05, 0.05, "top");
  expect_box(extent(p.environment->obstacle_front_outline().shapes), 0.95, 0.1, 1.05, 0.2, "front");
}

// At joint values (0, 0, 0) the arm lies along x: the base block x, y in [-0.1, 0.1], z in [0, 0.1];
// link1 up to x = 0.5 at z in [0.1, 0.2]; the tool sphere (radius 0.03) at x = 1.1, z = 0.15. So the
// front view spans x in [-0.1, 1.13], z in [0, 0.2], and the top view y in [-0.1, 0.1].
// Turned a quarter by the shoulder, the arm lies along y: the front view narrows to the base's
// x in [-0.1, 0.1], while its heights stay.
TEST(ArmViews, RobotSeenFromTheFrontByHand) {
  const Problem p = load_arm_problem(files());
  const Environment& env = *p.environment;
  expect_box(extent(env.robot_front_outline(st({0, 0, 0}))), -0.1, 0.0, 1.13, 0.2, "front, straight");
  expect_box(extent(env.robot_outline(st({0, 0, 0}))), -0.1, -0.1, 1.13, 0.1, "top, straight");
  expect_box(extent(env.robot_front_outline(st({kPi / 2, 0, 0}))), -0.1, 0.0, 0.1, 0.2, "front, turned");
  expect_box(extent(env.robot_outline(st({kPi / 2, 0, 0}))), -0.1, -0.1, 0.1, 1.13, "top, turned");
}

}  // namespace
}  // namespace amp::world
