// `amp plan` on a bad problem file, or on a problem whose referenced files (meshes, maps) are bad:
// exit code 1, one stderr line naming the file and the field, no output file.
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "support/cli_errors_fixture.hpp"

namespace {

namespace fs = std::filesystem;
using namespace amp::test;  // CliErrors, run helpers, kData, kExit*
using ::testing::HasSubstr;
using ::testing::StartsWith;

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

}  // namespace
