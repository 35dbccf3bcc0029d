// Bad input through the real `amp` binary: each case must end with exit code 1 and exactly one
// stderr line `amp: error: <file>: <field>: <what>` (no crash, hang or silent wrong answer), and
// must write no output file. Unsolvable problems end with exit code 2 at their limit.
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <sstream>
#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;
using ::testing::StartsWith;

constexpr int kExitError = 1;
constexpr int kExitNotSolved = 2;
// A guard, not a measurement: a hang becomes a failed test (exit 124) instead of a stuck suite.
constexpr int kHangGuardSeconds = 120;

const fs::path kAmp = fs::path(AMP_BINARY_DIR) / "bin" / "amp";
const fs::path kData = fs::path(AMP_SOURCE_DIR) / "tests" / "apps" / "data";

struct RunResult {
  int exit_code = -1;
  std::string out;
  std::string err;
};

std::string read_file(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

// A data file's path, quoted for the shell (built in steps: GCC 12 warns (-Wrestrict) about "'" + s).
std::string data(const std::string& name) {
  std::string quoted = "'";
  quoted += (kData / name).string();
  quoted += '\'';
  return quoted;
}

class CliErrors : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_TRUE(fs::is_regular_file(kAmp)) << kAmp << " is missing: build the amp_cli target first";
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() / ("amp_cli_errors_" + std::to_string(::getpid()) + "_" + info->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override {
    std::error_code ec;
    fs::permissions(dir_ / "locked.yaml", fs::perms::owner_all, ec);
    fs::remove_all(dir_, ec);
  }

  // Runs `amp <args>` inside the test's scratch directory, capturing stdout, stderr and the exit code.
  // `wrapper` goes between the hang guard and the binary (e.g. to drop root privileges).
  RunResult run(const std::string& args, const std::string& wrapper = "") const {
    const std::string cmd = "cd '" + dir_.string() + "' && timeout " + std::to_string(kHangGuardSeconds) + " " +
                            wrapper + " '" + kAmp.string() + "' " + args + " >stdout.txt 2>stderr.txt";
    const int status = std::system(cmd.c_str());
    RunResult r;
    r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    r.out = read_file(dir_ / "stdout.txt");
    r.err = read_file(dir_ / "stderr.txt");
    fs::remove(dir_ / "stdout.txt");
    fs::remove(dir_ / "stderr.txt");
    return r;
  }

  // `amp plan <problem> <extra>` asked to write a path and a picture into the scratch directory.
  RunResult plan(const std::string& problem, const std::string& extra = "") const {
    return run("plan " + problem + " --out out.path --svg out.svg " + extra);
  }

  // Exit code 1, one stderr line `amp: error: ...` holding every `expected` text, no output files.
  void expect_input_error(const RunResult& r, std::initializer_list<std::string> expected) const {
    EXPECT_EQ(r.exit_code, kExitError) << "stderr: " << r.err;
    const std::vector<std::string> lines = lines_of(r.err);
    ASSERT_EQ(lines.size(), 1u) << "stderr: " << r.err;
    EXPECT_THAT(lines[0], StartsWith("amp: error: "));
    EXPECT_THAT(lines[0], ::testing::Not(HasSubstr("internal")));
    for (const std::string& e : expected) EXPECT_THAT(lines[0], HasSubstr(e));
    EXPECT_FALSE(fs::exists(dir_ / "out.path"));
    EXPECT_FALSE(fs::exists(dir_ / "out.svg"));
  }

  fs::path dir_;
};

// ---- the problem file itself

TEST_F(CliErrors, MissingProblemFile) {
  expect_input_error(plan("no_such_problem.yaml"), {"no_such_problem.yaml", "no such file"});
}

TEST_F(CliErrors, UnreadableProblemFile) {
  fs::copy_file(kData / "ok.yaml", dir_ / "locked.yaml");
  fs::permissions(dir_ / "locked.yaml", fs::perms::none);
  std::string wrapper;
  if (std::ifstream(dir_ / "locked.yaml").good()) {
    // Root reads a chmod 000 file; run amp as `nobody` instead, when setpriv can do that.
    if (::geteuid() != 0 || std::system("command -v setpriv >/dev/null 2>&1") != 0) {
      GTEST_SKIP() << "a chmod 000 file is still readable here (root without setpriv): case not provoked";
    }
    fs::permissions(dir_, fs::perms::all);  // nobody must enter the scratch directory
    wrapper = "setpriv --reuid=65534 --regid=65534 --clear-groups";
  }
  expect_input_error(run("plan locked.yaml --out out.path --svg out.svg", wrapper), {"locked.yaml", "cannot open"});
}

TEST_F(CliErrors, DirectoryGivenAsProblem) {
  fs::create_directory(dir_ / "adir.yaml");
  expect_input_error(plan("adir.yaml"), {"adir.yaml", "not a regular file"});
}

TEST_F(CliErrors, MalformedYamlNamesTheLine) {
  expect_input_error(plan(data("bad_indent.yaml")), {"bad_indent.yaml", "malformed YAML", "line 7"});
}

TEST_F(CliErrors, CfgLineWithoutEquals) {
  expect_input_error(plan(data("no_equals.cfg")), {"no_equals.cfg:4", "key = value", "start.x -6.0"});
}

TEST_F(CliErrors, CfgMissingProblemKey) {
  expect_input_error(plan(data("missing_keys.cfg")), {"missing_keys.cfg", "[problem] goal.y", "missing key"});
}

TEST_F(CliErrors, UnknownTopLevelField) {
  expect_input_error(plan(data("unknown_field.yaml")), {"unknown_field.yaml", "obstacels", "unknown field"});
}

TEST_F(CliErrors, DuplicateField) {
  // yaml-cpp would keep the first `start` and drop the second without a word.
  expect_input_error(plan(data("duplicate_field.yaml")),
                     {"duplicate_field.yaml", "start", "duplicate field", "line 6"});
}

TEST_F(CliErrors, UnknownDefaultPlannerNamesTheField) {
  expect_input_error(plan(data("default_planner_unknown.yaml")),
                     {"default_planner_unknown.yaml", "defaults.planner", "unknown planner 'nope'", "valid: "});
}

TEST_F(CliErrors, RigidBodyWithoutShapes) {
  expect_input_error(plan(data("rigid3d_no_shapes.yaml")), {"rigid3d_no_shapes.yaml", "robot.shapes", "at least one"});
}

TEST_F(CliErrors, TooManyLinksNamesTheFieldOnce) {
  const RunResult r = plan(data("too_many_links.yaml"));
  expect_input_error(r, {"too_many_links.yaml: robot.links: need 1 to 12 links, got 13"});
}

TEST_F(CliErrors, UnknownRobotType) {
  expect_input_error(plan(data("unknown_robot.yaml")), {"unknown_robot.yaml", "robot.type", "'hovercraft'"});
}

TEST_F(CliErrors, UnknownObstacleKind) {
  expect_input_error(plan(data("unknown_obstacle.yaml")),
                     {"unknown_obstacle.yaml", "world.obstacles[0].triangle", "unknown field"});
}

TEST_F(CliErrors, StartOutOfBounds) {
  expect_input_error(plan(data("start_out_of_bounds.yaml")),
                     {"start_out_of_bounds.yaml", "start", "[12, 1]", "bounds"});
}

TEST_F(CliErrors, GoalInCollision) {
  expect_input_error(plan(data("goal_in_collision.yaml")), {"goal_in_collision.yaml", "goal", "[5, 5]", "collision"});
}

TEST_F(CliErrors, StartWithWrongNumberOfCoordinates) {
  expect_input_error(plan(data("start_wrong_dims.yaml")),
                     {"start_wrong_dims.yaml", "start", "expected 2 coordinates", "got 3"});
}

TEST_F(CliErrors, EmptyPolygon) {
  expect_input_error(plan(data("polygon_empty.yaml")),
                     {"polygon_empty.yaml", "world.obstacles[0].polygon", "at least 3 vertices, got 0"});
}

TEST_F(CliErrors, TwoVertexPolygon) {
  expect_input_error(plan(data("polygon_two_vertices.yaml")),
                     {"polygon_two_vertices.yaml", "world.obstacles[0].polygon", "at least 3 vertices, got 2"});
}

TEST_F(CliErrors, ZeroAreaPolygon) {
  expect_input_error(plan(data("polygon_zero_area.yaml")),
                     {"polygon_zero_area.yaml", "world.obstacles[0].polygon", "zero area"});
}

TEST_F(CliErrors, NegativeCircleRadius) {
  expect_input_error(plan(data("circle_negative_radius.yaml")),
                     {"circle_negative_radius.yaml", "world.obstacles[0].circle.radius", "'-1'"});
}

TEST_F(CliErrors, ResolutionZero) {
  expect_input_error(plan(data("resolution_zero.yaml")), {"resolution_zero.yaml", "resolution", "'0'"});
}

TEST_F(CliErrors, ResolutionNegative) {
  expect_input_error(plan(data("resolution_negative.yaml")), {"resolution_negative.yaml", "resolution", "'-1'"});
}

// ---- files the problem refers to

TEST_F(CliErrors, MeshAssimpCannotRead) {
  expect_input_error(plan(data("mesh_unreadable.yaml")),
                     {"mesh_unreadable.yaml", "world.obstacles[0].mesh.file", "not_a_mesh.stl", "mesh has no triangles"});
}

TEST_F(CliErrors, EdgeCheckUnknown) {
  expect_input_error(plan(data("edge_check_unknown.yaml")),
                     {"edge_check_unknown.yaml", "edge_check", "'certified' or 'discrete'", "'exact'"});
}

TEST_F(CliErrors, CfgStartOutsideVolume) {
  expect_input_error(plan(data("start_outside_volume.cfg")), {"start_outside_volume.cfg", "start", "outside"});
}

TEST_F(CliErrors, CfgMeshWithoutTriangles) {
  expect_input_error(plan(data("world_no_triangles.cfg")),
                     {"world_no_triangles.cfg", "world", "no_triangles.stl", "mesh has no triangles"});
}

TEST_F(CliErrors, MissingMeshFile) {
  expect_input_error(plan(data("mesh_missing.yaml")),
                     {"mesh_missing.yaml", "world.obstacles[0].mesh.file", "no_such_mesh.stl", "no such file"});
}

TEST_F(CliErrors, MapYamlFreeThresholdNotBelowOccupied) {
  expect_input_error(plan(data("map_bad_thresholds.yaml")), {"thresholds_map.yaml", "free_thresh", "occupied_thresh"});
}

TEST_F(CliErrors, PgmHeaderSizeDisagreesWithData) {
  expect_input_error(plan(data("map_pgm_size.yaml")), {"short_data.pgm", "4x4", "11 samples"});
}

TEST_F(CliErrors, MovingAiWrongRowCount) {
  expect_input_error(plan(data("movingai_rows.yaml")), {"bad_rows.map", "3 rows", "height 4"});
}

// ---- command-line options

TEST_F(CliErrors, NegativeTimeLimit) { expect_input_error(plan(data("ok.yaml"), "--time-limit -1"), {"--time-limit"}); }

TEST_F(CliErrors, ZeroTimeLimit) { expect_input_error(plan(data("ok.yaml"), "--time-limit 0"), {"--time-limit"}); }

TEST_F(CliErrors, NanTimeLimit) {
  expect_input_error(plan(data("ok.yaml"), "--time-limit nan"), {"--time-limit", "'nan'"});
}

TEST_F(CliErrors, FractionalNodeLimit) {
  expect_input_error(plan(data("ok.yaml"), "--node-limit 1.5"), {"--node-limit", "'1.5'"});
}

TEST_F(CliErrors, NegativeSeed) { expect_input_error(plan(data("ok.yaml"), "--seed -1"), {"--seed", "'-1'"}); }

TEST_F(CliErrors, ZeroNodeLimit) { expect_input_error(plan(data("ok.yaml"), "--node-limit 0"), {"--node-limit"}); }

TEST_F(CliErrors, ParamOutOfRange) {
  expect_input_error(plan(data("ok.yaml"), "--param k=0"), {"prm", "'k'", "0 is outside [1, "});
}

TEST_F(CliErrors, ParamNotANumber) {
  expect_input_error(plan(data("ok.yaml"), "--param k=abc"), {"prm", "'k'", "'abc'"});
}

TEST_F(CliErrors, UnknownParam) {
  expect_input_error(plan(data("ok.yaml"), "--param nope=3"), {"prm", "unknown parameter 'nope'", "valid: k"});
}

TEST_F(CliErrors, SeedInCollisionIsNamed) {
  expect_input_error(plan(data("seed_in_collision.yaml"), "--planner prm-l"),
                     {"seed_in_collision.yaml", "seeds[2]", "[5, 6]", "collision"});
}

TEST_F(CliErrors, CompetenceParametersOutOfRange) {
  expect_input_error(plan(data("ok.yaml"), "--planner prm-c --param o=0.5"), {"prm-c", "'o'", "0.5 is outside"});
  expect_input_error(plan(data("ok.yaml"), "--planner prm-g --param s=0"), {"prm-g", "'s'", "0 is outside"});
  expect_input_error(plan(data("ok.yaml"), "--planner prm-l --param n=-1"), {"prm-l", "'n'", "-1 is outside"});
  expect_input_error(plan(data("ok.yaml"), "--planner prm-l --param steps=0"), {"prm-l", "'steps'", "0 is outside"});
}

TEST_F(CliErrors, ProblemGridOfZeroSteps) {
  // The problem's own planner parameter is checked like a command-line one, for the planners that take it.
  expect_input_error(plan(data("grid_steps_zero.yaml"), "--planner prm-l"), {"prm-l", "'steps'", "0 is outside"});
  EXPECT_EQ(plan(data("grid_steps_zero.yaml"), "--planner prm").exit_code, 0);
}

TEST_F(CliErrors, UnknownPlannerListsTheValidOnes) {
  expect_input_error(plan(data("ok.yaml"), "--planner nope"), {"unknown planner 'nope'", "valid: ", "prm"});
}

// ---- output files

TEST_F(CliErrors, OutRefusesToOverwriteWithoutForce) {
  const std::string precious = "my own notes\n";
  std::ofstream(dir_ / "keep.path") << precious;
  const RunResult r = run("plan " + data("ok.yaml") + " --out keep.path");
  EXPECT_EQ(r.exit_code, kExitError);
  ASSERT_EQ(lines_of(r.err).size(), 1u) << r.err;
  EXPECT_THAT(r.err, StartsWith("amp: error: --out: "));
  EXPECT_THAT(r.err, HasSubstr("keep.path"));
  EXPECT_THAT(r.err, HasSubstr("--force"));
  EXPECT_EQ(read_file(dir_ / "keep.path"), precious);
}

TEST_F(CliErrors, OutOverwritesWithForce) {
  std::ofstream(dir_ / "keep.path") << "my own notes\n";
  const RunResult r = run("plan " + data("ok.yaml") + " --out keep.path --force");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err, "");
  // The file now holds the path: the first state is the problem's start (1, 1).
  const std::vector<std::string> lines = lines_of(read_file(dir_ / "keep.path"));
  ASSERT_GE(lines.size(), 2u);
  EXPECT_EQ(lines.front(), "1 1");
  EXPECT_EQ(lines.back(), "9 9");
}

