#include "amp/world/ompl_cfg.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <numbers>
#include <string>
#include <utility>

#include "amp/core/error.hpp"
#include "amp/world/polygon_geometry.hpp"
#include "amp/world/spatial_environment.hpp"
#include "support/source_tree.hpp"

namespace amp::world {
namespace {

namespace fs = std::filesystem;
const fs::path kProblems = fs::path(AMP_SOURCE_DIR) / "problems/ompl";

// A scratch directory per test holding hand-written .cfg and mesh files.
class OmplCfg : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::path(AMP_BINARY_DIR) / "ompl_cfg_test" / ::testing::UnitTest::GetInstance()->current_test_info()->name();
    fs::create_directories(dir_);
  }
  fs::path write(const std::string& name, const std::string& text) {
    std::ofstream(dir_ / name) << text;
    return dir_ / name;
  }
  // An OBJ prism of `polygon` (counter-clockwise, convex: fan caps) between z = 0 and z = h.
  void write_prism(const std::string& name, const std::vector<Eigen::Vector2d>& polygon, double h, double z0 = 0.0) {
    std::string obj;
    const int n = static_cast<int>(polygon.size());
    for (double z : {z0, h}) {
      for (const auto& p : polygon) obj += "v " + std::to_string(p.x()) + " " + std::to_string(p.y()) + " " + std::to_string(z) + "\n";
    }
    auto f = [&](int a, int b, int c) {
      obj += "f " + std::to_string(a + 1) + " " + std::to_string(b + 1) + " " + std::to_string(c + 1) + "\n";
    };
    for (int i = 1; i + 1 < n; ++i) {
      f(0, i + 1, i);          // bottom, facing down
      f(n, n + i, n + i + 1);  // top, facing up
    }
    for (int i = 0; i < n; ++i) {
      const int j = (i + 1) % n;
      f(i, j, n + j);
      f(i, n + j, n + i);
    }
    write(name, obj);
  }
  // A pentagonal prism from z0 to 0.5 as the world, a triangular prism 0.1 high as the robot.
  Problem pentagon_problem(double z0) {
    write_prism("pentagon.obj", pentagon, 0.5, z0);
    write_prism("robot.obj", {{0, 0}, {0.2, 0}, {0, 0.2}}, 0.1);
    return load_ompl_cfg(write("p.cfg", "[problem]\nrobot = robot.obj\nworld = pentagon.obj\nstart.x = -5\n"
                                        "start.y = -5\ngoal.x = 8\ngoal.y = 8\nvolume.min.x = -10\n"
                                        "volume.min.y = -10\nvolume.max.x = 10\nvolume.max.y = 10\n"));
  }
  const std::vector<Eigen::Vector2d> pentagon = {{0, 0}, {4, 0}, {5, 3}, {2, 5}, {-1, 3}};
  fs::path dir_;
};

TEST_F(OmplCfg, ThreeDimensionalProblemValues) {
  const Problem p = load_ompl_cfg(kProblems / "cage_window.cfg");
  EXPECT_EQ(p.name, "CageWindow");
  ASSERT_EQ(p.space->kind(), "se3");
  ASSERT_EQ(p.seeds.size(), 2u);
  // start: (2.5, 5, 5), 90 degrees about z.
  EXPECT_NEAR(p.start()[0], 2.5, 1e-12);
  EXPECT_NEAR(p.start()[2], 5.0, 1e-12);
  EXPECT_NEAR(p.start()[5], std::sin(std::numbers::pi / 4), 1e-7);
  EXPECT_NEAR(p.start()[6], std::cos(std::numbers::pi / 4), 1e-7);
  EXPECT_NEAR(p.goal()[6], 1.0, 1e-12);
  EXPECT_DOUBLE_EQ(p.defaults.time_limit_s, 20.0);
  EXPECT_EQ(p.environment->workspace_dimension(), 3);
  EXPECT_TRUE(p.environment->workspace_bounds().max().isApprox(Eigen::Vector3d(10, 10, 10)));
  // The rod (1.2 x 0.3 x 0.3 at (5, 5, 5) in its file) is re-centred on its vertex mean.
  EXPECT_NEAR(p.environment->robot_radius(), std::sqrt(0.36 + 0.0225 + 0.0225), 1e-6);  // assimp reads floats
  core::Counters counters;
  auto checker = p.environment->make_checker(counters);
  EXPECT_TRUE(checker->is_valid(p.start()));
  EXPECT_TRUE(checker->is_valid(p.goal()));
  State window = p.goal();
  window[0] = 5.0;  // through the window, lengthwise
  EXPECT_TRUE(checker->is_valid(window));
  window[2] = 7.0;  // into the wall above it
  EXPECT_FALSE(checker->is_valid(window));
}

