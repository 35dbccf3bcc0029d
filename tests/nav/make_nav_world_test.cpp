#include "amp/nav/make_nav_world.hpp"

#include <gtest/gtest.h>

#include "amp/core/error.hpp"
#include "amp/nav/grid_nav_world.hpp"
#include "amp/nav/polygon_nav_world.hpp"
#include "support/source_tree.hpp"

namespace amp::nav {
namespace {

const std::filesystem::path kProblems = std::filesystem::path(AMP_SOURCE_DIR) / "problems";

TEST(MakeNavWorld, MapProblemGivesAGridWorldSharingTheMap) {
  const world::Problem p = world::load_problem(kProblems / "office-map.yaml");
  const auto w = make_nav_world(p);
  const auto* grid = dynamic_cast<const GridNavWorld*>(w.get());
  ASSERT_NE(grid, nullptr);
  EXPECT_EQ(&grid->grid(), p.environment->obstacle_outline().grid);  // shared, not copied
  EXPECT_EQ(w->as_map(), grid);  // the typed view methods take a map from
  EXPECT_EQ(w->as_polygons(), nullptr);
  const Eigen::Vector2d start(p.start()[0], p.start()[1]);
  EXPECT_TRUE(w->disc_free(start, p.environment->robot_radius()));
  EXPECT_GT(w->ray_cast(start, {1, 0}, 100.0), 0.0);
}

TEST(MakeNavWorld, PlanarProblemGivesAPolygonWorld) {
  const world::Problem p = world::load_problem(kProblems / "walls.yaml");
  const auto w = make_nav_world(p);
  const auto* polygons = dynamic_cast<const PolygonNavWorld*>(w.get());
  ASSERT_NE(polygons, nullptr);
  EXPECT_EQ(w->as_polygons(), polygons);
  EXPECT_EQ(w->as_map(), nullptr);
  const Eigen::AlignedBox3d b = p.environment->workspace_bounds();
  EXPECT_DOUBLE_EQ(w->bounds().min().x(), b.min().x());
  EXPECT_DOUBLE_EQ(w->bounds().max().y(), b.max().y());
}

TEST(MakeNavWorld, ThreeDWorldsAreRefusedNamingTheFile) {
  const world::Problem p = world::load_problem(kProblems / "walls3d.yaml");
  try {
    make_nav_world(p);
    FAIL() << "expected ParameterError";
  } catch (const ParameterError& e) {
    EXPECT_NE(std::string(e.what()).find("walls3d.yaml"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace amp::nav