TEST_F(CliErrors, OutIsADirectory) {
  fs::create_directory(dir_ / "out.path");
  const RunResult r = plan(data("ok.yaml"));
  EXPECT_EQ(r.exit_code, kExitError);
  ASSERT_EQ(lines_of(r.err).size(), 1u) << r.err;
  EXPECT_THAT(r.err, StartsWith("amp: error: --out: "));
  EXPECT_THAT(r.err, HasSubstr("is a directory"));
  EXPECT_TRUE(fs::is_empty(dir_ / "out.path"));
  EXPECT_FALSE(fs::exists(dir_ / "out.svg"));
}

TEST_F(CliErrors, SvgIntoMissingDirectory) {
  const RunResult r = run("plan " + data("ok.yaml") + " --out out.path --svg no_such_dir/out.svg");
  expect_input_error(r, {"--svg", "no_such_dir", "does not exist"});
  EXPECT_FALSE(fs::exists(dir_ / "no_such_dir"));
}

TEST_F(CliErrors, SvgAndOutNameTheSameFile) {
  const RunResult r = run("plan " + data("ok.yaml") + " --out out.path --svg ./out.path");
  expect_input_error(r, {"--svg", "out.path", "--out"});
}

TEST_F(CliErrors, RenderWithoutOutput) {
  const RunResult r = run("render " + data("ok.yaml"));
  expect_input_error(r, {"--output", "required"});
}

