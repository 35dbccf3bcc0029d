#include <gtest/gtest.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <unistd.h>

#include "amp/core/error.hpp"
#include "amp/world/grid_environment.hpp"
#include "amp/world/grid_yaml.hpp"
#include "support/source_tree.hpp"

namespace amp::world {
namespace {

namespace fs = std::filesystem;

const fs::path kProblems = fs::path(AMP_SOURCE_DIR) / "problems";

YamlFields root_of(const fs::path& file) { return YamlFields(load_yaml_file(file), file, ""); }

State state_of(const YamlFields& root, const char* key) {
  const auto v = root.numbers(key);
  State s(static_cast<Eigen::Index>(v.size()));
  for (std::size_t i = 0; i < v.size(); ++i) s[static_cast<Eigen::Index>(i)] = v[i];
  return s;
}

// Breadth-first search over a lattice of disc positions half a cell apart: the bundled witness
// queries must be solvable.
bool lattice_connected(const LoadedWorld& w, const State& start, const State& goal) {
  const auto& env = dynamic_cast<const GridEnvironment&>(*w.environment);
  const double step = 0.5 * env.grid().resolution();
  const Eigen::AlignedBox2d e = env.grid().extent();
  const int nx = static_cast<int>(e.sizes().x() / step), ny = static_cast<int>(e.sizes().y() / step);
  auto at = [&](int i, int j) { return Eigen::Vector2d(e.min().x() + (i + 0.5) * step, e.min().y() + (j + 0.5) * step); };
  auto node = [&](const State& s) {
    return Eigen::Vector2i(static_cast<int>((s[0] - e.min().x()) / step), static_cast<int>((s[1] - e.min().y()) / step));
  };
  std::vector<char> seen(static_cast<std::size_t>(nx) * ny, 0);
  std::vector<Eigen::Vector2i> queue{node(start)};
  const Eigen::Vector2i target = node(goal);
  seen[queue[0].y() * nx + queue[0].x()] = 1;
  for (std::size_t k = 0; k < queue.size(); ++k) {
    if (queue[k] == target) return true;
    for (const Eigen::Vector2i& d : {Eigen::Vector2i(1, 0), Eigen::Vector2i(-1, 0), Eigen::Vector2i(0, 1), Eigen::Vector2i(0, -1)}) {
      const Eigen::Vector2i n = queue[k] + d;
      if (n.x() < 0 || n.y() < 0 || n.x() >= nx || n.y() >= ny || seen[n.y() * nx + n.x()]) continue;
      seen[n.y() * nx + n.x()] = 1;
      if (env.obstacles().disc_free(at(n.x(), n.y()), env.robot().radius)) queue.push_back(n);
    }
  }
  return false;
}

TEST(GridYaml, OfficeProblemLoads) {
  const YamlFields root = root_of(kProblems / "office-map.yaml");
  const LoadedWorld w = parse_grid_world(root);
  EXPECT_EQ(w.space->kind(), "rn");
  EXPECT_EQ(w.space->dimension(), 2);
  const auto& env = dynamic_cast<const GridEnvironment&>(*w.environment);
  EXPECT_EQ(env.grid().width(), 200);
  EXPECT_EQ(env.grid().height(), 150);
  EXPECT_DOUBLE_EQ(env.grid().resolution(), 0.05);
  EXPECT_GT(env.grid().count(CellState::kUnknown), 0u);
  EXPECT_LE(w.space->resolution(), 0.025 + 1e-12);  // half a cell
  EXPECT_DOUBLE_EQ(env.robot_radius(), 0.25);
  core::Counters counters;
  const auto checker = w.environment->make_checker(counters);
  const State start = state_of(root, "start"), goal = state_of(root, "goal");
  EXPECT_TRUE(w.space->in_bounds(start));
  EXPECT_TRUE(checker->is_valid(start));
  EXPECT_TRUE(checker->is_valid(goal));
  EXPECT_GT((goal - start).norm(), 7.0);  // crosses the map
  EXPECT_NE(w.environment->obstacle_outline().grid, nullptr);
  EXPECT_TRUE(lattice_connected(w, start, goal));
  // The 0.9 m doors stop a 0.92 m disc.
  const LoadedWorld wide{w.space, std::make_shared<const GridEnvironment>(
                                      env.obstacles().grid_ptr(), GridRobot{GridRobot::Kind::kDisc, 0.46, {}})};
  EXPECT_FALSE(lattice_connected(wide, start, goal));
}

TEST(GridYaml, MovingAiProblemLoads) {
  const YamlFields root = root_of(kProblems / "movingai-rooms.yaml");
  const LoadedWorld w = parse_grid_world(root);
  const auto& env = dynamic_cast<const GridEnvironment&>(*w.environment);
  EXPECT_EQ(env.grid().width(), 64);
  EXPECT_EQ(env.grid().height(), 64);
  EXPECT_LE(w.space->resolution(), 0.5);
  core::Counters counters;
  const auto checker = w.environment->make_checker(counters);
  EXPECT_TRUE(checker->is_valid(state_of(root, "start")));
  EXPECT_TRUE(checker->is_valid(state_of(root, "goal")));
  EXPECT_TRUE(lattice_connected(w, state_of(root, "start"), state_of(root, "goal")));
}

class GridYamlFileTest : public ::testing::Test {
 protected:
  void SetUp() override {
    static std::atomic<int> counter{0};
    dir_ = fs::temp_directory_path() / ("amp_grid_yaml_test_" + std::to_string(::getpid()) + "_" +
                                        std::to_string(counter++));
    fs::create_directories(dir_);
    std::ofstream(dir_ / "tiny.map") << "type octile\nheight 4\nwidth 6\nmap\n......\n.@@...\n......\n......\n";
  }
  void TearDown() override { fs::remove_all(dir_); }
  LoadedWorld parse(const std::string& text) const {
    std::ofstream(dir_ / "p.yaml") << text;
    return parse_grid_world(root_of(dir_ / "p.yaml"));
  }
  void expect_error(const std::string& text, const std::string& fragment) const {
    try {
      parse(text);
      ADD_FAILURE() << "no error for:\n" << text;
    } catch (const FileError& e) {
      EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("p.yaml"), std::string::npos) << e.what();
    }
  }
  fs::path dir_;
};

TEST_F(GridYamlFileTest, RigidRobotGetsSe2SpaceWithHalfCellResolution) {
  const LoadedWorld w = parse(
      "world: {map: tiny.map, resolution: 0.5}\n"
      "robot:\n  type: rigid2d\n  shapes:\n    - polygon: [[-0.2, -0.1], [0.2, -0.1], [0.2, 0.1], [-0.2, 0.1]]\n"
      "    - circle: {center: [0.3, 0], radius: 0.05}\n"
      "resolution: 0.5\nstart: [0.5, 0.5, 0]\ngoal: [2.5, 1.5, 1]\n");
  EXPECT_EQ(w.space->kind(), "se2");
  EXPECT_EQ(w.space->dimension(), 3);
  EXPECT_DOUBLE_EQ(w.space->resolution(), 0.25);
  EXPECT_NEAR(w.environment->robot_radius(), 0.35, 1e-12);
  EXPECT_TRUE(w.environment->workspace_bounds().max().isApprox(Eigen::Vector3d(3.0, 2.0, 0.0)));
}

TEST_F(GridYamlFileTest, FractionResolutionWhenBelowHalfACell) {
  const LoadedWorld w = parse("world: {map: tiny.map}\nrobot: {type: disc, radius: 0.3}\nresolution: 0.001\n");
  EXPECT_NEAR(w.space->resolution(), 0.001 * std::hypot(6.0, 4.0), 1e-12);
}

TEST_F(GridYamlFileTest, ErrorsNameTheField) {
  expect_error("world: {map: none.map}\nrobot: {type: disc, radius: 0.3}\n", "world.map");
  expect_error("world: {map: tiny.map, resolution: -1}\nrobot: {type: disc, radius: 0.3}\n", "world.resolution");
  expect_error("world: {map: tiny.map, colour: red}\nrobot: {type: disc, radius: 0.3}\n", "world.colour");
  expect_error("world: {map: tiny.map}\nrobot: {type: blob, radius: 0.3}\n", "robot.type");
  expect_error("world: {map: tiny.map}\nrobot: {type: disc}\n", "robot.radius");
  expect_error("world: {map: tiny.map}\nrobot: {type: rigid2d, shapes: [{polygon: [[0, 0], [1, 0]]}]}\n",
               "robot.shapes[0].polygon");
  expect_error("world: {map: tiny.map}\nrobot: {type: disc, radius: 0.3}\nresolution: 2\n", "resolution");
  expect_error("robot: {type: disc, radius: 0.3}\n", "world");
}

}  // namespace
}  // namespace amp::world
