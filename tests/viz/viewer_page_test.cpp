// The 3-D viewer page (viz/viewer_page.hpp): the frames the slider steps through, the meshes'
// simplification when a page would be too large, what the page says of a path, and that the page
// is whole (every key of its template filled, three.js inlined). The browser side is checked by
// tests/viz/viewer_browser_check.py in headless Chromium; the page's data, decoded independently,
// by tests/python/test_viewer_page.py.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "amp/roadmap/path_certificate.hpp"
#include "amp/roadmap/run.hpp"
#include "amp/viz/mesh_decimation.hpp"
#include "amp/viz/viewer_page.hpp"
#include "amp/world/problem.hpp"
#include "support/source_tree.hpp"

namespace amp::viz {
namespace {

namespace fs = std::filesystem;

world::Problem bundled(const std::string& name) {
  return world::load_problem(fs::path(AMP_SOURCE_DIR) / "problems" / name);
}

// Ended by solving or by the problem's node limit, not by the clock (sanitizer builds are slow).
std::vector<State> solve(const world::Problem& p, std::uint64_t seed) {
  const roadmap::RunOutcome run = roadmap::execute_run(p, p.defaults.planner, {}, seed, 3600.0, std::nullopt);
  EXPECT_EQ(run.record.status, core::PlanStatus::kSolved);
  return run.path;
}

// A square of side 1 in the plane z = 0 cut into n x n cells of two triangles each.
world::TriangleMesh grid_sheet(int n) {
  world::TriangleMesh m;
  for (int j = 0; j <= n; ++j) {
    for (int i = 0; i <= n; ++i) m.vertices.emplace_back(double(i) / n, double(j) / n, 0.0);
  }
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      const int a = j * (n + 1) + i, b = a + 1, c = a + n + 1, d = c + 1;
      m.triangles.emplace_back(a, b, d);
      m.triangles.emplace_back(a, d, c);
    }
  }
  return m;
}

TEST(ViewerFrames, KeepEveryWaypointAndStepByLength) {
  const world::Problem p = bundled("walls.yaml");
  const State a = p.start(), b = p.goal();
  State mid;
  p.space->interpolate(a, b, 0.25, mid);  // the first leg a quarter of the whole length
  const std::vector<State> path{a, mid, b};
  const std::vector<State> frames = viewer_frames(*p.space, path, 100);
  // 25 steps on the first leg, 75 on the second, and the start: 101 frames.
  ASSERT_EQ(frames.size(), 101u);
  EXPECT_EQ(frames.front(), a);
  EXPECT_EQ(frames[25], mid);
  EXPECT_EQ(frames.back(), b);
  const double step = p.space->distance(a, b) / 100.0;
  for (std::size_t i = 0; i + 1 < frames.size(); ++i) {
    EXPECT_NEAR(p.space->distance(frames[i], frames[i + 1]), step, 1e-9 * step + 1e-12);
  }
  EXPECT_EQ(viewer_frames(*p.space, {a}, 100).size(), 1u);
  // More waypoints than frames: one frame per waypoint, none dropped.
  EXPECT_EQ(viewer_frames(*p.space, path, 1).size(), 3u);
}

TEST(MeshDecimation, ClustersOnAGridAndKeepsWinding) {
  const world::TriangleMesh sheet = grid_sheet(40);  // 3,200 triangles
  const world::TriangleMesh same = cluster_vertices(sheet, 1e-3);
  EXPECT_EQ(same.triangles.size(), sheet.triangles.size());
  // Cells of 0.1 (the 41 grid lines fall into 10-11 cells a side): about 2 x 10 x 10 triangles.
  const world::TriangleMesh coarse = cluster_vertices(sheet, 0.1);
  EXPECT_GE(coarse.triangles.size(), 150u);
  EXPECT_LE(coarse.triangles.size(), 250u);
  for (const Eigen::Vector3i& t : coarse.triangles) {  // still facing +z, as the sheet does
    const Eigen::Vector3d n = (coarse.vertices[t[1]] - coarse.vertices[t[0]]).cross(coarse.vertices[t[2]] - coarse.vertices[t[0]]);
    EXPECT_GT(n.z(), 0.0);
  }
  EXPECT_EQ(decimation_cell({&sheet}, 5000), 0.0);  // fits already
  const double cell = decimation_cell({&sheet}, 500);
  ASSERT_GT(cell, 0.0);
  EXPECT_LE(cluster_vertices(sheet, cell).triangles.size(), 500u);
  EXPECT_GT(cluster_vertices(sheet, cell / 2).triangles.size(), 500u);  // the finest grid that fits
}

TEST(ViewerPage, IsWholeAndSaysThePathIsCertified) {
  const world::Problem p = bundled("walls3d.yaml");
  const ViewerContent content = path_content(p, solve(p, 1), "prm, seed 1");
  EXPECT_TRUE(content.path_certified);
  const std::string page = viewer_page(p, content);
  EXPECT_EQ(page.find("@AMP_"), std::string::npos);
  EXPECT_NE(page.find("THREE.OrbitControls"), std::string::npos);
  EXPECT_NE(page.find("certified collision-free along its whole length"), std::string::npos);
  EXPECT_NE(page.find("<title>Walls-3D</title>"), std::string::npos);
  EXPECT_EQ(page.find("Meshes simplified"), std::string::npos);
  EXPECT_EQ(page.find("NOT certified"), std::string::npos);
}

TEST(ViewerPage, SaysWhyAPathIsNotCertified) {
  const world::Problem p = bundled("walls3d.yaml");
  // Straight from start to goal runs through the walls.
  const ViewerContent content = path_content(p, {p.start(), p.goal()}, "a straight line");
  EXPECT_FALSE(content.path_certified);
  EXPECT_EQ(content.path_failure, "segment 0 (waypoints 0 to 1) could not be certified");
  const std::string page = viewer_page(p, content);
  EXPECT_NE(page.find("This path is NOT certified collision-free: segment 0"), std::string::npos);
}

TEST(ViewerPage, SimplifiesMeshesOnlyBeyondItsBudget) {
  const world::Problem p = bundled("walls3d.yaml");  // spheres: a few thousand triangles
  ViewerContent content;
  const std::string full = viewer_page(p, content);
  EXPECT_NE(full.find("No path: the robot is shown at the start"), std::string::npos);
  content.max_bytes = full.size() - 20'000;  // the meshes must lose some of their size
  const std::string small = viewer_page(p, content);
  EXPECT_NE(small.find("Meshes simplified for display"), std::string::npos);
  EXPECT_LT(small.size(), full.size());
}

TEST(ViewerPage, TitleCannotBreakThePage) {
  const world::Problem p = bundled("walls.yaml");
  ViewerContent content;
  content.title = "</script><b>@AMP_DATA@";
  const std::string page = viewer_page(p, content);
  EXPECT_NE(page.find("&lt;/script&gt;&lt;b&gt;@AMP_DATA@"), std::string::npos);
  EXPECT_EQ(page.find("</script><b>"), std::string::npos);
}

}  // namespace
}  // namespace amp::viz