TEST_F(CliErrors, RenderWithMalformedPathFile) {
  const RunResult r = run("render " + data("ok.yaml") + " --path " + data("bad_path.txt") + " -o out.svg");
  expect_input_error(r, {"bad_path.txt:2", "expected 2 numbers per state, got 3"});
}

// ---- unsolvable problems end at their limit with exit code 2

TEST_F(CliErrors, SealedGoalStopsAtNodeLimit) {
  const RunResult r = plan(data("sealed.yaml"), "--node-limit 300");
  EXPECT_EQ(r.exit_code, kExitNotSolved) << r.err;
  EXPECT_THAT(r.out, testing::ContainsRegex("status +node_limit"));
  EXPECT_THAT(r.out, testing::ContainsRegex("nodes +300\n"));
  const std::vector<std::string> lines = lines_of(r.err);
  ASSERT_EQ(lines.size(), 1u) << r.err;
  EXPECT_THAT(lines[0], StartsWith("amp: no solution"));
  EXPECT_THAT(lines[0], HasSubstr("node_limit"));
  EXPECT_FALSE(fs::exists(dir_ / "out.path"));  // no path to write
}

TEST_F(CliErrors, SealedGoalStopsAtTimeLimit) {
  const RunResult r = run("plan " + data("sealed.yaml") + " --json --time-limit 0.2 --node-limit 1000000000");
  EXPECT_EQ(r.exit_code, kExitNotSolved) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j.at("status"), "timeout");
  const std::vector<std::string> lines = lines_of(r.err);
  ASSERT_EQ(lines.size(), 1u) << r.err;
  EXPECT_THAT(lines[0], StartsWith("amp: no solution"));
  EXPECT_THAT(lines[0], HasSubstr("timeout"));
}

