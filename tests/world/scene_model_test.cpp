// The 3-D viewer's scene model (amp/world/scene_model.hpp) and its tessellation helpers
// (amp/world/solid_mesh.hpp): meshes closed and outward, volumes and areas against formulas worked
// out here, and every environment's link poses against the robot's own kinematics.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "amp/world/arm_environment.hpp"
#include "amp/world/grid_environment.hpp"
#include "amp/world/planar_environment.hpp"
#include "amp/world/problem.hpp"
#include "amp/world/solid_mesh.hpp"
#include "amp/world/spatial_environment.hpp"
#include "roadmap/test_worlds.hpp"
#include "support/state_of.hpp"
#include "support/source_tree.hpp"

namespace amp::world {
namespace {

namespace fs = std::filesystem;
using test::st;

constexpr double kPi = std::numbers::pi;
constexpr double kTol = 1e-9;

Problem problem(const char* name) { return load_problem(fs::path(AMP_SOURCE_DIR) / "problems" / name); }

// Divergence theorem: the signed volume enclosed (positive when the triangles face outward).
double volume(const TriangleMesh& m) {
  double six = 0.0;
  for (const Eigen::Vector3i& t : m.triangles) {
    six += m.vertices[t[0]].dot(m.vertices[t[1]].cross(m.vertices[t[2]]));
  }
  return six / 6.0;
}

// Closed and consistently wound: every directed edge once, and its reverse once.
bool closed_and_consistent(const TriangleMesh& m) {
  std::map<std::pair<int, int>, int> edges;
  for (const Eigen::Vector3i& t : m.triangles) {
    for (int k = 0; k < 3; ++k) ++edges[{t[k], t[(k + 1) % 3]}];
  }
  for (const auto& [e, n] : edges) {
    const auto back = edges.find({e.second, e.first});
    if (n != 1 || back == edges.end() || back->second != 1) return false;
  }
  return !m.triangles.empty();
}

// Area of the triangles whose normal points up (the top cap of an extrusion).
double top_area(const TriangleMesh& m) {
  double area = 0.0;
  for (const Eigen::Vector3i& t : m.triangles) {
    const Eigen::Vector3d& a = m.vertices[t[0]];
    const Eigen::Vector3d n = (m.vertices[t[1]] - a).cross(m.vertices[t[2]] - a);
    if (n.z() > 0.0) area += 0.5 * n.z();
  }
  return area;
}

double shoelace(const std::vector<Eigen::Vector2d>& v) {
  double twice = 0.0;
  for (std::size_t i = 0; i < v.size(); ++i) {
    const Eigen::Vector2d& a = v[i];
    const Eigen::Vector2d& b = v[(i + 1) % v.size()];
    twice += a.x() * b.y() - b.x() * a.y();
  }
  return std::abs(0.5 * twice);
}

void expect_box_near(const Eigen::AlignedBox3d& a, const Eigen::AlignedBox3d& b, double tol) {
  EXPECT_TRUE((a.min() - b.min()).norm() < tol) << a.min().transpose() << " vs " << b.min().transpose();
  EXPECT_TRUE((a.max() - b.max()).norm() < tol) << a.max().transpose() << " vs " << b.max().transpose();
}

// Every obstacle mesh of a flat world lies within the scene's bounds.
void expect_obstacles_inside(const SceneModel& m) {
  Eigen::AlignedBox3d grown = m.bounds;
  grown.extend((m.bounds.min().array() - kTol).matrix()).extend((m.bounds.max().array() + kTol).matrix());
  for (const TriangleMesh& o : m.obstacles) EXPECT_TRUE(grown.contains(mesh_bounds(o)));
}

// A 3-D world's obstacles are its solids, one mesh each, with the solids' bounds (to within the
// tessellation: a turned cylinder's polygon falls short of its circle by under 1 %).
void expect_solids_meshed(const SceneModel& m, const std::vector<Solid>& solids) {
  ASSERT_EQ(m.obstacles.size(), solids.size());
  for (std::size_t i = 0; i < solids.size(); ++i) {
    const Eigen::AlignedBox3d exact = solids[i].bounds(), tess = mesh_bounds(m.obstacles[i]);
    Eigen::AlignedBox3d grown = exact;
    grown.extend((exact.min().array() - kTol).matrix()).extend((exact.max().array() + kTol).matrix());
    EXPECT_TRUE(grown.contains(tess)) << "obstacle " << i;
    expect_box_near(tess, exact, 0.01 * exact.sizes().maxCoeff());
  }
}

Eigen::Isometry3d turned(double angle, const Eigen::Vector3d& axis, const Eigen::Vector3d& at) {
  Eigen::Isometry3d p = Eigen::Isometry3d::Identity();
  p.linear() = Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix();
  p.translation() = at;
  return p;
}

TEST(SolidMesh, BoxIsExactClosedAndOutward) {
  const Solid box = Solid::box({1.0, 2.0, 3.0}, turned(0.7, {1, 2, 3}, {0.5, -1.0, 2.0}));
  const TriangleMesh m = solid_mesh(box);
  EXPECT_EQ(m.vertices.size(), 8u);
  EXPECT_EQ(m.triangles.size(), 12u);
  EXPECT_TRUE(closed_and_consistent(m));
  EXPECT_NEAR(volume(m), 6.0, kTol);
  expect_box_near(mesh_bounds(m), box.bounds(), kTol);
}

TEST(SolidMesh, CylinderIsTheInscribedPrism) {
  const double r = 0.5, l = 2.0;
  const Solid upright = Solid::cylinder(r, l, turned(0.0, {0, 0, 1}, {1.0, 2.0, 3.0}));
  const TriangleMesh m = solid_mesh(upright);
  EXPECT_TRUE(closed_and_consistent(m));
  const int n = kRoundSides;
  EXPECT_NEAR(volume(m), 0.5 * n * r * r * std::sin(2.0 * kPi / n) * l, kTol);  // n triangles of the fan
  EXPECT_NEAR(volume(m), kPi * r * r * l, 0.012 * kPi * r * r * l);
  expect_box_near(mesh_bounds(m), upright.bounds(), kTol);  // axis extremes are vertices
  const Solid tilted = Solid::cylinder(r, l, turned(0.4, {1, 1, 0}, {0, 0, 0}));
  const Eigen::AlignedBox3d exact = tilted.bounds(), tess = mesh_bounds(solid_mesh(tilted));
  EXPECT_TRUE(exact.contains(tess));
  expect_box_near(tess, exact, r * (1.0 - std::cos(kPi / n)) + kTol);
}

TEST(SolidMesh, SphereIsCloseToRound) {
  const Solid ball = Solid::sphere(1.5, {1.0, -2.0, 0.5});
  const TriangleMesh m = solid_mesh(ball);
  EXPECT_EQ(m.triangles.size(), static_cast<std::size_t>(2 * kSphereSlices * (kSphereStacks - 1)));
  EXPECT_TRUE(closed_and_consistent(m));
  const double exact = 4.0 / 3.0 * kPi * std::pow(1.5, 3);
  EXPECT_LT(volume(m), exact);  // inscribed
  EXPECT_GT(volume(m), 0.95 * exact);
  expect_box_near(mesh_bounds(m), ball.bounds(), kTol);
  for (const Eigen::Vector3d& v : m.vertices) EXPECT_NEAR((v - ball.pose.translation()).norm(), 1.5, kTol);
}

TEST(SolidMesh, AppendShiftsIndices) {
  TriangleMesh both = solid_mesh(Solid::box({1, 1, 1}));
  append_mesh(both, solid_mesh(Solid::box({2, 2, 2}, turned(0.0, {0, 0, 1}, {5, 0, 0}))));
  EXPECT_EQ(both.vertices.size(), 16u);
  EXPECT_TRUE(closed_and_consistent(both));
  EXPECT_NEAR(volume(both), 1.0 + 8.0, kTol);
}

// Non-convex polygons, both orientations: caps cover exactly the polygon, walls close the prism.
TEST(ExtrudeShapes, NonConvexPolygonsKeepTheirArea) {
  const std::vector<Eigen::Vector2d> l_shape{{0, 0}, {4, 0}, {4, 1}, {1, 1}, {1, 3}, {0, 3}};  // ccw, area 6
  std::vector<Eigen::Vector2d> u_shape{{0, 0}, {0, 3}, {1, 3}, {1, 1}, {2, 1}, {2, 3}, {3, 3}, {3, 0}};  // cw
  // A comb with a reflex vertex between every tooth: ear clipping's hard case.
  const std::vector<Eigen::Vector2d> comb{{0, 0}, {5, 0}, {5, 2}, {4.5, 0.5}, {4, 2}, {3.5, 0.5}, {3, 2},
                                          {2.5, 0.5}, {2, 2}, {1.5, 0.5}, {1, 2}, {0.5, 0.5}, {0, 2}};
  for (const auto& ring : {l_shape, u_shape, comb}) {
    const TriangleMesh m = extrude_shapes({{Polygon{ring}}, {}}, 0.5, 2.5, 0.1);
    EXPECT_TRUE(closed_and_consistent(m));
    EXPECT_NEAR(top_area(m), shoelace(ring), kTol);
    EXPECT_NEAR(volume(m), 2.0 * shoelace(ring), kTol);
    EXPECT_EQ(m.triangles.size(), 2 * (ring.size() - 2) + 2 * ring.size());  // caps + walls
    EXPECT_NEAR(mesh_bounds(m).min().z(), 0.5, kTol);
    EXPECT_NEAR(mesh_bounds(m).max().z(), 2.5, kTol);
  }
  EXPECT_NEAR(shoelace(l_shape), 6.0, kTol);  // the formula itself, by hand
  EXPECT_NEAR(shoelace(u_shape), 7.0, kTol);
}

// Not a valid shape (validate_shapes refuses it), yet no reason to fail drawing: CGAL adds the
// crossing, and the caps cover both lobes with valid indices.
TEST(ExtrudeShapes, ASelfCrossingPolygonStillCoversItsLobes) {
  const std::vector<Eigen::Vector2d> bowtie{{0, 0}, {2, 2}, {2, 0}, {0, 2}};  // lobes of area 1 each
  const TriangleMesh m = extrude_shapes({{Polygon{bowtie}}, {}}, 0.0, 1.0, 0.1);
  for (const Eigen::Vector3i& t : m.triangles) {
    EXPECT_TRUE((t.array() >= 0).all() && (t.array() < static_cast<int>(m.vertices.size())).all());
  }
  EXPECT_NEAR(top_area(m), 2.0, kTol);
}

TEST(ExtrudeShapes, CirclesAndSegments) {
  const Circle c{{2.0, 1.0}, 0.5};
  const TriangleMesh disc = extrude_shapes({{}, {c}}, 0.0, 1.0, 0.1);
  EXPECT_TRUE(closed_and_consistent(disc));
  EXPECT_NEAR(volume(disc), 0.5 * kRoundSides * 0.25 * std::sin(2.0 * kPi / kRoundSides), kTol);
  expect_box_near(mesh_bounds(disc), {Eigen::Vector3d(1.5, 0.5, 0.0), Eigen::Vector3d(2.5, 1.5, 1.0)}, kTol);

  const Segment wall{{0.0, 0.0}, {3.0, 4.0}};  // length 5
  const TriangleMesh w = extrude_shapes({{}, {}, {wall}}, 0.0, 2.0, 0.1);
  EXPECT_TRUE(closed_and_consistent(w));
  EXPECT_NEAR(volume(w), 5.0 * 0.1 * 2.0, kTol);
  const Eigen::Vector2d across(-0.8, 0.6);  // unit normal of the segment
  for (const Eigen::Vector3d& v : w.vertices) EXPECT_NEAR(std::abs(across.dot(v.head<2>())), 0.05, kTol);

  const TriangleMesh point = extrude_shapes({{}, {Circle{{1.0, 1.0}, 0.0}}}, 0.0, 1.0, 0.1);
  EXPECT_NEAR(mesh_bounds(point).sizes().x(), 0.1, kTol);  // a point gets the wall thickness
}

void expect_pose(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b) {
  EXPECT_TRUE(a.isApprox(b, 1e-9)) << a.matrix() << "\nvs\n" << b.matrix();
}

TEST(SceneModel, PlanarRigidBodyFollowsItsState) {
  const Problem p = problem("hook.yaml");  // a non-convex body of three rectangles
  const auto& env = dynamic_cast<const PlanarEnvironment&>(*p.environment);
  const SceneModel m = env.scene_model();
  ASSERT_EQ(m.link_names, std::vector<std::string>{"body"});
  EXPECT_TRUE(m.flat);
  EXPECT_NEAR(m.bounds.max().z(), 0.08 * 100.0, kTol);
  expect_obstacles_inside(m);
  const Shapes2d& shapes = env.world().obstacles();
  EXPECT_EQ(m.obstacles.size(), shapes.polygons.size() + shapes.circles.size());  // no segments here
  std::vector<Eigen::Isometry3d> poses;
  for (const State& s : {p.start(), p.goal()}) {
    env.robot_link_poses(s, poses);
    ASSERT_EQ(poses.size(), 1u);
    expect_pose(poses[0], turned(s[2], {0, 0, 1}, {s[0], s[1], 0.0}));
  }
}

// Posed link meshes seen from above lie on the robot's outline (arm links are rectangles: exact).
TEST(SceneModel, PlanarLinkageMatchesItsOutline) {
  const Problem p = problem("linkage.yaml");
  const auto& env = dynamic_cast<const PlanarEnvironment&>(*p.environment);
  const SceneModel m = env.scene_model();
  ASSERT_EQ(m.robot_links.size(), 4u);
  EXPECT_EQ(m.link_names.back(), "link 3");
  expect_obstacles_inside(m);
  std::vector<Eigen::Isometry3d> poses;
  for (const State& s : {p.start(), p.goal()}) {
    env.robot_link_poses(s, poses);
    const Shapes2d outline = env.robot_outline(s);
    ASSERT_EQ(outline.polygons.size(), 4u);
    for (std::size_t l = 0; l < 4; ++l) {
      Eigen::AlignedBox2d drawn, meshed;
      for (const Eigen::Vector2d& v : outline.polygons[l].vertices) drawn.extend(v);
      for (const Eigen::Vector3d& v : m.robot_links[l].vertices) meshed.extend((poses[l] * v).head<2>());
      EXPECT_TRUE(drawn.isApprox(meshed, 1e-9)) << "link " << l;
    }
  }
}

TEST(SceneModel, RigidBodyInSpaceIsPlacedByItsState) {
  const Problem p = problem("puzzle.yaml");
  const auto& env = dynamic_cast<const SpatialEnvironment&>(*p.environment);
  const SceneModel m = env.scene_model();
  ASSERT_EQ(m.link_names, std::vector<std::string>{"body"});
  EXPECT_FALSE(m.flat);
  EXPECT_TRUE(m.bounds.isApprox(env.workspace_bounds()));
  expect_solids_meshed(m, env.world().obstacles());
  std::vector<Eigen::Isometry3d> poses;
  for (const State& s : p.seeds) {
    env.robot_link_poses(s, poses);
    ASSERT_EQ(poses.size(), 1u);
    EXPECT_TRUE(poses[0].translation().isApprox(Eigen::Vector3d(s[0], s[1], s[2]), 1e-12));
    EXPECT_TRUE(poses[0].translation().isApprox(env.reference_point(s), 1e-12));
    const Eigen::Quaterniond q(s[6], s[3], s[4], s[5]);
    EXPECT_TRUE(poses[0].linear().isApprox(q.normalized().toRotationMatrix(), 1e-9));
  }
}

// The tool tip (ScaraParams::tip, in the tool link's frame) lands on the reference point.
TEST(SceneModel, ScaraLinksCarryTheTool) {
  const Problem p = problem("scara-wicket.yaml");
  const auto& env = dynamic_cast<const SpatialEnvironment&>(*p.environment);
  const SceneModel m = env.scene_model();
  EXPECT_EQ(m.link_names, (std::vector<std::string>{"column", "upper arm", "forearm", "wrist", "tool"}));
  expect_solids_meshed(m, env.world().obstacles());  // the large cylinder rises above the bounds
  std::vector<Eigen::Isometry3d> poses;
  for (const State& s : p.seeds) {
    env.robot_link_poses(s, poses);
    ASSERT_EQ(poses.size(), 5u);
    EXPECT_TRUE((poses[4] * env.robot().scara_params().tip).isApprox(env.reference_point(s), 1e-9));
    const Eigen::AlignedBox3d column = mesh_bounds(m.robot_links[0]);
    EXPECT_NEAR(column.sizes().z(), env.robot().scara_params().column_height, kTol);
  }
}

TEST(SceneModel, ArmPosesEveryModelLink) {
  const Problem p = problem("panda-box.yaml");
  const auto& env = dynamic_cast<const ArmEnvironment&>(*p.environment);
  const SceneModel m = env.scene_model();
  const auto& links = env.robot().model().links();
  ASSERT_EQ(m.link_names.size(), links.size());
  for (std::size_t l = 0; l < links.size(); ++l) {
    EXPECT_EQ(m.link_names[l], links[l].name);
    EXPECT_EQ(m.robot_links[l].triangles.empty(), links[l].collision.empty()) << links[l].name;
  }
  EXPECT_TRUE(m.bounds.isApprox(env.workspace_bounds()));
  expect_solids_meshed(m, env.scene().obstacles());
  std::vector<Eigen::Isometry3d> poses, kinematics(links.size());
  const int tip = env.robot().kinematics().group().tip_link;
  for (const State& s : {p.start(), p.goal()}) {
    env.robot_link_poses(s, poses);
    env.robot().kinematics().link_poses(s, kinematics.data());
    ASSERT_EQ(poses.size(), links.size());
    expect_pose(poses.back(), kinematics.back());
    EXPECT_TRUE(poses[static_cast<std::size_t>(tip)].translation().isApprox(env.reference_point(s), 1e-9));
  }
}

// The boxes of a map's one obstacle mesh: solid_mesh makes a box of 8 vertices.
std::vector<Eigen::AlignedBox2d> boxes_of(const TriangleMesh& walls) {
  std::vector<Eigen::AlignedBox2d> boxes;
  for (std::size_t i = 0; i + 8 <= walls.vertices.size(); i += 8) {
    Eigen::AlignedBox2d b;
    for (std::size_t k = i; k < i + 8; ++k) b.extend(walls.vertices[k].head<2>());
    boxes.push_back(b);
  }
  return boxes;
}

// Merged boxes cover every blocked cell's centre once and no free one, in far fewer boxes than cells.
TEST(SceneModel, MapBoxesCoverExactlyTheBlockedCells) {
  for (const char* name : {"office-map.yaml", "movingai-rooms.yaml"}) {
    const Problem p = problem(name);
    const auto& env = dynamic_cast<const GridEnvironment&>(*p.environment);
    const SceneModel m = env.scene_model();
    ASSERT_EQ(m.obstacles.size(), 1u);
    EXPECT_EQ(m.obstacles[0].vertices.size() % 8, 0u);
    const std::vector<Eigen::AlignedBox2d> boxes = boxes_of(m.obstacles[0]);
    const OccupancyGrid& g = env.grid();
    std::size_t blocked = 0, wrong = 0;
    for (int y = 0; y < g.height(); ++y) {
      for (int x = 0; x < g.width(); ++x) {
        const Eigen::Vector2d c = g.cell_center(x, y);
        const auto inside = [&c](const Eigen::AlignedBox2d& b) { return b.contains(c); };
        const auto covering = std::count_if(boxes.begin(), boxes.end(), inside);
        wrong += covering == (g.blocked(x, y) ? 1 : 0) ? 0 : 1;
        blocked += g.blocked(x, y) ? 1 : 0;
      }
    }
    EXPECT_EQ(wrong, 0u) << name;
    EXPECT_GT(blocked, 0u);
    EXPECT_LT(boxes.size(), blocked / 4) << name;
    EXPECT_TRUE(closed_and_consistent(m.obstacles[0]));
    expect_obstacles_inside(m);

    ASSERT_EQ(m.link_names, std::vector<std::string>{"body"});
    EXPECT_NEAR(mesh_bounds(m.robot_links[0]).sizes().x(), 2 * env.robot().radius, kTol);
    std::vector<Eigen::Isometry3d> poses;
    env.robot_link_poses(p.goal(), poses);
    expect_pose(poses[0], turned(0.0, {0, 0, 1}, {p.goal()[0], p.goal()[1], 0.0}));
  }
}

// The roadmap tests' fake world draws too: the arm's second bar ends at the reference point.
TEST(SceneModel, TestBoxWorldArm) {
  const Problem p = roadmap::test::arm_problem();
  const SceneModel m = p.environment->scene_model();
  EXPECT_EQ(m.obstacles.size(), 2u);
  ASSERT_EQ(m.robot_links.size(), 2u);
  std::vector<Eigen::Isometry3d> poses;
  const State s = st({0.6, -1.1});
  p.environment->robot_link_poses(s, poses);
  ASSERT_EQ(poses.size(), 2u);
  const Eigen::Vector3d tip = poses[1] * Eigen::Vector3d(roadmap::test::kArmLink, 0, 0);
  EXPECT_TRUE(tip.isApprox(p.environment->reference_point(s), 1e-12));
}

}  // namespace
}  // namespace amp::world