TEST_F(OmplCfg, TwoDimensionalProblemRunsOnThePlanarChecker) {
  const Problem p = load_ompl_cfg(kProblems / "gap_planar.cfg");
  ASSERT_EQ(p.space->kind(), "se2");
  EXPECT_EQ(p.environment->workspace_dimension(), 2);
  EXPECT_EQ(p.defaults.planner, "prm");
  EXPECT_DOUBLE_EQ(p.defaults.time_limit_s, 10.0);
  EXPECT_NEAR(p.goal()[2], 1.5707963, 1e-12);
  // Four obstacle prisms placed by node matrices, as thick as the robot: both caps' triangles lie
  // in the robot's cap planes and merge into one region per box; its four sides lie on the region's
  // edges and go.
  EXPECT_EQ(p.environment->obstacle_outline().shapes.polygons.size(), 4u);
  for (const Polygon& box : p.environment->obstacle_outline().shapes.polygons) EXPECT_EQ(box.vertices.size(), 4u);
  EXPECT_EQ(p.environment->obstacle_outline().shapes.segments.size(), 0u);
  core::Counters counters;
  auto checker = p.environment->make_checker(counters);
  EXPECT_TRUE(checker->is_valid(p.start()));
  EXPECT_TRUE(checker->is_valid(p.goal()));
  State s = p.start();
  s << 0.0, 5.0, 0.0;  // on the wall
  EXPECT_FALSE(checker->is_valid(s));
  s << 0.0, 0.0, 0.0;  // in the gap (the L spans 1.2 across its long side, the gap 1.6)
  EXPECT_TRUE(checker->is_valid(s));
}

// OMPL.app checks a 2-D problem in 3-D, surface against surface, with the robot at height 0: the
// world is its surface within the robot's z slab, seen from above.
TEST_F(OmplCfg, TwoDimensionalWorldIsTheSurfaceInTheRobotsSlab) {
  const Problem p = pentagon_problem(-0.2);  // from below the robot to above it
  const Shapes2d walls = p.environment->obstacle_outline().shapes;
  // The caps lie outside the slab z 0..0.1. The vertical faces, clipped to it, lie on the sides (a
  // face's two triangles give the side and, or only, a stretch of it).
  EXPECT_EQ(walls.polygons.size(), 0u);
  ASSERT_GE(walls.segments.size(), 5u);
  ASSERT_LE(walls.segments.size(), 10u);
  const auto on_pentagon = [&](const Eigen::Vector2d& v) {
    return point_in_polygon(v, pentagon) || polygon_boundary_distance_sq(v, pentagon) < 1e-12;
  };
  for (const Segment& w : walls.segments) EXPECT_TRUE(on_pentagon(w.a) && on_pentagon(w.b));
  for (std::size_t i = 0; i < pentagon.size(); ++i) {
    const Eigen::Vector2d& a = pentagon[i];
    const Eigen::Vector2d& b = pentagon[(i + 1) % pentagon.size()];
    // The walls on this side, as stretches [t0, t1] of it, cover it whole.
    std::vector<std::pair<double, double>> stretches;
    const auto at = [&](const Eigen::Vector2d& v) { return (v - a).dot(b - a) / (b - a).squaredNorm(); };
    for (const Segment& w : walls.segments) {
      if (std::abs(orient2d(a, b, w.a)) < 1e-6 && std::abs(orient2d(a, b, w.b)) < 1e-6) {
        stretches.emplace_back(std::min(at(w.a), at(w.b)), std::max(at(w.a), at(w.b)));
      }
    }
    std::sort(stretches.begin(), stretches.end());
    double reach = 0.0;
    for (const auto& [t0, t1] : stretches) {
      if (t0 <= reach + 1e-6) reach = std::max(reach, t1);
    }
    EXPECT_GT(reach, 1.0 - 1e-6) << "side " << i;
  }
  core::Counters counters;
  auto checker = p.environment->make_checker(counters);
  State s(3);
  s << 4.5, 1.5, 0.0;  // across the side (4, 0)-(5, 3)
  EXPECT_FALSE(checker->is_valid(s));
  s << 7.0, 7.0, 0.0;  // clear of it
  EXPECT_TRUE(checker->is_valid(s));
  EXPECT_EQ(p.name, "p");
}