// ---- machine-readable output

TEST_F(CliErrors, JsonRecordIsValidJson) {
  const RunResult r = run("plan " + data("ok.yaml") + " --json --seed 3");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);  // throws (fails the test) on anything but JSON
  EXPECT_EQ(j.at("status"), "solved");
  EXPECT_EQ(j.at("seed"), 3);
  EXPECT_GT(j.at("cd_calls").get<long long>(), 0);
  EXPECT_EQ(j.at("cd_calls").get<long long>(), j.at("cd_calls_training").get<long long>() +
                                                    j.at("cd_calls_planning").get<long long>() +
                                                    j.at("cd_calls_query").get<long long>());
}

// ---- amp regions

std::string bundled(const std::string& name) {
  std::string quoted = "'";
  quoted += (fs::path(AMP_SOURCE_DIR) / "problems" / name).string();
  quoted += '\'';
  return quoted;
}

TEST_F(CliErrors, RegionsPrintsClusterStatisticsAndDrawsThem) {
  const RunResult r = run("regions " + bundled("maze.yaml") + " --json --seed 2 -o out.svg");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j.at("training_nodes"), 200);
  EXPECT_EQ(j.at("method"), "kmeans");
  EXPECT_GT(j.at("training_cd_calls").get<long long>(), 0);
  const int c = j.at("clusters").get<int>();
  ASSERT_EQ(j.at("regions").size(), static_cast<std::size_t>(c));
  double percent = 0.0;
  for (const auto& region : j.at("regions")) {
    percent += region.at("size_percent").get<double>();
    EXPECT_LE(region.at("visibility_min").get<double>(), region.at("visibility_mean").get<double>());
    EXPECT_LE(region.at("visibility_mean").get<double>(), region.at("visibility_max").get<double>());
  }
  EXPECT_NEAR(percent, 100.0, 1e-9);
  // The maze's tunnels make one cluster of low visibility (the paper's Table 1: about 0.2).
  double lowest = 1.0;
  for (const auto& region : j.at("regions")) lowest = std::min(lowest, region.at("visibility_mean").get<double>());
  EXPECT_LT(lowest, 0.4);
  const std::string svg = read_file(dir_ / "out.svg");
  EXPECT_THAT(svg, HasSubstr("class=\"regions\""));
  // The same seed gives the same table; several sizes give a picture each.
  EXPECT_EQ(run("regions " + bundled("maze.yaml") + " --json --seed 2").out, r.out);
  const RunResult sizes = run("regions " + bundled("walls.yaml") + " --training-nodes 50 100 -o w.svg --clustering auto");
  ASSERT_EQ(sizes.exit_code, 0) << sizes.err;
  EXPECT_THAT(sizes.out, HasSubstr("<- chosen"));
  EXPECT_TRUE(fs::exists(dir_ / "w-50.svg"));
  EXPECT_TRUE(fs::exists(dir_ / "w-100.svg"));
}

TEST_F(CliErrors, RegionsUnknownClustering) {
  expect_input_error(run("regions " + data("ok.yaml") + " --clustering dbscan -o out.svg"), {"--clustering", "dbscan"});
}

TEST_F(CliErrors, RegionsTrainingNodesTooFew) {
  expect_input_error(run("regions " + data("ok.yaml") + " --training-nodes 1 -o out.svg"), {"--training-nodes"});
}

TEST_F(CliErrors, RegionsRefusesToOverwriteWithoutForce) {
  { std::ofstream(dir_ / "mine.svg") << "keep"; }
  const RunResult r = run("regions " + data("ok.yaml") + " -o mine.svg");
  EXPECT_EQ(r.exit_code, kExitError);
  EXPECT_THAT(r.err, HasSubstr("--force"));
  EXPECT_EQ(read_file(dir_ / "mine.svg"), "keep");
}

TEST_F(CliErrors, UasWithAnUnknownClusteringParam) {
  expect_input_error(plan(data("ok.yaml"), "--planner uas --param clustering=dbscan"), {"clustering", "dbscan"});
}

}  // namespace
