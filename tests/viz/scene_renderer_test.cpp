// render_scene lays a 3-D world's two views side by side (top and front, one scale), and a 2-D
// world's single view alone: on the two-link arm of tests/data/arm/two_link and the sealed planar
// problem of the roadmap tests.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "amp/viz/scene_renderer.hpp"
#include "amp/world/arm_problem.hpp"
#include "roadmap/test_worlds.hpp"
#include "support/source_tree.hpp"

namespace amp::viz {
namespace {

namespace fs = std::filesystem;

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

TEST(SceneRenderer, ArmDrawsTopAndFrontPanels) {
  const fs::path dir = fs::path(AMP_SOURCE_DIR) / "tests" / "data" / "arm" / "two_link";
  const world::Problem p =
      world::load_arm_problem({dir / "two_link.urdf", dir / "two_link.srdf", dir / "scene.yaml", dir / "request.yaml", {}, {}});
  const std::vector<State> path{p.start(), p.goal()};
  SceneOptions options;
  options.path = &path;
  const std::string svg = render_scene(p, options);
  EXPECT_EQ(count(svg, "class=\"front-view\""), 1u);
  EXPECT_EQ(count(svg, "front view: x right, z up"), 1u);
  EXPECT_EQ(count(svg, "top view: x right, y up"), 1u);
  // Each panel draws the path, the start and the goal.
  EXPECT_EQ(count(svg, "class=\"start-goal\""), 2u);
  EXPECT_EQ(count(svg, "class=\"path\""), 2u);
}

TEST(SceneRenderer, PlanarWorldDrawsOnePanel) {
  const world::Problem p = roadmap::test::point_problem(true);
  ASSERT_FALSE(p.environment->has_front_view());
  const std::string svg = render_scene(p, SceneOptions{});
  EXPECT_EQ(count(svg, "front-view"), 0u);
  EXPECT_EQ(count(svg, "class=\"start-goal\""), 1u);
}

}  // namespace
}  // namespace amp::viz