// A cap in the plane of the robot's bottom face (z = 0) overlaps it wherever their shadows meet: its
// fan's triangles merge into the pentagon, a region, and the sides on its edges go.
TEST_F(OmplCfg, CapInTheRobotsPlaneIsOneRegion) {
  const Problem p = pentagon_problem(0.0);
  const Shapes2d walls = p.environment->obstacle_outline().shapes;
  ASSERT_EQ(walls.polygons.size(), 1u);
  EXPECT_EQ(walls.polygons[0].vertices.size(), 5u);
  EXPECT_NEAR(signed_area(walls.polygons[0].vertices), signed_area(pentagon), 1e-5);  // assimp reads floats
  EXPECT_EQ(walls.segments.size(), 0u);
  // The robot prism's two caps (one facing down) merge into its one triangle.
  ASSERT_EQ(p.environment->robot_outline(p.start()).polygons.size(), 1u);
  EXPECT_EQ(p.environment->robot_outline(p.start()).polygons[0].vertices.size(), 3u);
  core::Counters counters;
  auto checker = p.environment->make_checker(counters);
  State s(3);
  s << 2.0, 2.0, 0.0;  // wholly inside the region
  EXPECT_FALSE(checker->is_valid(s));
  s << 7.0, 7.0, 0.0;
  EXPECT_TRUE(checker->is_valid(s));
}

TEST_F(OmplCfg, WorldAboveTheRobotIsLeftOut) {
  write_prism("robot.obj", {{0, 0}, {0.2, 0}, {0, 0.2}}, 0.1);
  // A slab of world from z = 2 to 3 over the whole volume: the robot (z 0..0.1) passes under it.
  std::string obj;
  for (double z : {2.0, 3.0}) {
    for (const auto& [x, y] : {std::pair{-9.0, -9.0}, {9.0, -9.0}, {9.0, 9.0}, {-9.0, 9.0}}) {
      obj += "v " + std::to_string(x) + " " + std::to_string(y) + " " + std::to_string(z) + "\n";
    }
  }
  obj += "f 1 3 2\nf 1 4 3\nf 5 6 7\nf 5 7 8\nf 1 2 6\nf 1 6 5\nf 2 3 7\nf 2 7 6\nf 3 4 8\nf 3 8 7\nf 4 1 5\nf 4 5 8\n";
  write("roof.obj", obj);
  const fs::path cfg = write("roof.cfg", "[problem]\nrobot = robot.obj\nworld = roof.obj\nstart.x = -5\nstart.y = -5\n"
                                         "goal.x = 8\ngoal.y = 8\nvolume.min.x = -10\nvolume.min.y = -10\n"
                                         "volume.max.x = 10\nvolume.max.y = 10\n");
  const Problem p = load_ompl_cfg(cfg);
  EXPECT_TRUE(p.environment->obstacle_outline().shapes.empty());
}

TEST_F(OmplCfg, ErrorsNameTheFileAndKey) {
  write("robot.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  auto expect_error = [&](const std::string& text, const std::string& needle) {
    const fs::path cfg = write("bad.cfg", text);
    try {
      load_ompl_cfg(cfg);
      ADD_FAILURE() << "expected FileError for " << needle;
    } catch (const FileError& e) {
      EXPECT_NE(std::string(e.what()).find("bad.cfg"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
    }
  };
  const std::string good = "robot = robot.obj\nworld = robot.obj\nstart.x = 0\nstart.y = 0\ngoal.x = 1\ngoal.y = 1\n";
  expect_error("[problem]\nthis line is wrong\n", ":2:");
  expect_error("[problem\n", "section");
  expect_error("start.x = 1\n", "outside");
  expect_error("[solver]\nplanner = prm\n", "[problem]");
  expect_error("[problem]\nworld = robot.obj\nstart.x = 0\n", "robot: missing key");
  expect_error("[problem]\n" + good + "start.theta = abc\n", "start.theta: expected a number");
  expect_error("[problem]\nrobot = nothing.obj\nworld = robot.obj\n", "robot: no such file");
  // Fuzzing found: a name longer than the OS allows made std::filesystem throw its own exception.
  expect_error("[problem]\nrobot = " + std::string(300, 'r') + ".obj\nworld = robot.obj\n", "robot: no such file");
  write("broken.stl", "garbage");
  expect_error("[problem]\nrobot = broken.stl\nworld = robot.obj\n", "robot: ");
  expect_error("[problem]\n" + good + "volume.min.x = 5\nvolume.max.x = 1\nvolume.min.y = 0\nvolume.max.y = 1\n",
               "volume.max.x");
  expect_error("[problem]\nrobot = robot.obj\nworld = robot.obj\nstart.x = 0\nstart.y = 0\ngoal.x = 1\n", "goal.y");
  EXPECT_THROW(load_ompl_cfg(dir_ / "missing.cfg"), FileError);
}

}  // namespace
}  // namespace amp::world
